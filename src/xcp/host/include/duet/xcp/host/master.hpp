#pragma once
// The XCP master: commands to one slave over a MasterChannel, with the slave's answers as values and its errors as
// messages that name the command and the ERR code ("UPLOAD: ERR_ACCESS_DENIED (0x24)"). DAQ samples that arrive
// while a command waits are kept for receive_samples().

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "duet/support/result.hpp"
#include "duet/xcp/host/master_channel.hpp"

namespace duet::xcp::host {

struct SlaveProperties {
  std::uint8_t resources = 0;
  std::uint8_t comm_mode_basic = 0;
  std::uint8_t max_cto = 8;
  std::uint16_t max_dto = 8;
  std::uint8_t protocol_version = 0;
  std::uint8_t transport_version = 0;
};

struct DaqEntry {
  std::uint8_t extension = 0;
  std::uint32_t address = 0;
  std::uint8_t size = 0;
};

// One DAQ list: what to sample, on which event, how often.
struct DaqListSetup {
  std::uint16_t event = 0;
  std::uint8_t prescaler = 1;
  std::vector<DaqEntry> entries;
};

// One sample of one DAQ list: the entries' bytes one after another, in the order they were set up.
struct DaqSample {
  std::size_t list = 0;
  std::uint32_t timestamp = 0;
  std::vector<std::uint8_t> bytes;
};

// Computes the key for a seed (the slave's seed & key algorithm, as the tool vendor's DLL would).
using KeyFunction = std::function<std::vector<std::uint8_t>(std::uint8_t resource, std::span<const std::uint8_t> seed)>;

class Master {
 public:
  explicit Master(std::unique_ptr<MasterChannel> channel,
                  std::chrono::milliseconds timeout = std::chrono::milliseconds{1000});

  Result<SlaveProperties> connect();
  Status disconnect();
  // A raw command: the positive response (from its 0xFF on), or the failure naming `name` and the ERR code.
  Result<std::vector<std::uint8_t>> command(std::span<const std::uint8_t> request, std::string_view name);

  Result<std::vector<std::uint8_t>> upload(std::uint8_t extension, std::uint32_t address, std::uint32_t size);
  // Writes `bytes` so that the slave applies them at once: one DOWNLOAD, or one DOWNLOAD sequence (block mode).
  Status download(std::uint8_t extension, std::uint32_t address, std::span<const std::uint8_t> bytes);
  Result<std::uint32_t> checksum(std::uint8_t extension, std::uint32_t address, std::uint32_t size);
  // GET_ID and the upload that follows it.
  Result<std::vector<std::uint8_t>> identification(std::uint8_t type);
  Status unlock(std::uint8_t resource, const KeyFunction& key);
  Status set_calibration_page(std::uint8_t mode, std::uint8_t segment, std::uint8_t page);
  Result<std::uint8_t> calibration_page(std::uint8_t mode, std::uint8_t segment);

  // Configures DAQ from scratch with these lists and starts them all at once.
  Status start_daq(const std::vector<DaqListSetup>& lists);
  Status stop_daq();
  // Samples decoded so far, waiting up to `wait` for at least one.
  Result<std::vector<DaqSample>> receive_samples(std::chrono::milliseconds wait);

  [[nodiscard]] const SlaveProperties& properties() const { return properties_; }
  [[nodiscard]] std::uint64_t overload_events() const { return overload_events_; }
  [[nodiscard]] const MasterChannel& channel() const { return *channel_; }

 private:
  struct OdtLayout {
    std::size_t list = 0;
    bool first = false;
    bool last = false;
    std::size_t payload = 0;  // bytes after the PID (and the timestamp)
  };
  struct Assembly {
    std::uint32_t timestamp = 0;
    std::vector<std::uint8_t> bytes;
    bool started = false;
  };

  void take_asynchronous(std::vector<std::uint8_t> packet);
  Status set_mta(std::uint8_t extension, std::uint32_t address);

  std::unique_ptr<MasterChannel> channel_;
  std::chrono::milliseconds timeout_;
  SlaveProperties properties_;
  std::vector<OdtLayout> odts_by_pid_;  // indexed by PID
  std::vector<Assembly> assemblies_;    // per list
  std::deque<DaqSample> samples_;
  std::uint64_t overload_events_ = 0;
};

}  // namespace duet::xcp::host
