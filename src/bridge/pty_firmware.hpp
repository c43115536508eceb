#pragma once
// For tests: "firmware" on the PC whose XCP channel is a pseudo-terminal, as QEMU's `-serial pty` gives one. An XCP
// slave behind a StreamTransport on the pty's master side; the bridge opens the other side (path()). One thread does
// the I/O and steps a model at 1 kHz: `counter` counts the steps, event 0 samples after each.

#include <poll.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "duet/xcp/stream_transport.hpp"
#include "pseudo_terminal.hpp"

namespace duet::bridge {

struct PtyFirmwareOptions {
  std::uint8_t max_cto = 248;  // smaller: a DOWNLOAD of the table takes more DOWNLOAD_NEXT packets in block mode
  // Calibration locked at CONNECT until UNLOCK with the key for the seed {1, 2, 3, 4}: each byte inverted.
  bool calibration_locked = false;
};

class PtyFirmware {
 public:
  explicit PtyFirmware(PtyFirmwareOptions options = {}) {
    configuration_.max_cto = options.max_cto;
    if (options.calibration_locked) {
      configuration_.protected_resources = xcp::resource::calibration_paging;
      configuration_.seed_and_key = {.make_seed = make_seed, .key_is_valid = key_is_valid};
    }
  }
  ~PtyFirmware() { stop(); }
  PtyFirmware(const PtyFirmware&) = delete;
  PtyFirmware& operator=(const PtyFirmware&) = delete;

  [[nodiscard]] const std::string& path() const { return pty_.path(); }

  void start() {
    running_ = true;
    thread_ = std::thread{[this] { serve(); }};
  }
  void stop() {
    running_ = false;
    if (thread_.joinable()) thread_.join();
  }
  // Writes bytes straight into the channel, as noise on the line would.
  void inject(const std::vector<std::uint8_t>& bytes) {
    const std::lock_guard held{garbage_lock_};  // the firmware's thread takes them
    garbage_ = bytes;
  }
  // Samples event 0 as often as the transmit queue has room, rather than once per millisecond: for throughput.
  std::atomic<bool> flood{false};

  std::uint32_t counter = 0;
  std::array<std::uint8_t, 8> parameters{};
  std::array<std::uint8_t, 256> table{};  // more than one packet holds: for DOWNLOAD in block mode

 private:
  static std::size_t make_seed(std::uint8_t, std::span<std::uint8_t> seed) {
    for (std::size_t byte = 0; byte < 4; ++byte) seed[byte] = static_cast<std::uint8_t>(byte + 1);
    return 4;
  }
  static bool key_is_valid(std::uint8_t, std::span<const std::uint8_t> seed, std::span<const std::uint8_t> key) {
    if (key.size() != seed.size()) return false;
    for (std::size_t byte = 0; byte < key.size(); ++byte) {
      if (key[byte] != static_cast<std::uint8_t>(~seed[byte])) return false;
    }
    return true;
  }

  void serve() {
    std::array<std::uint8_t, 4096> input{};
    std::array<std::uint8_t, 4096> output{};
    std::vector<std::uint8_t> unsent;
    auto next_step = std::chrono::steady_clock::now();
    while (running_) {
      pollfd watched{pty_.descriptor(), static_cast<short>(POLLIN | (unsent.empty() ? 0 : POLLOUT)), 0};
      const auto wait =
          std::chrono::duration_cast<std::chrono::milliseconds>(next_step - std::chrono::steady_clock::now());
      ::poll(&watched, 1, wait.count() > 0 ? static_cast<int>(wait.count()) : 0);
      const ssize_t received = ::read(pty_.descriptor(), input.data(), input.size());
      if (received > 0) transport_.receive(std::span{input}.first(static_cast<std::size_t>(received)));
      if (flood) {
        for (int sample = 0; sample < 256 && queue_.free_bytes() > 4096; ++sample) {
          ++counter;
          slave_.on_event(0);
        }
        next_step = std::chrono::steady_clock::now();
      } else if (std::chrono::steady_clock::now() >= next_step) {
        ++counter;
        slave_.on_event(0);
        next_step += std::chrono::milliseconds{1};
      }
      {
        const std::lock_guard held{garbage_lock_};
        unsent.insert(unsent.end(), garbage_.begin(), garbage_.end());
        garbage_.clear();
      }
      if (unsent.size() < 65536) {  // frame more only when the pty has taken what was framed before
        const std::size_t framed = transport_.transmit(output);
        unsent.insert(unsent.end(), output.begin(), output.begin() + static_cast<std::ptrdiff_t>(framed));
      }
      if (!unsent.empty()) {  // the pty holds a few kilobytes; keep what it does not take
        const ssize_t written = ::write(pty_.descriptor(), unsent.data(), unsent.size());
        if (written > 0) unsent.erase(unsent.begin(), unsent.begin() + written);
      }
    }
  }

  PseudoTerminal pty_;
  std::atomic<bool> running_{false};
  std::thread thread_;
  std::mutex garbage_lock_;
  std::vector<std::uint8_t> garbage_;

  std::array<xcp::MemoryRegion, 3> regions_{
      xcp::MemoryRegion{
          .name = "counter", .address = 0x1000, .size = 4, .memory = reinterpret_cast<std::uint8_t*>(&counter)},
      xcp::MemoryRegion{.name = "parameters",
                        .address = 0x2000,
                        .size = 8,
                        .memory = parameters.data(),
                        .access = xcp::Access::read_write},
      xcp::MemoryRegion{
          .name = "table", .address = 0x3000, .size = 256, .memory = table.data(), .access = xcp::Access::read_write}};
  std::array<xcp::EventChannel, 1> events_{xcp::EventChannel{.name = "1 ms", .time_cycle = 1, .time_unit = 6}};
  std::array<xcp::DaqList, 2> lists_{};
  std::array<xcp::Odt, 4> odts_{};
  std::array<xcp::OdtEntry, 64> entries_{};
  std::array<std::uint8_t, 1 << 16> queue_storage_{};
  std::array<std::uint8_t, 256> download_buffer_{};
  xcp::TransmitQueue queue_{queue_storage_, {}};
  xcp::SlaveConfiguration configuration_{.memory = xcp::MemoryMap{regions_},
                                         .max_cto = 248,
                                         .max_dto = 256,
                                         .identification = "pty_firmware",
                                         .download_buffer = download_buffer_,
                                         .events = events_,
                                         .daq = {lists_, odts_, entries_},
                                         .queue = &queue_};
  xcp::Slave slave_{configuration_};
  std::array<std::uint8_t, 512> decoder_buffer_{};
  std::array<std::uint8_t, 512> packet_buffer_{};
  xcp::StreamTransport transport_{slave_, queue_, xcp::ethernet_framing, decoder_buffer_, 248, packet_buffer_};
};

}  // namespace duet::bridge
