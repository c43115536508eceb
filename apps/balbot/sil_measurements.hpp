#pragma once
// The measurable signals of generated firmware running in this process, read where its generated A2L says they are:
// each MEASUREMENT's address in the A2L's "signals" segment is an offset into the generated `signals` structure. A
// master on XCP reads the same bytes; here they are copied straight out of memory after each tick, so that a run of
// the firmware on the PC records what `duet sim` records for the model (the same column names, one row per tick).

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "duet/model/simulation.hpp"
#include "duet/support/result.hpp"
#include "duet/xcp/host/a2l.hpp"

namespace duet::sil {

class Measurements {
 public:
  // From the A2L's text (`source` names it in messages); `signals` is the generated structure of `size` bytes that
  // the A2L's segment "signals" describes. Fails when the A2L does not parse, has no such segment, the segment's
  // size is not `size` (an A2L from another generation), or a measurement lies outside it. `signals` must outlive
  // the Measurements.
  [[nodiscard]] static Result<Measurements> from_a2l(std::string_view text, std::string_view source,
                                                     const void* signals, std::size_t size);

  // An empty recording with a column per measured element, named as duet sim names them ("theta",
  // "linux_gains[0]"), with their units.
  [[nodiscard]] model::Recording empty_recording() const;
  // Appends a row: `time_s` and every element's value now. Precondition: `recording` came from empty_recording().
  // Not interrupt-safe: call it between ticks.
  void record(double time_s, model::Recording& recording) const;

 private:
  struct Column {
    std::string name;
    std::string unit;
    xcp::host::DataType type = xcp::host::DataType::uint8;
    std::size_t offset = 0;  // from the start of the signals structure
  };
  explicit Measurements(const void* signals) : signals_(signals) {}

  const void* signals_;
  std::vector<Column> columns_;
};

}  // namespace duet::sil
