#pragma once
// An XCP DAQ recording as an MDF 4 file: a group per DAQ list, named after the list's event, its channels the A2L
// variables the list samples (a2l_channels.hpp), the samples stored raw in their exact types as the master
// assembled them. A sample the master reports incomplete is written with every value missing. Groups of other
// samples may come first in the same file (duet pil's plant, a row per tick).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "duet/mdf4/writer.hpp"
#include "duet/support/result.hpp"
#include "duet/xcp/host/a2l.hpp"

namespace duet::mdf4_recording {

// One DAQ list: the event that samples it and the variables it holds, in the order of its entries.
struct DaqGroup {
  xcp::host::EventInfo event;
  std::vector<xcp::host::Variable> variables;
};

class DaqFile {
 public:
  // Creates the file (an MDF writer's, unfinalised until finalise()); `comment` is the file's. `groups_before` are
  // described before the DAQ lists' groups and take their samples by append_before().
  static Result<DaqFile> create(const std::filesystem::path& path, std::vector<DaqGroup> groups,
                                const std::string& comment, std::int64_t start_time_ns,
                                std::vector<mdf4::GroupSpec> groups_before = {});

  // One sample of list `list` at `time_s` (seconds since the start): the entries' bytes one after another, or none
  // for a sample the master reports incomplete.
  Status append(std::size_t list, double time_s, std::optional<std::span<const std::uint8_t>> bytes);
  // One sample of group `group` of `groups_before`.
  Status append_before(std::size_t group, double time_s, std::span<const mdf4::Value> values);
  Status flush() { return writer_.flush(); }
  Status finalise() { return writer_.finalise(); }

 private:
  DaqFile(mdf4::Writer writer, std::vector<DaqGroup> groups, std::size_t groups_before);
  mdf4::Writer writer_;
  std::vector<DaqGroup> groups_;
  std::size_t groups_before_;
  std::vector<std::size_t> values_per_sample_;  // per list
  std::vector<mdf4::Value> values_;
};

}  // namespace duet::mdf4_recording
