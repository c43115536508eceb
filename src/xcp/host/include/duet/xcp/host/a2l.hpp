#pragma once
// The A2L file (ASAM MCD-2 MC, ASAP2 1.71) that tells a master what a slave holds: its signals (MEASUREMENT), its
// parameters (CHARACTERISTIC), its memory segments and pages, its events and how to reach it (IF_DATA XCP). duet
// writes plain files that tools accept: no TYPEDEFs, no /include of AML, IF_DATA XCP inline. The reader reads what
// the writer writes (and files like them), for duet's own master and tools.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "duet/support/result.hpp"
#include "duet/xcp/host/endpoint.hpp"

namespace duet::xcp::host {

enum class DataType : std::uint8_t { uint8, int8, uint16, int16, uint32, int32, uint64, int64, float32, float64 };

std::size_t size_of(DataType type);
// Seconds per tick of ASAM's time unit codes (events, timestamps): 0 = 1 ns, 1 = 10 ns, ... 9 = 1 s; an unknown code
// counts as 1 us.
double seconds_per_unit(std::uint8_t code);
std::string_view a2l_name(DataType type);  // UBYTE, SWORD, FLOAT32_IEEE, ...

// physical = factor * raw + offset
struct Conversion {
  double factor = 1.0;
  double offset = 0.0;
  bool operator==(const Conversion&) const = default;
};

// A signal or a parameter: a scalar, or an array of `count` elements.
struct Variable {
  std::string name;
  std::string description;
  DataType type = DataType::float32;
  std::uint8_t extension = 0;
  std::uint32_t address = 0;
  std::uint32_t count = 1;
  std::string unit;
  double minimum = 0.0;
  double maximum = 0.0;
  Conversion conversion;
  bool operator==(const Variable&) const = default;
};

struct EventInfo {
  std::string name;
  std::uint16_t channel = 0;
  std::uint8_t time_cycle = 0;  // in time_unit; 0: not periodic
  std::uint8_t time_unit = 6;   // 0 = 1 ns ... 6 = 1 ms ... 9 = 1 s
  std::uint8_t priority = 0;
  [[nodiscard]] double period_s() const { return seconds_per_unit(time_unit) * time_cycle; }  // 0: not periodic
  bool operator==(const EventInfo&) const = default;
};

struct MemoryInfo {
  std::string name;
  std::uint8_t extension = 0;
  std::uint32_t address = 0;
  std::uint32_t size = 0;
  bool calibration = false;  // a calibration segment with a working and a reference page
  bool operator==(const MemoryInfo&) const = default;
};

struct A2lDescription {
  std::string project = "duet";
  std::string module;
  std::string description;
  std::vector<MemoryInfo> memory;
  std::vector<Variable> measurements;     // read-only
  std::vector<Variable> characteristics;  // tunable
  std::vector<EventInfo> events;
  std::uint8_t max_cto = 248;
  std::uint16_t max_dto = 1024;
  std::uint16_t max_daq_lists = 16;
  std::uint8_t timestamp_unit = 3;  // 3 = 1 us
  std::uint16_t timestamp_ticks = 1;
  [[nodiscard]] double timestamp_tick_s() const { return seconds_per_unit(timestamp_unit) * timestamp_ticks; }
  Endpoint transport;
  bool operator==(const A2lDescription&) const = default;
};

std::string write_a2l(const A2lDescription& a2l);

// Reads an A2L file; failures say "line:column: problem". `source` names the file in messages.
Result<A2lDescription> read_a2l(std::string_view text, std::string_view source = "A2L");

}  // namespace duet::xcp::host
