#pragma once
// `duet pil`'s MDF file: the plant's own quantities, a row per tick, as one group "every tick" of doubles, and after
// it the firmware's DAQ lists, a group per event (daq_file.hpp). The samples are appended as they come, from two
// threads (the plant's session and the XCP master's); the file is flushed every second of the PC's clock, so that a
// run that is killed leaves all but its last second.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "duet/mdf4_recording/daq_file.hpp"

namespace duet::mdf4_recording {

// The plant's quantities: a channel each, a name and a unit.
struct PlantColumns {
  std::vector<std::string> names;
  std::vector<std::string> units;
};

class PlantAndDaqFile {
 public:
  // Creates the file, unfinalised until finalise(); `lists` may be none (the plant alone).
  static Result<std::unique_ptr<PlantAndDaqFile>> create(const std::filesystem::path& path, const PlantColumns& plant,
                                                         std::vector<DaqGroup> lists, const std::string& comment,
                                                         std::int64_t start_time_ns);

  // Thread-safe. After a failure, or once finalised, samples are dropped: the first failure is finalise()'s answer.
  void append_plant(double time_s, std::span<const double> values);
  // One sample of DAQ list `list`, as DaqFile::append takes it.
  void append_daq(std::size_t list, double time_s, std::optional<std::span<const std::uint8_t>> bytes);
  // Writes what is buffered and marks the file finalised (once; later calls say the same); the first failure of any
  // append, flush or the finalisation.
  Status finalise();

 private:
  explicit PlantAndDaqFile(DaqFile file);
  void took(Status appended);  // under mutex_

  std::mutex mutex_;
  DaqFile file_;
  std::vector<mdf4::Value> row_;
  std::optional<Failure> failure_;
  bool finalised_ = false;
  std::chrono::steady_clock::time_point next_flush_;
};

}  // namespace duet::mdf4_recording
