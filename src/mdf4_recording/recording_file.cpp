#include "duet/mdf4_recording/recording_file.hpp"

#include <vector>

#include "duet/mdf4/writer.hpp"
#include "duet/mdf4_recording/typed_values.hpp"
#include "duet/model/data_type.hpp"
#include "duet/support/number_text.hpp"

namespace duet::mdf4_recording {
namespace {

// The program's signal a column records an element of, if any.
const model::ProgramSignal* signal_of(const model::Recording& recording, const RecordingFileSpec& spec,
                                      std::size_t column) {
  if (spec.program == nullptr || column >= recording.signals.size() || !recording.signals[column]) return nullptr;
  return &spec.program->signals.at(*recording.signals[column]);
}

}  // namespace

Status write_recording_file(const std::filesystem::path& path, const model::Recording& recording,
                            const RecordingFileSpec& spec) {
  mdf4::GroupSpec group{.name = spec.group, .comment = {}, .channels = {}};
  std::vector<mdf4::ValueType> column_types;
  for (std::size_t column = 0; column < recording.columns.size();) {
    const model::ProgramSignal* signal = signal_of(recording, spec, column);
    if (signal == nullptr) {
      group.channels.push_back({.name = recording.names[column],
                                .type = mdf4::ValueType::f64,
                                .unit = recording.units[column],
                                .comment = {},
                                .conversion = std::nullopt,
                                .elements = 1});
      column_types.push_back(mdf4::ValueType::f64);
      ++column;
      continue;
    }
    // A vector's elements are the columns that follow, one each (model::simulate records them so).
    const std::size_t elements = signal->type.elements();
    const mdf4::ValueType type = value_type(signal->type.type);
    group.channels.push_back({.name = signal->name,
                              .type = type,
                              .unit = signal->unit,
                              .comment = signal->description,
                              .conversion = std::nullopt,
                              .elements = elements});
    column_types.insert(column_types.end(), elements, type);
    column += elements;
  }
  if (column_types.size() != recording.columns.size())
    return Failure{path.string() + ": the recording's last signal lacks elements"};
  auto writer =
      mdf4::Writer::create(path, {.groups = {group}, .start_time_ns = spec.start_time_ns, .comment = spec.comment});
  if (!writer) return Failure{writer.error()};
  std::vector<mdf4::Value> values(recording.columns.size());
  for (std::size_t row = 0; row < recording.time_s.size(); ++row) {
    for (std::size_t column = 0; column < values.size(); ++column) {
      auto value = typed_value(recording.columns[column][row], column_types[column]);
      if (!value) {
        return Failure{path.string() + ": " + recording.names[column] + " at " + shortest_text(recording.time_s[row]) +
                       " s: " + value.error()};
      }
      values[column] = value.value();
    }
    if (Status appended = writer.value().append(0, recording.time_s[row], values); !appended) return appended;
  }
  return writer.value().finalise();
}

}  // namespace duet::mdf4_recording
