#pragma once
// A recording of one time base (model::Recording: a row per tick, `duet sim`'s and the plant's of `duet pil`) as an
// MDF 4 file of one group. The columns a simulation took from the program's signals become channels of their
// signals' exact types, units and descriptions, a vector one channel of its elements; the others (what a plant shows
// of itself) are doubles.

#include <cstdint>
#include <filesystem>
#include <string>

#include "duet/model/program.hpp"
#include "duet/model/simulation.hpp"
#include "duet/support/result.hpp"

namespace duet::mdf4_recording {

struct RecordingFileSpec {
  std::string group;    // the group's acquisition name, e.g. "base rate 1 ms"
  std::string comment;  // the file's comment: what was recorded, from what
  std::int64_t start_time_ns = 0;
  // The program the recording's signal columns (model::Recording::signals) come from; none: every column a double.
  const model::Program* program = nullptr;
};

// Writes the file whole and finalised; a failure names the file, and the column and time of a value its signal's
// type does not hold.
[[nodiscard]] Status write_recording_file(const std::filesystem::path& path, const model::Recording& recording,
                                          const RecordingFileSpec& spec);

}  // namespace duet::mdf4_recording
