#pragma once
// The XCP master: commands to one slave over a MasterChannel, with the slave's answers as values and its errors as
// messages that name the command and the ERR code ("UPLOAD: ERR_ACCESS_DENIED (0x24)"). It speaks any conforming
// slave's dialect: the byte order CONNECT announces, the DAQ layout GET_DAQ_PROCESSOR_INFO and
// GET_DAQ_RESOLUTION_INFO describe, fill bytes after responses and DAQ packets. Every packet it cannot use is counted
// by reason. DAQ samples that arrive while a command waits are kept for receive_samples().

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "duet/support/result.hpp"
#include "duet/xcp/host/daq_setup.hpp"
#include "duet/xcp/host/master_channel.hpp"
#include "duet/xcp/packet.hpp"

namespace duet::xcp::host {

struct SlaveProperties {
  std::uint8_t resources = 0;
  std::uint8_t comm_mode_basic = 0;
  std::uint8_t max_cto = 8;
  std::uint16_t max_dto = 8;
  std::uint8_t protocol_version = 0;
  std::uint8_t transport_version = 0;
  ByteOrder byte_order = ByteOrder::intel;  // of multi-byte fields in packets (COMM_MODE_BASIC bit 0)
};

// One sample of one DAQ list: the entries' bytes one after another, in the order they were set up, and the slave's
// timestamp in ticks (DaqProcessor::seconds_per_tick()) counted on across the timestamp's wraps; 0 when the slave
// sends none. Unwrapping needs successive samples less than half the timestamp's range apart. An incomplete sample
// (Master::deliver_incomplete_samples) has its list and ticks but no bytes.
struct DaqSample {
  std::size_t list = 0;
  std::int64_t ticks = 0;
  std::vector<std::uint8_t> bytes;
  bool complete = true;
};

// Packets the master received but could not use, by reason, and the losses the link and the slave reported.
struct PacketCounters {
  std::uint64_t unknown_identification = 0;  // DAQ packets of no ODT this master configured
  std::uint64_t too_short = 0;               // packets shorter than their layout
  std::uint64_t incomplete = 0;              // DAQ packets of samples whose other ODTs did not all arrive in order
  std::uint64_t unexpected = 0;              // responses, errors and service requests no command waited for
  std::uint64_t counter_gaps = 0;            // CTR values missing from the slave's sequence: packets lost on the way
  std::uint64_t overload_events = 0;         // the slave dropped samples (EV_DAQ_OVERLOAD, or the PID's MSB)
  std::uint64_t padded = 0;  // packets longer than their layout, used without their fill bytes (not a loss)

  // Packets or samples lost or thrown away: everything above but padding.
  [[nodiscard]] std::uint64_t lost() const {
    return unknown_identification + too_short + incomplete + unexpected + counter_gaps + overload_events;
  }
};

// Computes the key for a seed (the slave's seed & key algorithm, as the tool vendor's DLL would).
using KeyFunction = std::function<std::vector<std::uint8_t>(std::uint8_t resource, std::span<const std::uint8_t> seed)>;

class Master {
 public:
  explicit Master(std::unique_ptr<MasterChannel> channel,
                  std::chrono::milliseconds timeout = std::chrono::milliseconds{1000});

  // CONNECT, then, if the slave offers DAQ, GET_DAQ_PROCESSOR_INFO and GET_DAQ_RESOLUTION_INFO (an error answer there
  // leaves daq_processor() empty until start_daq() asks again).
  Result<SlaveProperties> connect();
  Status disconnect();
  // A raw command: the positive response (from its 0xFF on), or the failure naming `name` and the ERR code.
  Result<std::vector<std::uint8_t>> command(std::span<const std::uint8_t> request, std::string_view name);

  Result<std::vector<std::uint8_t>> upload(std::uint8_t extension, std::uint32_t address, std::uint32_t size);
  // Writes `bytes` so that the slave applies them at once: one DOWNLOAD, or one DOWNLOAD sequence (block mode).
  Status download(std::uint8_t extension, std::uint32_t address, std::span<const std::uint8_t> bytes);
  Result<std::uint32_t> checksum(std::uint8_t extension, std::uint32_t address, std::uint32_t size);
  // GET_ID: the identification in the response (mode bit 0), or uploaded from where the slave put the MTA.
  Result<std::vector<std::uint8_t>> identification(std::uint8_t type);
  Status unlock(std::uint8_t resource, const KeyFunction& key);
  Status set_calibration_page(std::uint8_t mode, std::uint8_t segment, std::uint8_t page);
  Result<std::uint8_t> calibration_page(std::uint8_t mode, std::uint8_t segment);

  // GET_DAQ_PROCESSOR_INFO and GET_DAQ_RESOLUTION_INFO, asked again.
  Result<DaqProcessor> read_daq_processor();
  // Configures DAQ from scratch with these lists, laid out for the slave (see daq_plan.hpp), and starts them all at
  // once.
  Status start_daq(const std::vector<DaqListSetup>& lists);
  Status stop_daq();
  // Samples decoded so far, waiting up to `wait` for at least one.
  Result<std::vector<DaqSample>> receive_samples(std::chrono::milliseconds wait);
  // Whether receive_samples() also gives the samples whose first ODT came but not all the others (counted as
  // incomplete either way), marked incomplete in their place among the others: for a recorder that keeps a missing
  // sample's time. Off by default.
  void deliver_incomplete_samples(bool deliver) { deliver_incomplete_ = deliver; }

  [[nodiscard]] const SlaveProperties& properties() const { return properties_; }
  [[nodiscard]] const std::optional<DaqProcessor>& daq_processor() const { return daq_processor_; }
  // Seconds per DaqSample::ticks; 0 when samples carry no timestamp.
  [[nodiscard]] double seconds_per_tick() const { return daq_processor_ ? daq_processor_->seconds_per_tick() : 0.0; }
  [[nodiscard]] PacketCounters counters() const;
  [[nodiscard]] std::uint64_t overload_events() const { return counters_.overload_events; }
  [[nodiscard]] const MasterChannel& channel() const { return *channel_; }

 private:
  struct OdtLayout {
    std::size_t list = 0;  // index into the lists start_daq() was given
    std::size_t odt = 0;   // within its list
    bool last = false;
    std::size_t payload = 0;  // the entries' bytes
  };
  struct Assembly {
    bool started = false;
    std::size_t next_odt = 0;
    std::size_t packets = 0;
    std::int64_t ticks = 0;
    std::vector<std::uint8_t> bytes;
  };

  // Sends a command and waits for its answer: the positive response or the error packet, whole.
  Result<std::vector<std::uint8_t>> exchange(std::span<const std::uint8_t> request, std::string_view name);
  Status set_mta(std::uint8_t extension, std::uint32_t address);
  // UPLOADs `size` bytes from where the MTA points.
  Result<std::vector<std::uint8_t>> upload_at_mta(std::uint32_t size);
  void take_asynchronous(std::vector<std::uint8_t> packet);
  void take_daq(std::span<const std::uint8_t> packet);
  // Drops a list's sample in assembly: a missing sample for receive_samples() if asked for and its time is known.
  void abandon(std::size_t list);
  // The layout of the ODT a DAQ packet names, or nullptr.
  [[nodiscard]] const OdtLayout* odt_of(std::span<const std::uint8_t> packet, std::uint8_t odt_number) const;
  std::int64_t unwrap(std::uint32_t timestamp);

  std::unique_ptr<MasterChannel> channel_;
  std::chrono::milliseconds timeout_;
  SlaveProperties properties_;
  std::optional<DaqProcessor> daq_processor_;
  bool timestamps_ = false;                       // the running DAQ lists' samples carry timestamps
  std::vector<std::vector<OdtLayout>> layouts_;   // per list, per ODT
  std::vector<std::optional<OdtLayout>> by_pid_;  // absolute identification: per PID
  std::vector<Assembly> assemblies_;              // per list
  std::optional<std::uint32_t> last_timestamp_;
  std::int64_t ticks_ = 0;
  std::deque<DaqSample> samples_;
  bool deliver_incomplete_ = false;
  PacketCounters counters_;
};

}  // namespace duet::xcp::host
