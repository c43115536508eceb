#pragma once
// A model as read from its file (docs/MODELS.md): blocks connected by signal names, parameters, constants, signal
// declarations, sample times and subsystems, every element with the place in the file it came from.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace duet::model {

// 1-based, as editors count. `file`: the model file it is in when that is a referenced model's (a model reference
// brings another file's blocks), empty for the model's own file.
struct Location {
  int line = 0;
  int column = 0;
  std::string file;
};

enum class DataType : std::uint8_t { float64, float32, int8, int16, int32, uint8, uint16, uint32, boolean };

// A literal: a scalar (shape {}), a vector (shape {n}) or a matrix (shape {rows, columns}), row by row.
struct Value {
  std::vector<double> elements;
  std::vector<std::size_t> shape;
};

struct Parameter {
  std::string name;
  Value value;
  DataType type = DataType::float64;
  std::string unit;
  std::optional<double> minimum;
  std::optional<double> maximum;
  std::string description;
  std::vector<std::string> labels;  // value k's name (a choice, a state); empty: a number
  Location location;
};

struct Constant {
  std::string name;
  Value value;
  Location location;
};

struct SignalDeclaration {
  std::string name;
  std::optional<DataType> type;
  std::vector<std::size_t> shape;
  std::string unit;
  bool measurable = false;
  std::string description;
  std::vector<std::string> labels;  // value k's name (a state, a choice); empty: a number
  Location location;
};

// A block parameter: a literal, or the name of a model-level parameter or constant.
struct BlockParameter {
  std::optional<Value> literal;
  std::string reference;
  std::string text;              // as written, for messages (also a word like a pin name)
  std::optional<DataType> type;  // a Code block's parameters declare theirs
  Location location;
};

// Port -> signal name; a Code block's ports also declare their type and size.
struct Connection {
  std::string port;
  std::string signal;
  Location location;
  std::optional<DataType> type;
  std::vector<std::size_t> shape;
};

// A Code block's function: void function(const Inputs&, Outputs&, State&, const Parameters&), in a freestanding
// header beside the model.
struct StateVariable {
  std::string name;
  DataType type = DataType::float64;
  std::vector<std::size_t> shape;
  Value initial;
  Location location;
};

struct UserCode {
  std::string function;
  std::string file;  // relative to the model file
  Location file_location;
  std::vector<StateVariable> state;
  bool direct_feedthrough = true;  // outputs depend on inputs within the step
};

struct Period {
  enum class Kind : std::uint8_t { inherited, base, multiple, constant } kind = Kind::inherited;
  std::int64_t multiple = 1;  // of the base period, for Kind::multiple
  Location location;
};

struct Trigger {
  enum class Kind : std::uint8_t { none, interrupt, edge } kind = Kind::none;
  std::string interrupt;
  std::optional<int> priority;  // none: `auto`
  std::string edge;             // rising, falling, either
  std::string signal;
  Location location;
};

struct Block {
  std::string name;
  std::string type;
  Location location;
  Location type_location;
  Period period;
  std::vector<std::pair<std::string, BlockParameter>> parameters;
  std::vector<Connection> inputs;
  std::vector<Connection> outputs;
  std::vector<Block> blocks;  // a Subsystem's; a model reference's, from the referenced file
  std::string model;          // a model reference: the referenced file, relative to the referencing one
  Location model_location;
  Trigger trigger;
  std::string enable;            // a Subsystem's enabling signal
  std::optional<UserCode> code;  // a Code block's
};

// The XCP slave the generated code carries: its packet limits and the sizes of its DAQ tables, transmit queue and
// download buffer. The generator builds the firmware's slave and the A2L from these same numbers (docs/XCP.md, "One
// description"); a model's `xcp:` section changes the defaults.
struct XcpSettings {
  std::uint32_t max_cto = 248;  // command and response packets, bytes
  std::uint32_t max_dto = 248;  // DAQ packets, bytes
  std::uint32_t daq_lists = 8;
  std::uint32_t odts = 64;  // in all lists together
  std::uint32_t odt_entries = 512;
  std::uint32_t queue_bytes = 16 * 1024;    // responses, events and DAQ packets waiting for the line
  std::uint32_t download_bytes = 256;       // the longest DOWNLOAD sequence, applied at once
  std::string identification = "absolute";  // how DAQ packets name their ODT (docs/XCP.md)
  std::uint32_t timestamp_bytes = 4;
  Location location;  // of the section, when the model has one
};

struct Model {
  std::string file;
  int version = 0;
  std::string name;
  std::string description;
  double base_period_us = 0;
  Location base_period_location;
  // `precision: double`: the model computes in double precision on purpose; otherwise each place double precision
  // starts is a warning, since the Cortex-M4's FPU is single precision.
  bool double_precision = false;
  std::vector<Constant> constants;
  std::vector<Parameter> parameters;
  std::vector<SignalDeclaration> signals;
  std::vector<Block> blocks;
  XcpSettings xcp;
};

}  // namespace duet::model
