#include "sil_measurements.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "duet/model/generate.hpp"

namespace duet::sil {
namespace {

template <typename T>
double load(const std::byte* at) {
  T value{};
  std::memcpy(&value, at, sizeof(T));  // the structure's members may be of any type at that offset: copy, not cast
  return static_cast<double>(value);
}

// The raw value, without the A2L's conversion (generated A2Ls convert by identity, and 1 * x + 0 would turn -0
// into +0, which duet sim's recording keeps).
double load(xcp::host::DataType type, const std::byte* at) {
  using xcp::host::DataType;
  switch (type) {
    case DataType::uint8: return load<std::uint8_t>(at);
    case DataType::int8: return load<std::int8_t>(at);
    case DataType::uint16: return load<std::uint16_t>(at);
    case DataType::int16: return load<std::int16_t>(at);
    case DataType::uint32: return load<std::uint32_t>(at);
    case DataType::int32: return load<std::int32_t>(at);
    case DataType::uint64: return load<std::uint64_t>(at);
    case DataType::int64: return load<std::int64_t>(at);
    case DataType::float32: return load<float>(at);
    case DataType::float64: return load<double>(at);
  }
  return 0;
}

}  // namespace

Result<Measurements> Measurements::from_a2l(std::string_view text, std::string_view source, const void* signals,
                                            std::size_t size) {
  auto a2l = xcp::host::read_a2l(text, source);
  if (!a2l) return Failure{a2l.error()};
  const auto& memory = a2l.value().memory;
  const auto segment = std::find_if(memory.begin(), memory.end(),
                                    [](const xcp::host::MemoryInfo& info) { return info.name == "signals"; });
  if (segment == memory.end()) return Failure{std::string{source} + ": no memory segment 'signals'"};
  if (segment->size != size) {
    return Failure{std::string{source} + ": the segment 'signals' has " + std::to_string(segment->size) +
                   " bytes, the firmware's Signals " + std::to_string(size) +
                   ": the A2L is not from the generation the firmware was built from"};
  }
  Measurements result{signals};
  for (const xcp::host::Variable& measurement : a2l.value().measurements) {
    if (model::is_executive_account(a2l.value(), measurement)) continue;  // not the model's to record
    const std::size_t element_size = xcp::host::size_of(measurement.type);
    const std::uint64_t end = std::uint64_t{measurement.address} + std::uint64_t{measurement.count} * element_size;
    const auto within = [&](const xcp::host::MemoryInfo& info) {
      return measurement.address >= info.address && end <= std::uint64_t{info.address} + info.size;
    };
    if (!within(*segment)) {
      return Failure{std::string{source} + ": measurement '" + measurement.name +
                     "' lies outside the segment 'signals'"};
    }
    std::string name = measurement.name;
    std::replace(name.begin(), name.end(), '.', '/');  // a subsystem's path, as duet sim names its signals
    for (std::uint32_t element = 0; element < measurement.count; ++element) {
      result.columns_.push_back({measurement.count == 1 ? name : name + "[" + std::to_string(element) + "]",
                                 measurement.unit, measurement.type,
                                 measurement.address - segment->address + element * element_size});
    }
  }
  return result;
}

model::Recording Measurements::empty_recording() const {
  model::Recording recording;
  for (const Column& column : columns_) {
    recording.names.push_back(column.name);
    recording.units.push_back(column.unit);
  }
  recording.columns.resize(columns_.size());
  return recording;
}

void Measurements::record(double time_s, model::Recording& recording) const {
  const auto* base = static_cast<const std::byte*>(signals_);
  recording.time_s.push_back(time_s);
  for (std::size_t k = 0; k < columns_.size(); ++k)
    recording.columns[k].push_back(load(columns_[k].type, base + columns_[k].offset));
}

}  // namespace duet::sil
