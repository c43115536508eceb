#include "typing.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <string_view>

#include "block_semantics.hpp"
#include "duet/model/data_type.hpp"
#include "duet/support/closest_word.hpp"
#include "duet/support/number_text.hpp"

namespace duet::model {
namespace {

std::optional<SignalType> first_known(const KnownTypes& inputs, std::initializer_list<std::size_t> among) {
  for (const std::size_t index : among) {
    if (index < inputs.size() && inputs[index]) return inputs[index];
  }
  return std::nullopt;
}

std::optional<SignalType> first_known(const KnownTypes& inputs) {
  for (const auto& input : inputs) {
    if (input) return input;
  }
  return std::nullopt;
}

std::optional<DataType> word_type(const ProgramBlock& block) {
  const Argument* type = block.argument("type");
  if (type == nullptr) return std::nullopt;
  return parse_type_name(type->text);
}

std::size_t size_argument(const ProgramBlock& block, const char* name) {
  const Argument* argument = block.argument(name);
  if (argument == nullptr || argument->value.elements.empty()) return 1;
  return static_cast<std::size_t>(std::max(1.0, argument->value.elements.front()));
}

// A whole-number parameter as written (offsets, counts); `fallback` when it is not given.
std::size_t number_argument(const ProgramBlock& block, const char* name, std::size_t fallback) {
  const Argument* argument = block.argument(name);
  if (argument == nullptr || argument->value.elements.empty() || !(argument->value.elements.front() >= 0)) {
    return fallback;
  }
  return static_cast<std::size_t>(argument->value.elements.front());
}

// The shape of `count` elements: one is a scalar.
std::vector<std::size_t> sized(std::size_t count) {
  return count > 1 ? std::vector<std::size_t>{count} : std::vector<std::size_t>{};
}

// The type of a value a parameter gives: a tunable parameter's own, a literal's is the block's (`fallback`).
SignalType argument_type(const Program& program, const Argument& argument, DataType fallback) {
  if (argument.kind == Argument::Kind::parameter) {
    const Parameter& parameter = program.parameter(argument);
    return {parameter.type, parameter.value.shape};
  }
  return {fallback, argument.value.shape};
}

std::vector<std::size_t> product_shape(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) {
  const std::size_t rows = a.empty() ? 1 : a[0];
  if (b.size() == 1) return {rows};  // a matrix times a vector is a vector
  const std::size_t columns = b.size() == 2 ? b[1] : 1;
  return {rows, columns};
}

}  // namespace

KnownTypes infer_outputs(const Program& program, const ProgramBlock& block, const KnownTypes& inputs,
                         bool guess_scalars) {
  KnownTypes outputs(block.outputs.size());
  if (outputs.empty()) return outputs;
  const std::string& type = block.type();
  std::optional<SignalType>& y = outputs[0];
  const auto shape_of =
      [guess_scalars](const std::optional<SignalType>& input) -> std::optional<std::vector<std::size_t>> {
    if (input) return input->shape;
    if (guess_scalars) return std::vector<std::size_t>{};
    return std::nullopt;
  };
  const auto boolean_like = [&shape_of](const std::optional<SignalType>& input) -> std::optional<SignalType> {
    const auto shape = shape_of(input);
    if (!shape) return std::nullopt;
    return SignalType{DataType::boolean, *shape};
  };
  if (block.block->code) {
    for (std::size_t k = 0; k < outputs.size(); ++k) {
      const Connection& port = block.block->outputs[k];
      outputs[k] = SignalType{port.type.value_or(DataType::float64), port.shape};
    }
  } else if (type == "Constant") {
    const Argument* value = block.argument("value");
    if (value != nullptr) y = argument_type(program, *value, word_type(block).value_or(DataType::float64));
  } else if (type == "EdgeDetect") {
    y = SignalType{DataType::boolean, {}};
  } else if (type == "Not" || type == "Compare") {
    y = boolean_like(first_known(inputs, {0}));
  } else if (type == "Logic") {
    y = boolean_like(first_known(inputs));
  } else if (type == "Relational") {
    // One input may be a scalar that the other's elements are each compared with.
    const auto u1 = shape_of(inputs[0]);
    const auto u2 = shape_of(inputs[1]);
    if (u1 && u2) y = SignalType{DataType::boolean, u1->empty() ? *u2 : *u1};
  } else if (type == "Switch") {
    y = first_known(inputs, {0, 2});
  } else if (type == "Convert") {
    if (shape_of(inputs[0]) && word_type(block)) y = SignalType{*word_type(block), *shape_of(inputs[0])};
  } else if (type == "Mux") {
    if (std::all_of(inputs.begin(), inputs.end(), [](const auto& input) { return input.has_value(); })) {
      std::size_t count = 0;
      for (const auto& input : inputs) count += input->elements();
      y = SignalType{inputs[0]->type, {count}};
    }
  } else if (type == "Demux" || type == "Selector") {
    if (inputs[0]) std::fill(outputs.begin(), outputs.end(), SignalType{inputs[0]->type, {}});
  } else if (type == "Lookup") {
    const Argument* table = block.argument("table");
    if (table != nullptr && inputs[0]) y = SignalType{argument_type(program, *table, DataType::float64).type, {}};
  } else if (type == "MatrixMultiply") {
    if (inputs[0] && inputs[1]) y = SignalType{inputs[0]->type, product_shape(inputs[0]->shape, inputs[1]->shape)};
  } else if (type == "Counter") {
    y = SignalType{word_type(block).value_or(DataType::uint32), {}};
  } else if (type == "Step" || type == "PulseGenerator") {
    y = SignalType{word_type(block).value_or(DataType::float64), {}};
  } else if (type == "BytePack") {
    if (std::all_of(inputs.begin(), inputs.end(), [](const auto& input) { return input.has_value(); })) {
      std::size_t bytes = 0;
      for (const auto& input : inputs) bytes += size_of(input->type) * input->elements();
      y = SignalType{DataType::uint8, sized(bytes)};
    }
  } else if (type == "ByteUnpack") {
    if (word_type(block)) y = SignalType{*word_type(block), sized(size_argument(block, "count"))};
  } else if (type == "Mean") {
    if (inputs[0]) y = SignalType{inputs[0]->type, {}};
  } else if (type == "StateSpace" || type == "StateFeedback" || type == "KalmanFilter") {
    // Outputs as many as the rows of C (StateSpace), of K (StateFeedback) or of A (KalmanFilter: the states).
    const char* rows = type == "StateSpace" ? "c" : type == "StateFeedback" ? "k" : "a";
    if (inputs[0]) y = SignalType{inputs[0]->type, sized(argument_size(program, block, rows).rows)};
  } else if (type == "SpiReceive") {
    y = SignalType{DataType::uint8, sized(size_argument(block, "size"))};
  } else if (type == "GpioIn") {
    y = SignalType{DataType::boolean, {}};
  } else if (type == "Exti") {
    y = SignalType{DataType::boolean, {}};
  } else if (type == "InputCapture") {
    outputs[0] = SignalType{DataType::uint32, {}};
    if (outputs.size() > 1) outputs[1] = SignalType{DataType::boolean, {}};
  } else if (type == "SpiDma" || type == "IpcReceive") {
    y = SignalType{DataType::uint8, sized(size_argument(block, "size"))};
  } else if (type == "PlantInput" || type == "Inport") {
    y = SignalType{DataType::float64, sized(size_argument(block, "size"))};
  } else if (type == "AdcDma") {
    y = SignalType{DataType::uint16, sized(size_argument(block, "count"))};
  } else {  // Gain, Sum, Product, Abs, Saturation, Atan2, delays, integrators, PID, RateTransition: as their inputs
    y = first_known(inputs);
  }
  // Demux and InputCapture name outputs by port: keep each output's type on the port it belongs to.
  if (type == "InputCapture") {
    for (std::size_t k = 0; k < outputs.size(); ++k) {
      outputs[k] =
          block.output_ports[k] == "edge" ? SignalType{DataType::boolean, {}} : SignalType{DataType::uint32, {}};
    }
  }
  return outputs;
}

namespace {

// One block's checks. Each names the block, the port or parameter, what it is and what it should be.
class BlockCheck {
 public:
  BlockCheck(const Program& program, const ProgramBlock& block, std::vector<Diagnostic>& diagnostics)
      : program_(program),
        block_(block),
        diagnostics_(diagnostics),
        name_("block '" + block.path + "' (" + block.type() + ")") {}

  void run() {
    const std::size_t before = diagnostics_.size();
    words();
    if (block_.block->code) {
      code_ports();
      return;
    }
    inputs();
    // Parameters mean something only once the block's own types are right.
    if (diagnostics_.size() == before) parameters();
  }

 private:
  void error(Location where, const std::string& message, const std::string& hint) {
    diagnostics_.push_back({Diagnostic::Severity::error, where, message, hint});
  }

  [[nodiscard]] const SignalType& input_type(std::size_t k) const { return program_.signals[block_.inputs[k]].type; }
  [[nodiscard]] std::string input(std::size_t k) const {
    return "input '" + block_.input_ports[k] + "' (signal '" + program_.signals[block_.inputs[k]].name + "')";
  }
  [[nodiscard]] Location input_location(std::size_t k) const {
    for (const Connection& connection : block_.block->inputs) {
      if (connection.port == block_.input_ports[k]) return connection.location;
    }
    return block_.block->location;
  }
  [[nodiscard]] Location output_location(std::size_t k) const {
    for (const Connection& connection : block_.block->outputs) {
      if (connection.port == block_.output_ports[k]) return connection.location;
    }
    return block_.block->location;
  }
  [[nodiscard]] bool is(std::initializer_list<const char*> types) const {
    return std::any_of(types.begin(), types.end(), [this](const char* type) { return block_.type() == type; });
  }

  // Parameters that are words: a data type, an operator, a mode, signs.
  void words() {
    const Argument* type = block_.argument("type");
    if (type != nullptr && is({"Constant", "Convert", "Counter", "ByteUnpack", "Step", "PulseGenerator"}) &&
        !word_type(block_)) {
      constexpr std::string_view types[] = {"double", "single", "int8",   "int16",  "int32",
                                            "uint8",  "uint16", "uint32", "boolean"};
      const auto closest = closest_word(type->text, types);
      error(type->location, "parameter 'type' of " + name_ + " is '" + type->text + "', which is not a data type",
            closest ? "did you mean '" + std::string{*closest} + "'?"
                    : "double, single, int8, int16, int32, uint8, uint16, uint32 or boolean");
    }
    const Argument* op = block_.argument("operator");
    if (op != nullptr && is({"Compare", "Relational"}) && !parse_compare_operator(op->text)) {
      error(op->location, name_ + " has no operator '" + op->text + "'", "its operators: <, <=, ==, !=, >= and >");
    }
    if (op != nullptr && block_.type() == "Logic" && !parse_logic_operator(op->text)) {
      std::string capitals = op->text;
      for (char& c : capitals) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      error(op->location, name_ + " has no operator '" + op->text + "'",
            parse_logic_operator(capitals) ? "did you mean '" + capitals + "'?"
                                           : "its operators: AND, OR, XOR, NAND and NOR");
    }
    const Argument* mode = block_.argument("mode");
    if (mode != nullptr && block_.type() == "RateTransition" && mode->text != "deterministic" &&
        mode->text != "latest") {
      error(mode->location, name_ + " has no mode '" + mode->text + "'",
            "its modes: deterministic, between periodic rates, and latest, with an interrupt task");
    }
    choice("function", {"min", "max"});
    choice("endian", {"little", "big"});
    choice("anti_windup", {"none", "clamping"});
    choice("method", {"linear", "nearest", "flat", "above"});
    choice("extrapolation", {"clip", "linear"});
    const Argument* signs = block_.argument("signs");
    if (signs != nullptr && block_.type() == "Product") {
      if (signs->text.find_first_not_of("*/") != std::string::npos || signs->text.size() != block_.inputs.size()) {
        error(signs->location, "signs '" + signs->text + "' of " + name_ + " are not one * or / per input",
              "u1 first: '*/' is u1 / u2");
      }
    }
    for (const char* fixed : {"time_s", "period_s", "width_s", "delay_s", "window", "offset", "count"}) {
      const Argument* argument = block_.argument(fixed);
      if (argument == nullptr) continue;
      if (argument->kind == Argument::Kind::parameter) {
        error(argument->location,
              "parameter '" + std::string{fixed} + "' of " + name_ + " names the tunable parameter '" + argument->text +
                  "', but it sizes the generated code",
              "give a number, or a constant (constants: in the model)");
      } else if (argument->value.elements.size() != 1 ||
                 !(argument->value.elements[0] >= (std::string_view{fixed} == "window" ? 1 : 0))) {
        error(argument->location,
              "parameter '" + std::string{fixed} + "' of " + name_ + " must be one number, " +
                  (std::string_view{fixed} == "window" ? "1" : "0") + " or more",
              "for example " + std::string{fixed} + ": 1");
      }
    }
    if (signs != nullptr && block_.type() == "Sum") {
      std::string given = signs->text;
      given.erase(std::remove(given.begin(), given.end(), '|'), given.end());
      if (given.find_first_not_of("+-") != std::string::npos) {
        error(signs->location, "signs '" + signs->text + "' of " + name_ + " are not all + or -",
              "one + or - per input, u1 first: '+-' is u1 - u2");
      } else if (given.size() != block_.inputs.size()) {
        error(signs->location,
              "signs '" + signs->text + "' of " + name_ + " give " + std::to_string(given.size()) + " signs for " +
                  std::to_string(block_.inputs.size()) + " inputs",
              "one + or - per input, u1 first");
      }
    }
  }

  // A word parameter that takes one of a few words.
  void choice(const char* parameter, std::initializer_list<std::string_view> words) {
    const Argument* given = block_.argument(parameter);
    if (given == nullptr || std::find(words.begin(), words.end(), given->text) != words.end()) return;
    std::string list;
    for (const std::string_view word : words) list += (list.empty() ? "" : " or ") + std::string{word};
    error(given->location, name_ + " has no " + parameter + " '" + given->text + "'", "give " + list);
  }

  // Inputs that must agree with each other in type, and in size where `shapes`.
  void same(const std::vector<std::size_t>& ports, bool types, bool shapes) {
    for (std::size_t n = 1; n < ports.size(); ++n) {
      const std::size_t first = ports[0];
      const std::size_t k = ports[n];
      if (k >= block_.inputs.size()) continue;
      const SignalType& a = input_type(first);
      const SignalType& b = input_type(k);
      if (types && a.type != b.type) {
        error(input_location(k),
              "type mismatch: " + input(k) + " of " + name_ + " is " + describe(b) + ", but " + input(first) + " is " +
                  describe(a),
              "convert one of them with a Convert block");
        return;
      }
      if (shapes && a.shape != b.shape) {
        error(input_location(k),
              "size mismatch: " + input(k) + " of " + name_ + " is " + describe(b) + ", but " + input(first) + " is " +
                  describe(a),
              "a " + block_.type() + " works element by element on inputs of one size");
        return;
      }
    }
  }

  void inputs() {
    std::vector<std::size_t> all(block_.inputs.size());
    for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
    if (block_.inputs.empty()) {
      if (block_.type() == "Counter" && !block_.outputs.empty() &&
          program_.signals[block_.outputs[0]].type.type == DataType::boolean) {
        error(block_.argument("type")->location, "type mismatch: " + name_ + " cannot count in boolean",
              "give it an integer type, or leave out 'type' for uint32");
      }
      return;
    }
    if (is({"DiscreteIntegrator", "DiscreteDerivative", "DiscretePid", "Atan2", "PwmOut", "FilteredDerivative",
            "TransferFunction", "StateSpace", "Mean", "MovingAverage", "KalmanFilter", "StateFeedback", "DeadZone",
            "Interpolation"}) &&
        !is_floating(input_type(0).type)) {
      error(
          input_location(0),
          "type mismatch: " + name_ + " computes in floating point, but " + input(0) + " is " + describe(input_type(0)),
          "convert it to single or double with a Convert block");
      return;
    }
    if (is({"Abs", "Gain", "Sum", "Product", "Saturation", "MatrixMultiply", "Sign", "MinMax"}) &&
        input_type(0).type == DataType::boolean) {
      error(input_location(0), "type mismatch: " + name_ + " does arithmetic, but " + input(0) + " is boolean",
            "convert it to a number with a Convert block");
      return;
    }
    if (is({"Sum", "Product", "Atan2", "MinMax"})) same(all, true, true);
    if (block_.type() == "ByteUnpack") unpacked_bytes();
    if (block_.type() == "DiscretePid") external_gains();
    if (is({"TransferFunction", "MovingAverage"}) && !input_type(0).shape.empty()) {
      error(input_location(0),
            "size mismatch: " + name_ + " filters one signal, but " + input(0) + " is " + describe(input_type(0)),
            "give it a scalar (a Demux picks elements)");
    }
    if (is({"StateSpace", "KalmanFilter", "StateFeedback", "TransferFunction"})) matrices();
    if (is({"Mux", "MatrixMultiply"})) same(all, true, false);
    if (block_.type() == "Logic") same(all, false, true);
    if (block_.type() == "Relational") {
      same(all, true, false);
      const SignalType& u1 = input_type(0);
      const SignalType& u2 = input_type(1);
      if (!u1.shape.empty() && !u2.shape.empty() && u1.shape != u2.shape) {
        error(input_location(1),
              "size mismatch: " + input(1) + " of " + name_ + " is " + describe(u2) + ", but " + input(0) + " is " +
                  describe(u1),
              "compare inputs of one size, or one of them with a scalar");
      }
    }
    if (block_.type() == "Switch") {
      same({0, 2}, true, true);
      const SignalType& condition = input_type(1);
      if (!condition.shape.empty() && condition.shape != input_type(0).shape) {
        error(input_location(1),
              "size mismatch: " + input(1) + " of " + name_ + " is " + describe(condition) + ", but " + input(0) +
                  " is " + describe(input_type(0)),
              "give one condition, or one per element");
      }
    }
    if (is({"Selector", "Lookup"})) {
      const std::size_t index = block_.type() == "Selector" ? 1 : 0;
      if (!input_type(index).shape.empty()) {
        error(input_location(index),
              "size mismatch: " + input(index) + " of " + name_ + " is " + describe(input_type(index)),
              "a " + block_.type() + " takes one index, a scalar");
      }
    }
    if (block_.type() == "MatrixMultiply" && block_.inputs.size() == 2) {
      const SignalType& a = input_type(0);
      const SignalType& b = input_type(1);
      const std::size_t inner = a.shape.size() == 2 ? a.shape[1] : 1;
      const std::size_t b_rows = b.shape.empty() ? 1 : b.shape[0];
      if (inner != b_rows) {
        error(input_location(1), "size mismatch: " + name_ + " multiplies " + describe(a) + " by " + describe(b),
              "the columns of a must equal the rows of b; a vector is a column");
      }
    }
    if (block_.type() == "GpioOut" && input_type(0) != SignalType{DataType::boolean, {}}) {
      error(input_location(0),
            "type mismatch: " + name_ + " writes a boolean, but " + input(0) + " is " + describe(input_type(0)),
            "compare the value (Compare) or convert it to boolean");
    }
    if (block_.type() == "Demux") {
      const std::size_t elements = input_type(0).elements();
      for (std::size_t k = 0; k < block_.outputs.size(); ++k) {
        if (demux_element(block_.output_ports[k]) < elements) continue;
        error(output_location(k),
              "size mismatch: output '" + block_.output_ports[k] + "' of " + name_ + " is element " +
                  std::to_string(demux_element(block_.output_ports[k]) + 1) + " of " + input(0) + ", which is " +
                  describe(input_type(0)),
              "output yN carries element N: connect y1 to y" + std::to_string(elements) + " only");
        break;
      }
    }
  }

  // A DiscretePid's gain comes from its input or its parameter, and an input gain is of the error's type; its reset
  // is a boolean.
  void external_gains() {
    if (const auto k = input_of(block_, "reset")) {
      const SignalType& reset = input_type(*k);
      if (reset.type != DataType::boolean || (!reset.shape.empty() && reset.shape != input_type(0).shape)) {
        error(input_location(*k),
              "type mismatch: " + input(*k) + " of " + name_ + " is " + describe(reset) + ", but a reset is boolean",
              "give one boolean, or one per element of the error (Compare gives a boolean)");
      }
    }
    for (const char* name : {"p", "i", "d"}) {
      const auto k = input_of(block_, name);
      if (!k) continue;
      if (const Argument* given = block_.argument(name)) {
        error(given->location, name_ + " has both an input '" + name + "' and a parameter '" + name + "'",
              "give the gain one way: the input (external) or the parameter");
      }
      const SignalType& gain = input_type(*k);
      if (gain.type != input_type(0).type || (!gain.shape.empty() && gain.shape != input_type(0).shape)) {
        error(input_location(*k),
              "type mismatch: " + input(*k) + " of " + name_ + " is " + describe(gain) + ", but " + input(0) + " is " +
                  describe(input_type(0)),
              "a gain is one value, or one per element, of the error's type");
      }
    }
  }

  // A ByteUnpack reads bytes that are there.
  void unpacked_bytes() {
    if (input_type(0).type != DataType::uint8) {
      error(input_location(0),
            "type mismatch: " + name_ + " reads bytes, but " + input(0) + " is " + describe(input_type(0)),
            "give it uint8 elements (an SpiDma's, an IpcReceive's)");
      return;
    }
    const auto type = word_type(block_);
    if (!type) return;
    const std::size_t offset = number_argument(block_, "offset", 0);
    const std::size_t count = size_argument(block_, "count");
    const std::size_t needed = offset + count * size_of(*type);
    if (needed > input_type(0).elements()) {
      error(block_.block->location,
            name_ + " reads bytes " + std::to_string(offset) + " to " + std::to_string(needed - 1) + " of " + input(0) +
                ", which has " + std::to_string(input_type(0).elements()),
            "check offset, count and type");
    }
  }

  // The matrices of StateSpace, KalmanFilter and StateFeedback, and a TransferFunction's coefficients, agree.
  void matrices() {
    const auto size = [this](const char* name) { return argument_size(program_, block_, name); };
    const auto has = [this](const char* name) { return block_.argument(name) != nullptr; };
    const auto expect = [&](const char* name, std::size_t rows, std::size_t columns) {
      if (!has(name)) return;
      const ArgumentSize given = size(name);
      if (given.rows == rows && given.columns == columns) return;
      error(block_.argument(name)->location,
            "size mismatch: parameter '" + std::string{name} + "' of " + name_ + " is " + std::to_string(given.rows) +
                "x" + std::to_string(given.columns) + ", but it must be " + std::to_string(rows) + "x" +
                std::to_string(columns),
            "matrices are lists of rows; a vector input is a column");
    };
    const std::size_t inputs = input_type(0).elements();
    if (block_.type() == "TransferFunction") {
      const std::size_t numerator = size("numerator").elements;
      const std::size_t denominator = size("denominator").elements;
      if (denominator < 2 || numerator != denominator) {
        error(block_.argument("denominator")->location,
              name_ + " has " + std::to_string(numerator) + " numerator and " + std::to_string(denominator) +
                  " denominator coefficients",
              "give N+1 of each (order N >= 1, highest power of z first; pad the numerator with leading zeros)");
      }
      const Argument* a0 = block_.argument("denominator");
      if (a0->kind == Argument::Kind::literal && !a0->value.elements.empty() && a0->value.elements[0] == 0) {
        error(a0->location, "the denominator of " + name_ + " starts with 0", "its first coefficient must not be 0");
      }
      return;
    }
    if (block_.type() == "StateFeedback") {
      expect("k", size("k").rows, inputs);
      return;
    }
    const std::size_t states = size("a").rows;
    expect("a", states, states);
    if (block_.type() == "StateSpace") {
      expect("b", states, inputs);
      const std::size_t outputs = size("c").rows;
      expect("c", outputs, states);
      expect("d", outputs, inputs);
      expect("initial", states, 1);
      return;
    }
    expect("c", inputs, states);
    expect("initial", states, 1);
    expect("covariance", states, states);
    if (has("gain")) {
      expect("gain", states, inputs);
      for (const char* unused : {"g", "q", "r"}) {
        if (has(unused)) {
          error(block_.argument(unused)->location,
                name_ + " is given a steady-state gain and '" + std::string{unused} + "'",
                "give either gain (steady state) or g, q and r (time-varying)");
        }
      }
      return;
    }
    if (!has("g") || !has("q") || !has("r")) {
      error(block_.block->location, name_ + " needs g, q and r (time-varying) or gain (steady state)",
            "the thesis' filter: a, c, g, q, r; duet design kalman computes a steady-state gain");
      return;
    }
    const std::size_t noises = size("g").columns;
    expect("g", states, noises);
    expect("q", noises, noises);
    expect("r", inputs, inputs);
  }

  // A Code block's ports are declared: the signals must be what the function takes.
  void code_ports() {
    for (std::size_t k = 0; k < block_.inputs.size(); ++k) {
      for (const Connection& port : block_.block->inputs) {
        if (port.port != block_.input_ports[k]) continue;
        const SignalType declared{port.type.value_or(DataType::float64), port.shape};
        if (input_type(k) == declared) continue;
        error(port.location,
              "type mismatch: input '" + port.port + "' of " + name_ + " is declared " + describe(declared) +
                  " but signal '" + port.signal + "' is " + describe(input_type(k)),
              "declare the port as the signal is, or convert the signal");
      }
    }
    // Its parameters and state declare their types: their values must be values of them.
    for (const auto& [parameter_name, parameter] : block_.block->parameters) {
      if (parameter.literal) {
        declared_value("parameter '" + parameter_name + "'", *parameter.literal,
                       {parameter.type.value_or(DataType::float64), parameter.literal->shape}, parameter.location);
      }
    }
    for (const StateVariable& state : block_.block->code->state) {
      declared_value("state '" + state.name + "'", state.initial, {state.type, state.shape}, state.location);
    }
  }

  // A value given for something of a declared type: a scalar (which fills it) or one value per element.
  void declared_value(const std::string& what, const Value& value, const SignalType& type, Location where) {
    for (const double element : value.elements) {
      if (!fits(element, type.type)) {
        error(where,
              "type mismatch: " + what + " of " + name_ + " is " + shortest_text(element) +
                  ", which is not a value of " + std::string{type_name(type.type)},
              "give a value of " + std::string{type_name(type.type)} + ", or declare another type");
        return;
      }
    }
    if (!value.shape.empty() && value.elements.size() != type.elements()) {
      error(where,
            "size mismatch: " + what + " of " + name_ + " has " + std::to_string(value.elements.size()) +
                " values for " + describe(type),
            "give a scalar, or one value per element");
    }
  }

  // A DeadZone's start is not above its end, element by element (a scalar applies to every element); a tunable
  // parameter's initial values are checked.
  void zone_limits() {
    const Argument* start = block_.argument("start");
    const Argument* end = block_.argument("end");
    if (start == nullptr || end == nullptr) return;
    const std::vector<double>& starts = start->value.elements;
    const std::vector<double>& ends = end->value.elements;
    if (starts.empty() || ends.empty()) return;
    for (std::size_t k = 0; k < std::max(starts.size(), ends.size()); ++k) {
      const double first = starts[std::min(k, starts.size() - 1)];
      const double last = ends[std::min(k, ends.size() - 1)];
      if (first <= last) continue;
      error(start->location,
            "parameter 'start' of " + name_ + " is " + shortest_text(first) + ", above its end, " + shortest_text(last),
            "the dead zone is start..end: give start <= end");
      return;
    }
  }

  // An Interpolation's breakpoints increase strictly, one table value each, and only linear interpolation
  // extrapolates.
  void interpolation_table() {
    const Argument* breakpoints = block_.argument("breakpoints");
    const Argument* table = block_.argument("table");
    const std::vector<double>& at = breakpoints->value.elements;
    if (at.size() < 2) {
      error(breakpoints->location,
            "parameter 'breakpoints' of " + name_ + " has " + std::to_string(at.size()) +
                (at.size() == 1 ? " value" : " values") + ", but it needs at least 2",
            "give two or more breakpoints in increasing order");
      return;
    }
    for (std::size_t k = 1; k < at.size(); ++k) {
      if (at[k] > at[k - 1]) continue;
      error(breakpoints->location,
            "parameter 'breakpoints' of " + name_ + " does not increase strictly: " + shortest_text(at[k]) +
                " follows " + shortest_text(at[k - 1]),
            "each breakpoint must be above the one before");
      return;
    }
    if (table->value.elements.size() != at.size()) {
      error(table->location,
            "size mismatch: parameter 'table' of " + name_ + " has " + std::to_string(table->value.elements.size()) +
                " values for " + std::to_string(at.size()) + " breakpoints",
            "give one table value per breakpoint");
    }
    const Argument* extrapolation = block_.argument("extrapolation");
    const Argument* method = block_.argument("method");
    if (extrapolation != nullptr && extrapolation->text == "linear" && method != nullptr && method->text != "linear") {
      error(extrapolation->location,
            name_ + " extrapolates linearly, but its method is '" + method->text + "', which does not interpolate",
            "give method: linear, or leave out extrapolation (clip)");
    }
  }

  // Why the block's parameters take the type they must: for the hint of a value that does not fit.
  [[nodiscard]] std::string computes_in(DataType expected) const {
    const std::string type{type_name(expected)};
    if (block_.type() == "Counter") return "a Counter counts in its type, " + type + " (uint32 unless given)";
    if (block_.type() == "Constant") return "the Constant's type is " + type;
    if (block_.type() == "Compare") return "a Compare compares in its input's type, " + type;
    return "the block computes in its input's type, " + type;
  }

  // A tunable parameter must be of the block's type and either a scalar or of the signal's size; a literal must be
  // a value of the block's type.
  void parameters() {
    static const std::set<std::string> numeric{
        "k",     "lower", "upper", "gain",  "initial",    "p",         "i",           "d",          "n",
        "value", "limit", "table", "final", "amplitude",  "numerator", "denominator", "a",          "b",
        "c",     "g",     "q",     "r",     "covariance", "start",     "end",         "breakpoints"};
    if (block_.type() == "DeadZone") zone_limits();
    if (block_.type() == "Interpolation") interpolation_table();
    // Blocks whose parameters are matrices (checked by matrices()) or tables, not one value per element.
    const bool elementwise = !is({"StateSpace", "KalmanFilter", "StateFeedback", "TransferFunction", "Interpolation"});
    if (block_.outputs.empty() || block_.type() == "Lookup") return;  // a Lookup's table gives it its type
    const SignalType& working = program_.signals[block_.outputs[0]].type;
    for (const auto& [parameter_name, argument] : block_.arguments) {
      if (numeric.count(parameter_name) == 0 || argument.kind == Argument::Kind::word) continue;
      // A Compare compares in its input's type; every other block computes in its output's.
      const DataType expected = block_.type() == "Compare" ? input_type(0).type : working.type;
      const SignalType on = block_.type() == "Compare" ? input_type(0) : working;
      if (argument.kind == Argument::Kind::parameter) {
        const Parameter& parameter = program_.parameter(argument);
        const SignalType given{parameter.type, parameter.value.shape};
        if (block_.type() == "Constant") {
          if (word_type(block_) && *word_type(block_) != parameter.type) {
            error(argument.location,
                  "type mismatch: parameter '" + parameter.name + "' is " + describe(given) + " but " + name_ +
                      " has type: " + std::string{type_name(*word_type(block_))},
                  "declare '" + parameter.name + "' with type: " + std::string{type_name(*word_type(block_))} +
                      ", or leave out the Constant's type");
          }
        } else if (given.type != expected) {
          error(argument.location,
                "type mismatch: parameter '" + parameter.name + "' is " + describe(given) + " but " + name_ +
                    " computes in " + std::string{type_name(expected)},
                "declare '" + parameter.name + "' with type: " + std::string{type_name(expected)});
        } else if (elementwise && !given.shape.empty() && given.elements() != on.elements()) {
          error(argument.location,
                "size mismatch: parameter '" + parameter.name + "' is " + describe(given) + " but " + name_ +
                    " computes on " + describe(on),
                "give a scalar, or one value per element");
        }
        continue;
      }
      for (const double element : argument.value.elements) {
        if (!fits(element, expected)) {
          error(argument.location,
                "type mismatch: parameter '" + parameter_name + "' of " + name_ + " is " + shortest_text(element) +
                    ", which is not a value of " + std::string{type_name(expected)},
                computes_in(expected) + ": give a value of that type" +
                    (block_.inputs.empty() ? std::string{", or another type"} : ", or convert the input"));
          break;
        }
      }
      if (block_.type() != "Constant" && elementwise && !argument.value.shape.empty() &&
          argument.value.elements.size() != on.elements()) {
        error(argument.location,
              "size mismatch: parameter '" + parameter_name + "' of " + name_ + " has " +
                  std::to_string(argument.value.elements.size()) + " elements but the block computes on " +
                  describe(on),
              "give a scalar, or one value per element");
      }
    }
  }

  const Program& program_;
  const ProgramBlock& block_;
  std::vector<Diagnostic>& diagnostics_;
  std::string name_;
};

}  // namespace

void check_types(const Program& program, const ProgramBlock& block, std::vector<Diagnostic>& diagnostics) {
  BlockCheck{program, block, diagnostics}.run();
}

}  // namespace duet::model
