#pragma once
// For tests: the robot's application channel on the PC, behind a pseudo-terminal: an app_channel::Endpoint that
// publishes theta, battery voltage and distance at 100 Hz (and the executive's account every second) and takes the
// controller gains P, I, D, as the firmware on
// the real-time core does over /dev/ttyRPMSG1. One thread does the I/O.

#include <poll.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "duet/app_channel/endpoint.hpp"
#include "pseudo_terminal.hpp"

namespace duet::bridge {

class PtyApplication {
 public:
  PtyApplication() = default;
  ~PtyApplication() { stop(); }
  PtyApplication(const PtyApplication&) = delete;
  PtyApplication& operator=(const PtyApplication&) = delete;

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
    [[maybe_unused]] const ssize_t written = ::write(pty_.descriptor(), bytes.data(), bytes.size());
  }

  // The gains as the firmware holds them (the test reads them after the thread has applied a set).
  std::atomic<float> p{0.0196F}, i{0.0F}, d{0.0187F};
  std::atomic<std::uint32_t> samples{0};

 private:
  void serve() {
    std::array<std::uint8_t, 1024> input{};
    std::array<std::uint8_t, 1024> output{};
    std::vector<std::uint8_t> unsent;
    auto next_sample = std::chrono::steady_clock::now();
    while (running_) {
      pollfd watched{pty_.descriptor(), static_cast<short>(POLLIN | (unsent.empty() ? 0 : POLLOUT)), 0};
      const auto wait =
          std::chrono::duration_cast<std::chrono::milliseconds>(next_sample - std::chrono::steady_clock::now());
      ::poll(&watched, 1, wait.count() > 0 ? static_cast<int>(wait.count()) : 0);
      const ssize_t received = ::read(pty_.descriptor(), input.data(), input.size());
      if (received > 0) {
        endpoint_.receive(std::span{input}.first(static_cast<std::size_t>(received)));
        p = gains_[0];
        i = gains_[1];
        d = gains_[2];
      }
      if (std::chrono::steady_clock::now() >= next_sample) {
        const std::uint32_t sample = samples++;
        theta_ = static_cast<float>(sample % 200) * 0.1F - 10.0F;
        battery_ = 7.4F;
        distance_ = static_cast<std::uint16_t>(20 + sample % 50);
        (void)endpoint_.publish(sample);
        if (sample % 100 == 99) publish_account(sample + 1);  // once a second, as the firmware does
        next_sample += std::chrono::milliseconds{10};
      }
      if (unsent.size() < 4096) {
        const std::size_t framed = endpoint_.transmit(output);
        unsent.insert(unsent.end(), output.begin(), output.begin() + static_cast<std::ptrdiff_t>(framed));
      }
      if (!unsent.empty()) {
        const ssize_t written = ::write(pty_.descriptor(), unsent.data(), unsent.size());
        if (written > 0) unsent.erase(unsent.begin(), unsent.begin() + written);
      }
    }
  }

  // The executive's account of a two-task model at 10 ms per tick, cycles counted at 25 MHz.
  void publish_account(std::uint32_t ticks) {
    const std::array<app_channel::TaskReport, 2> tasks{app_channel::TaskReport{"rate 1", ticks, 0, 150, 180, 250},
                                                       app_channel::TaskReport{"IPCC_RX1", 3, 1, 300, 310, 320}};
    (void)endpoint_.publish_executive({.ticks = ticks,
                                       .base_period_ns = 10'000'000,
                                       .busy_ppm = 12'000,
                                       .overruns = 1,
                                       .cycle_hz = 25'000'000,
                                       .tasks = tasks});
  }

  PseudoTerminal pty_;
  std::atomic<bool> running_{false};
  std::thread thread_;

  float theta_ = 0;
  float battery_ = 0;
  std::uint16_t distance_ = 0;
  std::array<float, 3> gains_{0.0196F, 0.0F, 0.0187F};
  const std::array<app_channel::Item, 3> telemetry_{app_channel::item("theta", "deg", theta_, -90, 90),
                                                    app_channel::item("battery", "V", battery_, 0, 12.6),
                                                    app_channel::item("distance", "cm", distance_, 0, 400)};
  const std::array<app_channel::Item, 3> parameters_{app_channel::item("P", "", gains_[0], 0, 1),
                                                     app_channel::item("I", "", gains_[1], 0, 1),
                                                     app_channel::item("D", "", gains_[2], 0, 1)};
  const app_channel::Application application_{"balbot", 10000, telemetry_, parameters_};
  std::array<std::uint8_t, 4096> ring_{};
  xcp::TransmitQueue queue_{ring_, {}};
  std::array<std::uint8_t, app_channel::decoder_buffer_size> decoder_buffer_{};
  std::array<std::uint8_t, app_channel::max_packet> packet_buffer_{};
  app_channel::Endpoint endpoint_{application_, queue_, {}, decoder_buffer_, packet_buffer_};
};

}  // namespace duet::bridge
