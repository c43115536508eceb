#pragma once
// The A2L file (ASAM MCD-2 MC, ASAP2 1.71) that tells a master what a slave holds: its signals (MEASUREMENT), its
// parameters (CHARACTERISTIC), its memory segments and pages, its events and how to reach it (IF_DATA XCP). duet
// writes plain files that tools accept: no TYPEDEFs, no /include of AML, IF_DATA XCP inline. The reader reads what
// the writer writes and what other tools write (TYPEDEFs and INSTANCEs, AXIS_PTS, CURVE and MAP, /include), for
// duet's own master and tools, and says what it leaves out.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "duet/support/result.hpp"
#include "duet/xcp/checksum.hpp"
#include "duet/xcp/daq.hpp"
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

// A raw value's name in a verbal conversion (COMPU_METHOD TAB_VERB, COMPU_VTAB): what a master shows instead of it.
struct Label {
  double raw = 0.0;
  std::string text;
  bool operator==(const Label&) const = default;
};

// An axis of a CURVE or MAP, as the reader found it: where a master finds its points.
struct Axis {
  enum class Kind : std::uint8_t {
    standard,  // STD_AXIS: the points are stored in the parameter's record, before or after its values
    common,    // COM_AXIS: the points are an AXIS_PTS of their own, shared by parameters (`reference`)
    fixed,     // FIX_AXIS: the points are computed from the A2L's numbers, not stored
    curve,     // CURVE_AXIS: the points are the values of another CURVE (`reference`)
    rescale,   // RES_AXIS: a rescale axis (an AXIS_RESCALE record, `reference`)
  };
  Kind kind = Kind::standard;
  std::string input;                  // the measurement the axis is looked up with ("NO_INPUT_QUANTITY" when none)
  std::uint32_t points = 0;           // the most points the axis has
  std::string reference;              // the AXIS_PTS or CURVE named (common, curve, rescale)
  DataType type = DataType::float32;  // standard and common: the points' type
  std::uint32_t address = 0;          // standard and common: where the first point is
  bool operator==(const Axis&) const = default;
};

// A signal or a parameter: a scalar, or an array of `count` elements.
struct Variable {
  std::string name;
  std::string description;
  DataType type = DataType::float32;
  std::uint8_t extension = 0;
  std::uint32_t address = 0;  // of the first value (past the axis points a CURVE's or MAP's record may start with)
  std::uint32_t count = 1;    // values in all
  std::string unit;
  double minimum = 0.0;
  double maximum = 0.0;
  Conversion conversion;
  // A verbal conversion: raw values shown by name (a state, a choice); empty: numbers. Replaces `conversion`.
  std::vector<Label> labels;
  // The array's dimensions (MATRIX_DIM), their product `count`; empty: one dimension of `count`.
  std::vector<std::uint32_t> dimensions;
  // A CURVE's or MAP's axes, x first (read only: the writer writes values and arrays).
  std::vector<Axis> axes;
  // The COMPU_METHOD's type when the reader cannot apply it (TAB_INTP, FORM, "RAT_FUNC (not linear)", ...):
  // `conversion` is then the identity and the values are raw. Empty: `conversion` (or `labels`) is the whole story.
  std::string unapplied_conversion;
  bool operator==(const Variable&) const = default;
};

struct EventInfo {
  std::string name;
  std::uint16_t channel = 0;
  std::uint8_t time_cycle = 0;  // in time_unit; 0: not periodic
  std::uint8_t time_unit = 6;   // 0 = 1 ns ... 6 = 1 ms ... 9 = 1 s
  std::uint8_t priority = 0;
  // The EVENT's short name (at most 8 characters, unique among the events); empty: the writer makes one from the name.
  std::string short_name;
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
  // The ECU program's identifier (MOD_PAR EPK and ADDR_EPK): the firmware holds the same text at `epk_address` and
  // answers GET_ID type 5 with it, so that a master sees whether the A2L fits the firmware. Empty: none. The writer
  // declares a read-only memory segment for it when no segment covers it, so that a master can upload it.
  std::string epk;
  std::uint32_t epk_address = 0;
  // IF_DATA XCP PROTOCOL_LAYER: the largest command and data packets.
  std::uint8_t max_cto = 248;
  std::uint16_t max_dto = 1024;
  // IF_DATA XCP DAQ: the most DAQ lists (MAX_DAQ), the largest ODT entry in bytes (MAX_ODT_ENTRY_SIZE_DAQ), how a DAQ
  // packet names its ODT (IDENTIFICATION_FIELD_TYPE_*), and the timestamp's size in bytes (1, 2 or 4; 0: none), unit
  // (3 = 1 us, as EventInfo::time_unit) and ticks per unit.
  std::uint16_t max_daq_lists = 16;
  std::uint8_t max_odt_entry_size = 0xFF;
  IdentificationField identification_field = IdentificationField::absolute;
  std::uint8_t timestamp_size = 4;
  std::uint8_t timestamp_unit = 3;
  std::uint16_t timestamp_ticks = 1;
  [[nodiscard]] double timestamp_tick_s() const { return seconds_per_unit(timestamp_unit) * timestamp_ticks; }
  // The calibration segments (IF_DATA XCP SEGMENT): BUILD_CHECKSUM's algorithm and largest block, and whether each has
  // a read-only reference page (1) beside its working page (0).
  ChecksumType checksum_type = ChecksumType::crc_16_ccitt;
  std::uint32_t checksum_max_block_size = 0xFFFF;
  bool calibration_reference_page = true;
  // Whether the firmware handles USER_CMD (a SlaveConfiguration::user_command): only then is it an OPTIONAL_CMD.
  bool user_command = false;
  Endpoint transport;
  // What the reader met and left out or read only in part, as "FILE:LINE:COLUMN: what" (the writer ignores them).
  std::vector<std::string> warnings;
  bool operator==(const A2lDescription&) const = default;
};

std::string write_a2l(const A2lDescription& a2l);

// Reads A2L text; failures say "FILE:LINE:COLUMN: problem", with `source` as FILE. An /include names a file relative to
// the folder of `source`.
Result<A2lDescription> read_a2l(std::string_view text, std::string_view source = "A2L");
// Reads an A2L file, its /includes relative to its folder.
Result<A2lDescription> read_a2l_file(const std::string& path);

}  // namespace duet::xcp::host
