#include "generator.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <set>

#include "block_semantics.hpp"
#include "duet/blocks/convert.hpp"
#include "duet/model/block_types.hpp"
#include "duet/model/data_type.hpp"
#include "duet/model/interpreter.hpp"
#include "typed.hpp"
#include "user_code.hpp"

namespace duet::model {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

std::string shortest(auto value) {
  char text[48];
  const auto written = std::to_chars(std::begin(text), std::end(text), value);
  std::string result{std::begin(text), written.ptr};
  if (result.find_first_of(".e") == std::string::npos) result += ".0";
  return result;
}

std::string type_of(DataType type) { return std::string{cpp_type(type)}; }

// Vectors up to this size are written element by element, as one would by hand: GCC then keeps their elements in
// registers and drops the ones nothing reads (a loop over a local array keeps the array, every element computed and
// stored: the robot's 7 raw values of which it uses 3, its 4 tuned settings compared through 3 arrays).
constexpr std::size_t written_out_elements = 16;

// Statements over the elements of a signal: one per element with its index for up to written_out_elements, in a loop
// beyond.
std::string for_each(std::size_t count, const std::string& body_with_i) {
  if (count > written_out_elements) {
    return "  for (std::size_t i = 0; i < " + std::to_string(count) + "; ++i) " + body_with_i + "\n";
  }
  std::string text;
  for (std::size_t index = 0; index < count; ++index) {
    std::string body = body_with_i;
    const std::string subscript = "[" + std::to_string(index) + "]";
    for (std::size_t at = body.find("[i]"); at != std::string::npos; at = body.find("[i]", at + subscript.size()))
      body.replace(at, 3, subscript);
    text += "  " + body + "\n";
  }
  return text;
}

// Statements (lines ending in a newline) two spaces further in.
std::string indented(const std::string& statements) {
  std::string text;
  for (std::size_t start = 0; start < statements.size();) {
    const std::size_t end = statements.find('\n', start);
    text += "  " + statements.substr(start, end - start + 1);
    start = end + 1;
  }
  return text;
}

std::string compare_name(blocks::CompareOperator op) {
  constexpr const char* names[] = {"less", "less_equal", "equal", "not_equal", "greater_equal", "greater"};
  return std::string{"duet::blocks::CompareOperator::"} + names[static_cast<int>(op)];
}

std::string interpolation_name(blocks::InterpolationMethod method) {
  constexpr const char* names[] = {"linear", "nearest", "flat", "above"};
  return std::string{"duet::blocks::InterpolationMethod::"} + names[static_cast<int>(method)];
}

std::string extrapolation_name(blocks::Extrapolation extrapolation) {
  return extrapolation == blocks::Extrapolation::linear ? "duet::blocks::Extrapolation::linear"
                                                        : "duet::blocks::Extrapolation::clip";
}

std::string logic_name(blocks::LogicOperator op) {
  constexpr const char* names[] = {"logical_and", "logical_or", "logical_xor", "logical_nand", "logical_nor"};
  return std::string{"duet::blocks::LogicOperator::"} + names[static_cast<int>(op)];
}

bool has_state(const std::string& type) {
  return type == "UnitDelay" || type == "EdgeDetect" || type == "Counter" || type == "DiscreteIntegrator" ||
         type == "DiscreteDerivative" || type == "DiscretePid" || type == "RateTransition" || type == "Step" ||
         type == "PulseGenerator" || type == "FilteredDerivative" || type == "TransferFunction" ||
         type == "StateSpace" || type == "MovingAverage" || type == "KalmanFilter";
}

// The compile-time value of the resource a hardware block names (duet/hardware/resources.hpp), or nothing for a pin
// (a Pin constant of its own), a simulation's plant resource and every other block.
std::string hardware_resource_value(const ProgramBlock& block) {
  const auto text = [&block](const char* name) { return block.argument(name)->text; };
  const auto quoted = [&](const char* name) { return "\"" + text(name) + "\""; };
  const std::string& type = block.type();
  if (type == "PwmOut") return "duet::hardware::pwm(" + quoted("timer") + ", " + text("channel") + ")";
  if (type == "InputCapture") return "duet::hardware::capture(" + quoted("timer") + ", " + text("channel") + ")";
  if (type == "SpiDma" || type == "SpiReceive") return "duet::hardware::spi(" + quoted("spi") + ")";
  if (type == "AdcStart" || type == "AdcDma")
    return "duet::hardware::adc(" + quoted("adc") + ", " + text("channel") + ")";
  if (type == "Exti") return "duet::hardware::exti(" + quoted("line") + ")";
  if (type == "IpcSend" || type == "IpcReceive") return "duet::hardware::ipc(" + quoted("channel") + ")";
  return {};
}

}  // namespace

bool Generator::has_state_member(const ProgramBlock& block) {
  return block.block->code.has_value() || (has_state(block.type()) && !block.outputs.empty());
}

std::vector<Field> lay_out(std::vector<Field> fields, std::size_t& size) {
  std::size_t end = 0;
  std::size_t alignment = 1;
  for (Field& field : fields) {
    const std::size_t align = size_of(field.type);
    alignment = std::max(alignment, align);
    end = (end + align - 1) / align * align;
    field.offset = end;
    end += align * field.count;
  }
  size = fields.empty() ? 1 : (end + alignment - 1) / alignment * alignment;  // C++: an empty struct takes a byte
  return fields;
}

std::string literal(DataType type, double value) {
  return with_type(type, [value, type](auto tag) -> std::string {
    using T = decltype(tag);
    const T converted = blocks::convert<T>(value);
    if constexpr (std::is_same_v<T, bool>) {
      return converted ? "true" : "false";
    } else if constexpr (std::is_floating_point_v<T>) {
      const std::string suffix = std::is_same_v<T, float> ? "F" : "";
      const std::string limits = "std::numeric_limits<" +
                                 type_of(std::is_same_v<T, float> ? DataType::float32 : DataType::float64) +
                                 ">::infinity()";
      if (std::isinf(converted)) return converted < 0 ? "-" + limits : limits;
      return shortest(converted) + suffix;
    } else {
      return type_of(type) + "{" + std::to_string(static_cast<long long>(converted)) + "}";
    }
  });
}

Generator::Generator(const Program& program)
    : program_(program), member_(program.signals.size(), false), inlined_(program.signals.size()) {
  for (std::size_t index = 0; index < program.signals.size(); ++index) {
    const ProgramSignal& signal = program.signals[index];
    const ProgramBlock& driver = program.blocks[signal.driver];
    bool member = signal.measurable || driver.task == at_initialisation || !driver.enables.empty();
    for (const ProgramBlock& block : program.blocks) {
      const bool reads = std::find(block.inputs.begin(), block.inputs.end(), index) != block.inputs.end();
      const bool enabled_by = std::find(block.enables.begin(), block.enables.end(), index) != block.enables.end();
      if ((reads && (block.task != driver.task || block.update_task != driver.task)) ||
          (enabled_by && block.task != driver.task)) {
        member = true;
      }
    }
    member_[index] = member && !signal.parameter;
    // A scalar Constant that is a literal (or a model constant) and that nothing measures is written where it is
    // read, as one would by hand; a block that needs its address (MatrixMultiply, Selector) keeps it in memory.
    const Argument* value = driver.argument("value");
    const bool addressed =
        std::any_of(program.blocks.begin(), program.blocks.end(), [index](const ProgramBlock& block) {
          return (block.type() == "MatrixMultiply" || block.type() == "Selector") &&
                 std::find(block.inputs.begin(), block.inputs.end(), index) != block.inputs.end();
        });
    if (driver.type() == "Constant" && value != nullptr && value->kind == Argument::Kind::literal &&
        value->value.elements.size() == 1 && !signal.measurable && driver.enables.empty() && !addressed) {
      member_[index] = false;
      inlined_[index] = literal(signal.type.type, value->value.elements[0]);
    }
  }
}

std::vector<Field> Generator::signal_fields() const {
  std::vector<Field> fields;
  for (std::size_t index = 0; index < program_.signals.size(); ++index) {
    if (!member_[index]) continue;
    const ProgramSignal& signal = program_.signals[index];
    fields.push_back({signal.identifier, signal.type.type, signal.type.elements(), 0});
  }
  return fields;
}

std::vector<Field> Generator::parameter_fields() const {
  std::vector<Field> fields;
  for (const Parameter& parameter : program_.model->parameters) {
    fields.push_back({parameter.name, parameter.type, parameter.value.elements.size(), 0});
  }
  return fields;
}

std::string Generator::storage(std::size_t signal) const {
  if (inlined_[signal]) return *inlined_[signal];
  const ProgramSignal& info = program_.signals[signal];
  if (info.parameter) return "p." + program_.model->parameters[*info.parameter].name;
  return (member_[signal] ? "signals." : "") + info.identifier;
}

std::string Generator::element(std::size_t signal, const std::string& index) const {
  return storage(signal) + (program_.signals[signal].type.elements() > 1 ? "[" + index + "]" : "");
}

std::string Generator::element(std::size_t signal, std::size_t index) const {
  return element(signal, std::to_string(index));
}

std::string Generator::pointer(std::size_t signal) const {
  return program_.signals[signal].type.elements() > 1 ? storage(signal) : "&" + storage(signal);
}

std::string Generator::argument(const ProgramBlock& block, const std::string& name, double fallback, DataType type,
                                const std::string& index) const {
  const Argument* given = block.argument(name);
  if (given != nullptr && given->kind == Argument::Kind::parameter) {
    const Parameter& parameter = program_.parameter(*given);
    return "p." + parameter.name + (parameter.value.elements.size() > 1 ? "[" + index + "]" : "");
  }
  if (given != nullptr && given->value.elements.size() > 1) return block.identifier + "_" + name + "[" + index + "]";
  return literal(type, given != nullptr && !given->value.elements.empty() ? given->value.elements[0] : fallback);
}

std::string Generator::argument_value(const ProgramBlock& block, const std::string& name, DataType type,
                                      std::size_t index) const {
  const Argument& given = *block.argument(name);
  if (given.kind == Argument::Kind::parameter) {
    const Parameter& parameter = program_.parameter(given);
    return "p." + parameter.name + (parameter.value.elements.size() > 1 ? "[" + std::to_string(index) + "]" : "");
  }
  return literal(type, given.value.elements.empty() ? 0.0 : given.value.elements[index]);
}

std::string Generator::state(const ProgramBlock& block, const std::string& index) const {
  const std::size_t count = block.outputs.empty() ? 1 : program_.signals[block.outputs[0]].type.elements();
  return "state." + block.identifier + (count > 1 && block.type() != "RateTransition" ? "[" + index + "]" : "");
}

std::string Generator::state_members() const {
  std::string text;
  for (const auto& [fast, ratio] : shared_countdowns())
    text += "  std::uint32_t " + shared_countdown(fast, ratio) + ";\n";
  for (const ProgramBlock& block : program_.blocks) {
    if (block.block->code) {
      text += "  code::" + block.identifier + "::State " + block.identifier + ";\n";
      continue;
    }
    if (!has_state(block.type()) || block.outputs.empty()) continue;
    const SignalType& type = program_.signals[block.outputs[0]].type;
    const std::string element_type = type_of(type.type);
    const std::string count = type.elements() > 1 ? "[" + std::to_string(type.elements()) + "]" : "";
    if (block.type() == "RateTransition") {
      const Transfer transfer = transfer_of(program_, block);
      const std::string value = type.elements() > 1
                                    ? "std::array<" + element_type + ", " + std::to_string(type.elements()) + ">"
                                    : element_type;
      const char* kind = transfer.kind == Transfer::Kind::fast_to_slow   ? "FastToSlow"
                         : transfer.kind == Transfer::Kind::slow_to_fast ? "SlowToFast"
                                                                         : "AsyncTransfer";
      text += "  duet::rt::" + std::string{kind} + "<" + value + "> " + block.identifier + ";\n";
      if (transfer.kind != Transfer::Kind::latest && !block.enables.empty()) {
        text += "  std::uint32_t " + block.identifier + "_countdown;\n";
      }
      continue;
    }
    if (block.type() == "EdgeDetect") {  // remembers its input, of the input's type
      const DataType input = program_.signals[block.inputs[0]].type.type;
      text += "  duet::blocks::EdgeDetector<" + type_of(input) + "> " + block.identifier + ";\n";
      continue;
    }
    if (block.type() == "Step" || block.type() == "PulseGenerator") {
      text += "  duet::blocks::StepCounter " + block.identifier + ";\n";
      continue;
    }
    if (const std::string sized = sized_state_type(block); !sized.empty()) {
      text += "  " + sized + " " + block.identifier + ";\n";
      continue;
    }
    text += "  duet::blocks::" + block.type() + "<" + element_type + "> " + block.identifier + count + ";\n";
  }
  return text;
}

std::string Generator::state_resets() const {
  std::string text;
  for (const auto& [fast, ratio] : shared_countdowns()) text += "  state." + shared_countdown(fast, ratio) + " = 0;\n";
  for (const ProgramBlock& block : program_.blocks) {
    if (block.block->code) {
      for (const StateVariable& variable : block.block->code->state) {
        for (std::size_t i = 0; i < variable.initial.elements.size(); ++i) {
          const std::size_t count = variable.initial.elements.size();
          text += "  state." + block.identifier + "." + variable.name +
                  (count > 1 ? "[" + std::to_string(i) + "]" : "") + " = " +
                  literal(variable.type, variable.initial.elements[i]) + ";\n";
        }
      }
      continue;
    }
    if (!has_state(block.type()) || block.outputs.empty()) continue;
    const SignalType& type = program_.signals[block.outputs[0]].type;
    const std::size_t n = type.elements();
    const std::string& kind = block.type();
    if (kind == "RateTransition") {
      std::string initial;
      for (std::size_t i = 0; i < n; ++i) {
        initial += (i == 0 ? "" : ", ") + argument(block, "initial", 0, type.type, std::to_string(i));
      }
      text += "  state." + block.identifier + ".reset(" + (n > 1 ? "{" + initial + "}" : initial) + ");\n";
      if (transfer_of(program_, block).kind != Transfer::Kind::latest && !block.enables.empty()) {
        text += "  state." + block.identifier + "_countdown = 0;\n";
      }
    } else if (kind == "UnitDelay" || kind == "DiscreteIntegrator") {
      text += for_each(n, state(block, "i") + ".state = " + argument(block, "initial", 0, type.type, "i") + ";");
    } else if (kind == "Counter") {
      text += for_each(n, state(block, "i") + ".count = " + argument(block, "initial", 0, type.type, "i") + ";");
    } else if (kind == "EdgeDetect") {
      text +=
          "  " + state(block, "0") + ".previous = " + literal(program_.signals[block.inputs[0]].type.type, 0) + ";\n";
    } else if (kind == "DiscreteDerivative") {
      text += for_each(n, state(block, "i") + ".previous = " + literal(type.type, 0) + ";");
    } else if (kind == "DiscretePid") {
      text += for_each(n, state(block, "i") + " = {" + literal(type.type, 0) + ", " + literal(type.type, 0) + "};");
    } else if (kind == "Step" || kind == "PulseGenerator") {
      text += "  state." + block.identifier + ".k = 0;\n";
    } else if (kind == "FilteredDerivative") {
      text += for_each(n, state(block, "i") + ".filter = " + literal(type.type, 0) + ";");
    } else {
      text += sized_state_reset(block);
    }
  }
  return text;
}

std::string Generator::block_constants() const {
  std::string text;
  for (const ProgramBlock& block : program_.blocks) {
    if (block.type() == "GpioIn" || block.type() == "GpioOut") {
      text += "constexpr duet::hardware::Pin " + block.identifier + "_pin = duet::hardware::pin(\"" +
              block.argument("pin")->text + "\");\n";
    }
    if (const std::string resource = hardware_resource_value(block); !resource.empty()) {
      text += "constexpr auto " + block.identifier + "_resource = " + resource + ";\n";
    }
    const bool matrices = block.type() == "TransferFunction" || block.type() == "StateSpace" ||
                          block.type() == "KalmanFilter" || block.type() == "StateFeedback";
    for (const auto& [name, argument] : block.arguments) {
      if (argument.kind != Argument::Kind::literal || argument.value.elements.empty()) continue;
      if (argument.value.elements.size() < 2 && !(matrices && name != "initial" && name != "covariance")) continue;
      const DataType type = block.type() == "Compare" ? program_.signals[block.inputs[0]].type.type
                            : block.type() == "Lookup" || block.outputs.empty()
                                ? DataType::float64
                                : program_.signals[block.outputs[0]].type.type;
      text += "constexpr " + type_of(type) + " " + block.identifier + "_" + name + "[] = {";
      for (std::size_t i = 0; i < argument.value.elements.size(); ++i) {
        text += (i == 0 ? "" : ", ") + literal(type, argument.value.elements[i]);
      }
      text += "};\n";
    }
  }
  return text;
}

std::string Generator::declare_outputs(const ProgramBlock& block) const {
  std::string text;
  for (const std::size_t signal : block.outputs) {
    if (member_[signal] || program_.signals[signal].parameter || inlined_[signal]) continue;
    const SignalType& type = program_.signals[signal].type;
    text += "  " + type_of(type.type) + " " + program_.signals[signal].identifier +
            (type.elements() > 1 ? "[" + std::to_string(type.elements()) + "]" : "") + "{};\n";
  }
  return text;
}

std::string Generator::guarded(const ProgramBlock& block, std::string statements) const {
  if (block.enables.empty() || statements.empty()) return statements;
  std::string condition;
  for (const std::size_t signal : block.enables) {
    condition +=
        (condition.empty() ? "" : " && ") + std::string{"duet::blocks::convert<bool>("} + element(signal, "0") + ")";
  }
  return "  if (" + condition + ") {\n" + indented(statements) + "  }\n";
}

std::string Generator::output_phase(std::size_t index) const {
  const ProgramBlock& block = program_.blocks[index];
  const std::string statements = output_statements(block);
  std::string text = declare_outputs(block) + guarded(block, statements);
  return text.empty() ? text : "  // " + block.path + " (" + block.type() + ")\n" + text;
}

std::string Generator::update_phase(std::size_t index) const {
  const ProgramBlock& block = program_.blocks[index];
  return guarded(block, update_statements(block));
}

std::string Generator::output_statements(const ProgramBlock& block) const {
  const std::string& type = block.type();
  if (block.block->code) return code_call(block);
  if (block.outputs.empty()) return hardware_output(block);
  if (type == "RateTransition") return rate_transition_output(block);
  if (!hardware_resource(block).empty()) return hardware_output(block);
  const std::size_t y = block.outputs[0];
  const SignalType& out = program_.signals[y].type;
  const std::size_t n = out.elements();
  const DataType t = out.type;
  const auto in = [&](std::size_t k, const std::string& index) { return element(block.inputs[k], index); };
  const auto assign = [&](const std::string& value) { return for_each(n, element(y, "i") + " = " + value + ";"); };
  if (type == "Constant") {
    if (program_.signals[y].parameter || inlined_[y]) return {};  // read where it is used
    return assign(argument(block, "value", 0, t, "i"));
  }
  if (type == "Gain") return assign("duet::blocks::gain(" + in(0, "i") + ", " + argument(block, "k", 1, t, "i") + ")");
  if (type == "Sum" || type == "Product") {
    const std::string signs = sum_signs(block);
    const std::string factors = product_signs(block);
    std::string value = type == "Sum" && signs[0] == '-' ? "duet::blocks::negate(" + in(0, "i") + ")" : in(0, "i");
    if (type == "Product" && factors[0] == '/') value = "duet::blocks::divide(" + literal(t, 1) + ", " + value + ")";
    for (std::size_t k = 1; k < block.inputs.size(); ++k) {
      const char* operation = type == "Product" ? (factors[k] == '/' ? "divide" : "multiply")
                              : signs[k] == '-' ? "subtract"
                                                : "add";
      value = "duet::blocks::" + std::string{operation} + "(" + value + ", " + in(k, "i") + ")";
    }
    return assign(value);
  }
  if (type == "Saturation") {
    return assign("duet::blocks::saturate(" + in(0, "i") + ", " + argument(block, "lower", -infinity, t, "i") + ", " +
                  argument(block, "upper", infinity, t, "i") + ")");
  }
  if (type == "DeadZone") {
    return assign("duet::blocks::dead_zone(" + in(0, "i") + ", " + argument(block, "start", 0, t, "i") + ", " +
                  argument(block, "end", 0, t, "i") + ")");
  }
  if (type == "Interpolation") {
    // Both have two values or more: a tunable parameter's array, or the block's constant array.
    const auto values = [&](const char* name) {
      const Argument& given = *block.argument(name);
      const std::string data = given.kind == Argument::Kind::parameter ? "p." + program_.parameter(given).name
                                                                       : block.identifier + "_" + name;
      return "std::span<const " + type_of(t) + ">{" + data + ", " + std::to_string(given.value.elements.size()) + "}";
    };
    return assign("duet::blocks::interpolate(" + interpolation_name(interpolation_method(block)) + ", " +
                  extrapolation_name(extrapolation_of(block)) + ", " + values("breakpoints") + ", " + values("table") +
                  ", " + in(0, "i") + ")");
  }
  if (type == "Abs") return assign("duet::blocks::absolute(" + in(0, "i") + ")");
  if (type == "Sign") return assign("duet::blocks::sign(" + in(0, "i") + ")");
  if (type == "MinMax") {
    const std::string function = block.argument("function")->text == "max" ? "maximum" : "minimum";
    std::string value = in(0, "i");
    for (std::size_t k = 1; k < block.inputs.size(); ++k) {
      value = "duet::blocks::" + function + "(" + value + ", " + in(k, "i") + ")";
    }
    return assign(value);
  }
  if (type == "Step" || type == "PulseGenerator") return source_output(block);
  if (type == "BytePack" || type == "ByteUnpack") return bytes_output(block);
  if (type == "Mean") {
    const std::size_t count = program_.signals[block.inputs[0]].type.elements();
    return assign("duet::blocks::mean(" + pointer(block.inputs[0]) + ", std::size_t{" + std::to_string(count) + "})");
  }
  if (type == "StateFeedback") {
    const std::size_t nx = program_.signals[block.inputs[0]].type.elements();
    return "  duet::blocks::state_feedback(" + array_argument(block, "k", t) + ", " + pointer(block.inputs[0]) + ", " +
           std::to_string(n) + ", " + std::to_string(nx) + ", " + pointer(y) + ");\n";
  }
  if (type == "TransferFunction" || type == "StateSpace" || type == "MovingAverage" || type == "KalmanFilter") {
    return sized_state_output(block);
  }
  if (type == "Atan2") return assign("duet::blocks::atan2(" + in(0, "i") + ", " + in(1, "i") + ")");
  if (type == "Not") return assign("!duet::blocks::convert<bool>(" + in(0, "i") + ")");
  if (type == "Convert") return assign("duet::blocks::convert<" + type_of(t) + ">(" + in(0, "i") + ")");
  if (type == "Compare") {
    const DataType compared = program_.signals[block.inputs[0]].type.type;
    return assign("duet::blocks::compare(" + compare_name(compare_operator(block)) + ", " + in(0, "i") + ", " +
                  argument(block, "value", 0, compared, "i") + ")");
  }
  if (type == "Relational") {
    return assign("duet::blocks::compare(" + compare_name(compare_operator(block)) + ", " + in(0, "i") + ", " +
                  in(1, "i") + ")");
  }
  if (type == "Logic") {
    std::string inputs;
    for (std::size_t k = 0; k < block.inputs.size(); ++k) {
      inputs += (k == 0 ? "" : ", ") + std::string{"duet::blocks::convert<bool>("} + in(k, "i") + ")";
    }
    return assign("duet::blocks::logic<" + logic_name(logic_operator(block)) + ">(" + inputs + ")");
  }
  if (type == "Switch") {
    return assign("duet::blocks::select(duet::blocks::convert<bool>(" + in(1, "i") + "), " + in(0, "i") + ", " +
                  in(2, "i") + ")");
  }
  if (type == "Mux") {
    std::string text;
    std::size_t at = 0;
    for (std::size_t k = 0; k < block.inputs.size(); ++k) {
      const std::size_t count = program_.signals[block.inputs[k]].type.elements();
      for (std::size_t i = 0; i < count; ++i)
        text += "  " + element(y, at++) + " = " + element(block.inputs[k], i) + ";\n";
    }
    return text;
  }
  if (type == "Demux") {
    std::string text;
    for (std::size_t k = 0; k < block.outputs.size(); ++k) {
      text += "  " + element(block.outputs[k], "0") + " = " +
              element(block.inputs[0], demux_element(block.output_ports[k])) + ";\n";
    }
    return text;
  }
  if (type == "Selector") {
    const std::size_t count = program_.signals[block.inputs[0]].type.elements();
    return assign("duet::blocks::element_at(std::span<const " + type_of(t) + ">{" + pointer(block.inputs[0]) + ", " +
                  std::to_string(count) + "}, " + in(1, "0") + ")");
  }
  if (type == "Lookup") {
    const Argument* table = block.argument("table");
    const std::size_t count = table->value.elements.size();
    std::string data = table->kind == Argument::Kind::parameter ? (count > 1 ? "p." + program_.parameter(*table).name
                                                                             : "&p." + program_.parameter(*table).name)
                                                                : block.identifier + "_table";
    if (table->kind != Argument::Kind::parameter && count == 1) data = "&" + literal(t, table->value.elements[0]);
    return assign("duet::blocks::element_at(std::span<const " + type_of(t) + ">{" + data + ", " +
                  std::to_string(count) + "}, " + in(0, "0") + ")");
  }
  if (type == "MatrixMultiply") {
    const MatrixSizes sizes = matrix_sizes(program_, block);
    return "  duet::blocks::matrix_multiply(" + pointer(block.inputs[0]) + ", " + pointer(block.inputs[1]) + ", " +
           pointer(y) + ", " + std::to_string(sizes.rows) + ", " + std::to_string(sizes.inner) + ", " +
           std::to_string(sizes.columns) + ");\n";
  }
  if (type == "EdgeDetect") {
    constexpr const char* edges[] = {"rising", "falling", "either"};
    return assign(state(block, "0") + ".detect(duet::blocks::Edge::" + edges[static_cast<int>(edge_of(block))] + ", " +
                  in(0, "0") + ")");
  }
  if (type == "UnitDelay" || type == "Counter" || type == "DiscreteIntegrator") {
    return assign(state(block, "i") + ".output()");
  }
  const std::string period = literal(t, block.period_s);
  if (type == "DiscreteDerivative") {
    return assign(state(block, "i") + ".output(" + in(0, "i") + ", " + argument(block, "gain", 1, t, "i") + ", " +
                  period + ")");
  }
  if (type == "FilteredDerivative") {
    return assign(state(block, "i") + ".output(" + in(0, "i") + ", " + argument(block, "gain", 1, t, "i") + ", " +
                  argument(block, "n", pid_default_filter, t, "i") + ")");
  }
  if (type == "DiscretePid") {
    return assign(state(block, "i") + ".output(" + in(0, "i") + ", " + "{" + pid_gain(block, "p", t) + ", " +
                  pid_gain(block, "i", t) + ", " + pid_gain(block, "d", t) + ", " +
                  argument(block, "n", pid_default_filter, t, "i") + ", " +
                  argument(block, "lower", -infinity, t, "i") + ", " + argument(block, "upper", infinity, t, "i") +
                  "}" + pid_reset(block) + ")");
  }
  return "  #error \"duet gen: block type " + type + " is not generated yet\"\n";
}

std::string Generator::update_statements(const ProgramBlock& block) const {
  const std::string& type = block.type();
  if (block.outputs.empty()) return {};  // unconnected: no state member (has_state_member)
  if (type == "RateTransition") return rate_transition_update(block);
  if (!has_state(type)) return {};
  const SignalType& out = program_.signals[block.outputs[0]].type;
  const std::size_t n = out.elements();
  const DataType t = out.type;
  const std::string period = literal(t, block.period_s);
  const auto in = [&](const std::string& index) { return element(block.inputs.at(0), index); };
  if (type == "UnitDelay") return for_each(n, state(block, "i") + ".update(" + in("i") + ");");
  if (type == "Counter")
    return for_each(n, state(block, "i") + ".update(" + argument(block, "limit", 0, t, "i") + ");");
  if (type == "DiscreteIntegrator" && block.argument("lower") == nullptr && block.argument("upper") == nullptr) {
    return for_each(n, state(block, "i") + ".update(" + in("i") + ", " + argument(block, "gain", 1, t, "i") + ", " +
                           period + ");");  // unlimited: saturating at infinity changes nothing
  }
  if (type == "DiscreteIntegrator") {
    return for_each(n, state(block, "i") + ".update(" + in("i") + ", " + argument(block, "gain", 1, t, "i") + ", " +
                           period + ", " + argument(block, "lower", -infinity, t, "i") + ", " +
                           argument(block, "upper", infinity, t, "i") + ");");
  }
  if (type == "DiscreteDerivative") return for_each(n, state(block, "i") + ".update(" + in("i") + ");");
  if (type == "Step" || type == "PulseGenerator") return "  state." + block.identifier + ".update();\n";
  if (type == "FilteredDerivative") {
    return for_each(n, state(block, "i") + ".update(" + in("i") + ", " + argument(block, "gain", 1, t, "i") + ", " +
                           argument(block, "n", pid_default_filter, t, "i") + ", " + period + ");");
  }
  if (type == "TransferFunction" || type == "StateSpace" || type == "MovingAverage" || type == "KalmanFilter") {
    return sized_state_update(block);
  }
  if (type == "DiscretePid") {
    const std::string update = anti_windup_clamping(block) ? ".update_clamped(" : ".update(";
    return for_each(n, state(block, "i") + update + in("i") + ", " + "{" + pid_gain(block, "p", t) + ", " +
                           pid_gain(block, "i", t) + ", " + pid_gain(block, "d", t) + ", " +
                           argument(block, "n", pid_default_filter, t, "i") + ", " +
                           argument(block, "lower", -infinity, t, "i") + ", " +
                           argument(block, "upper", infinity, t, "i") + "}, " + period + pid_reset(block) + ");");
  }
  return {};
}

std::string Generator::pid_gain(const ProgramBlock& block, const std::string& name, DataType type) const {
  if (const auto k = input_of(block, name)) return element(block.inputs[*k], "i");  // an external gain
  return argument(block, name, 0, type, "i");
}

std::string Generator::pid_reset(const ProgramBlock& block) const {
  if (const auto k = input_of(block, "reset")) return ", " + element(block.inputs[*k], "i");
  return {};  // without the argument: the overloads without a reset
}

std::string Generator::source_output(const ProgramBlock& block) const {
  const DataType t = program_.signals[block.outputs[0]].type.type;
  // A boolean source computes in uint8 (Step and PulseGenerator take numbers) and converts.
  const DataType value_type = t == DataType::boolean ? DataType::uint8 : t;
  const SourceSteps steps = source_steps(block);
  const std::string k = "state." + block.identifier + ".output()";
  std::string value;
  if (block.type() == "Step") {
    value = "duet::blocks::step(" + k + ", " + std::to_string(steps.start) + "U, " +
            argument(block, "initial", 0, value_type, "0") + ", " + argument(block, "final", 1, value_type, "0") + ")";
  } else {
    value = "duet::blocks::pulse(" + k + ", " + std::to_string(steps.period) + "U, " + std::to_string(steps.width) +
            "U, " + std::to_string(steps.start) + "U, " + argument(block, "amplitude", 1, value_type, "0") + ")";
  }
  if (t == DataType::boolean) value = "duet::blocks::convert<bool>(" + value + ")";
  return "  " + element(block.outputs[0], "0") + " = " + value + ";\n";
}

std::string Generator::bytes_output(const ProgramBlock& block) const {
  const std::string endian =
      std::string{"duet::blocks::Endian::"} + (endian_of(block) == blocks::Endian::big ? "big" : "little");
  const std::size_t y = block.outputs[0];
  std::string text;
  if (block.type() == "BytePack") {
    std::size_t at = 0;
    for (const std::size_t signal : block.inputs) {
      const SignalType& type = program_.signals[signal].type;
      for (std::size_t i = 0; i < type.elements(); ++i) {
        text += "  duet::blocks::pack(" + element(signal, i) + ", " + endian + ", &" + element(y, at) + ");\n";
        at += size_of(type.type);
      }
    }
    return text;
  }
  const SignalType& out = program_.signals[y].type;
  const std::size_t offset = unpack_offset(block);
  for (std::size_t i = 0; i < out.elements(); ++i) {
    text += "  " + element(y, i) + " = duet::blocks::unpack<" + type_of(out.type) + ">(&" +
            element(block.inputs[0], offset + i * size_of(out.type)) + ", " + endian + ");\n";
  }
  return text;
}

std::string Generator::array_argument(const ProgramBlock& block, const std::string& name, DataType type) const {
  const Argument* given = block.argument(name);
  if (given->kind == Argument::Kind::parameter) {
    const Parameter& parameter = program_.parameter(*given);
    return (parameter.value.elements.size() > 1 ? "p." : "&p.") + parameter.name;
  }
  (void)type;  // block_constants() declares it in the block's type
  return block.identifier + "_" + name;
}

std::string Generator::sized_state_type(const ProgramBlock& block) const {
  if (block.inputs.empty()) return {};  // the sized blocks all have an input
  const SignalType& out = program_.signals[block.outputs[0]].type;
  const std::string t = type_of(out.type);
  const std::string& type = block.type();
  const std::size_t inputs = program_.signals[block.inputs[0]].type.elements();
  if (type == "TransferFunction") {
    return "duet::blocks::DiscreteTransferFunction<" + t + ", " +
           std::to_string(argument_size(program_, block, "denominator").elements - 1) + ">";
  }
  if (type == "StateSpace") {
    return "duet::blocks::DiscreteStateSpace<" + t + ", " + std::to_string(argument_size(program_, block, "a").rows) +
           ", " + std::to_string(inputs) + ", " + std::to_string(out.elements()) + ">";
  }
  if (type == "MovingAverage") {
    return "duet::blocks::MovingAverage<" + t + ", " + std::to_string(block_window(block)) + ">";
  }
  if (type == "KalmanFilter") {
    const std::string states = std::to_string(argument_size(program_, block, "a").rows);
    if (block.argument("gain") != nullptr) {
      return "duet::blocks::SteadyStateKalmanFilter<" + t + ", " + states + ", " + std::to_string(inputs) + ">";
    }
    return "duet::blocks::KalmanFilter<" + t + ", " + states + ", " + std::to_string(inputs) + ", " +
           std::to_string(argument_size(program_, block, "g").columns) + ">";
  }
  return {};
}

std::string Generator::sized_state_reset(const ProgramBlock& block) const {
  const std::string& type = block.type();
  const DataType t = program_.signals[block.outputs[0]].type.type;
  const std::string name = "state." + block.identifier;
  std::string text = "  " + name + " = {};\n";
  const auto fill = [&](const std::string& member, std::size_t count, const char* parameter, double fallback) {
    const bool given = block.argument(parameter) != nullptr;
    const bool scalar = given && argument_size(program_, block, parameter).elements == 1;
    for (std::size_t i = 0; i < count; ++i) {
      text += "  " + name + "." + member + "[" + std::to_string(i) +
              "] = " + argument(block, parameter, fallback, t, scalar || !given ? "0" : std::to_string(i)) + ";\n";
    }
  };
  if (type == "StateSpace" || type == "KalmanFilter") fill("x", argument_size(program_, block, "a").rows, "initial", 0);
  if (type == "MovingAverage") fill("window", block_window(block), "initial", 0);
  if (type == "KalmanFilter" && block.argument("gain") == nullptr) {
    const std::size_t states = argument_size(program_, block, "a").rows;
    if (block.argument("covariance") != nullptr) {
      fill("p", states * states, "covariance", 0);
    } else {  // the identity
      for (std::size_t i = 0; i < states; ++i) {
        text += "  " + name + ".p[" + std::to_string(i * states + i) + "] = " + literal(t, 1) + ";\n";
      }
    }
  }
  return text;
}

std::string Generator::sized_state_output(const ProgramBlock& block) const {
  const std::string& type = block.type();
  const DataType t = program_.signals[block.outputs[0]].type.type;
  const std::size_t y = block.outputs[0];
  const std::string name = "state." + block.identifier;
  const std::string u = pointer(block.inputs[0]);
  if (type == "TransferFunction") {
    return "  " + element(y, "0") + " = " + name + ".output(" + element(block.inputs[0], "0") + ", " +
           array_argument(block, "numerator", t) + ", " + array_argument(block, "denominator", t) + ");\n";
  }
  if (type == "StateSpace") {
    return "  " + name + ".output(" + u + ", " + array_argument(block, "c", t) + ", " + array_argument(block, "d", t) +
           ", " + pointer(y) + ");\n";
  }
  if (type == "MovingAverage") {
    return "  " + element(y, "0") + " = " + name + ".output(" + element(block.inputs[0], "0") + ");\n";
  }
  if (block.argument("gain") != nullptr) {
    return "  " + name + ".output(" + u + ", " + array_argument(block, "c", t) + ", " +
           array_argument(block, "gain", t) + ", " + pointer(y) + ");\n";
  }
  return "  " + name + ".output(" + u + ", " + array_argument(block, "c", t) + ", " + array_argument(block, "r", t) +
         ", " + pointer(y) + ");\n";
}

std::string Generator::sized_state_update(const ProgramBlock& block) const {
  const std::string& type = block.type();
  const DataType t = program_.signals[block.outputs[0]].type.type;
  const std::string name = "state." + block.identifier;
  const std::string u = pointer(block.inputs[0]);
  if (type == "TransferFunction") {
    return "  " + name + ".update(" + element(block.inputs[0], "0") + ", " + array_argument(block, "numerator", t) +
           ", " + array_argument(block, "denominator", t) + ");\n";
  }
  if (type == "StateSpace") {
    return "  " + name + ".update(" + u + ", " + array_argument(block, "a", t) + ", " + array_argument(block, "b", t) +
           ");\n";
  }
  if (type == "MovingAverage") return "  " + name + ".update(" + element(block.inputs[0], "0") + ");\n";
  if (block.argument("gain") != nullptr) {
    return "  " + name + ".update(" + u + ", " + array_argument(block, "a", t) + ", " + array_argument(block, "c", t) +
           ", " + array_argument(block, "gain", t) + ");\n";
  }
  return "  " + name + ".update(" + u + ", " + array_argument(block, "a", t) + ", " + array_argument(block, "c", t) +
         ", " + array_argument(block, "g", t) + ", " + array_argument(block, "q", t) + ");\n";
}

// A Code block: its inputs and parameters copied into its structures, the function called with them and its state,
// its outputs copied out; the interpreter moves the same bytes.
std::string Generator::code_call(const ProgramBlock& block) const {
  const std::string space = "code::" + block.identifier + "::";
  std::string text = "  {\n    " + space + "Inputs block_inputs{};\n";
  const auto copy = [](const std::string& to, const std::string& from, std::size_t count) {
    if (count == 1) return "    " + to + " = " + from + ";\n";
    return "    for (std::size_t i = 0; i < " + std::to_string(count) + "; ++i) " + to + "[i] = " + from + "[i];\n";
  };
  for (std::size_t k = 0; k < block.inputs.size(); ++k) {
    const std::size_t count = program_.signals[block.inputs[k]].type.elements();
    text += copy("block_inputs." + block.input_ports[k], storage(block.inputs[k]), count);
  }
  text += "    " + space + "Outputs block_outputs{};\n    " + space + "Parameters block_parameters{};\n";
  for (const auto& [name, argument] : block.arguments) {
    const std::size_t count = std::max<std::size_t>(1, argument.value.elements.size());
    const DataType type = code_parameter_type(program_, block, name);
    for (std::size_t i = 0; i < count; ++i) {
      const std::string index = std::to_string(i);
      text += "    block_parameters." + name + (count > 1 ? "[" + index + "]" : "") + " = " +
              argument_value(block, name, type, i) + ";\n";
    }
  }
  text += "    " + block.block->code->function + "(block_inputs, block_outputs, state." + block.identifier +
          ", block_parameters);\n";
  for (std::size_t k = 0; k < block.outputs.size(); ++k) {
    const std::size_t count = program_.signals[block.outputs[k]].type.elements();
    text += copy(storage(block.outputs[k]), "block_outputs." + block.output_ports[k], count);
  }
  return text + "  }\n";
}

// Hardware blocks: each kind through its typed call in the port (duet/hardware/hardware.hpp), with the resource a
// compile-time template argument (block_constants), and values in the kind's own type: bytes, sample counts, a float
// duty. A signal of another type is converted into a local of the kind's type first. PlantInput and PlantOutput,
// which exist for simulation, go to the plant by name as doubles.
std::string Generator::hardware_output(const ProgramBlock& block) const {
  const std::string& type = block.type();
  if (hardware_resource(block).empty()) return {};  // a block with its outputs unconnected
  if (type == "GpioOut") {
    return "  duet::hardware::gpio_write(" + block.identifier + "_pin, " + element(block.inputs[0], "0") + ");\n";
  }
  if (type == "GpioIn") {
    return "  " + element(block.outputs[0], "0") + " = duet::hardware::gpio_read(" + block.identifier + "_pin);\n";
  }
  if (is_plant_resource(type)) return plant_resource_access(block);
  const std::string resource = "<" + block.identifier + "_resource>";
  if (type == "AdcStart") {
    const auto count = static_cast<long long>(block.argument("count")->value.elements.at(0));
    return "  duet::hardware::adc_start" + resource + "(std::uint16_t{" + std::to_string(count) + "});\n";
  }
  if (type == "PwmOut") {
    return "  duet::hardware::pwm_write" + resource + "(" + converted(block.inputs[0], 0, DataType::float32) + ");\n";
  }
  if (type == "InputCapture") {
    std::string text =
        "  {\n    const duet::hardware::CaptureReading reading = duet::hardware::capture_read" + resource + "();\n";
    for (std::size_t k = 0; k < block.outputs.size(); ++k) {
      text += "    " + element(block.outputs[k], "0") + " = reading." +
              (block.output_ports[k] == "edge" ? "rising" : "count") + ";\n";
    }
    return text + "  }\n";
  }
  if (type == "Exti")
    return "  " + element(block.outputs[0], "0") + " = duet::hardware::exti_level" + resource + "();\n";
  const bool sends = type == "SpiDma" || type == "IpcSend";
  std::string text = "  {\n";
  if (sends && !block.inputs.empty()) {
    text += "    const std::uint8_t written[] = {" + every_element(block.inputs, DataType::uint8) +
            "};\n    duet::hardware::" + (type == "SpiDma" ? "spi_transfer" : "ipc_send") + resource + "(written);\n";
  }
  if (!block.outputs.empty()) {
    const std::size_t signal = block.outputs[0];  // bytes (SpiDma, SpiReceive, IpcReceive) or samples (AdcDma)
    const char* call = type == "AdcDma" ? "adc_samples" : type == "IpcReceive" ? "ipc_receive" : "spi_received";
    text += "    duet::hardware::" + std::string{call} + resource + "({" + pointer(signal) + ", " +
            std::to_string(program_.signals[signal].type.elements()) + "});\n";
  }
  return text + "  }\n";
}

// A signal's element as `type`: as it is if it has that type already.
std::string Generator::converted(std::size_t signal, std::size_t index, DataType type) const {
  if (program_.signals[signal].type.type == type) return element(signal, index);
  return "duet::blocks::convert<" + type_of(type) + ">(" + element(signal, index) + ")";
}

// Every element of the signals in turn, each as `type`, separated by commas: an array's initializer.
std::string Generator::every_element(const std::vector<std::size_t>& signals, DataType type) const {
  std::string text;
  for (const std::size_t signal : signals) {
    for (std::size_t i = 0; i < program_.signals[signal].type.elements(); ++i) {
      text += (text.empty() ? "" : ", ") + converted(signal, i, type);
    }
  }
  return text;
}

// PlantInput, PlantOutput, Inport and Outport: the plant's resource by name, values as doubles (the PC's port only).
std::string Generator::plant_resource_access(const ProgramBlock& block) const {
  const std::string resource = "\"" + hardware_resource(block) + "\"";
  std::string text = "  {\n";
  if (!block.inputs.empty()) {
    text += "    const double written[] = {" + every_element(block.inputs, DataType::float64) +
            "};\n    duet::hardware::write(" + resource + ", written);\n";
  }
  if (!block.outputs.empty()) {
    const std::size_t signal = block.outputs[0];
    text += "    duet::hardware::read(" + resource + ", {" + pointer(signal) + ", " +
            std::to_string(program_.signals[signal].type.elements()) + "});\n";
  }
  return text + "  }\n";
}

// Whether the slower rate releases in this activation of the faster task: the task's shared countdown (the name of
// its flag), or, inside an enabled subsystem where activations can be skipped, the block's own. The interpreter keeps
// one countdown per block; both count the activations in which the transition runs, so they release alike.
std::string Generator::release_flag(const ProgramBlock& block, std::string& statements) const {
  const Transfer transfer = transfer_of(program_, block);
  const std::size_t fast = transfer.kind == Transfer::Kind::fast_to_slow ? block.update_task : block.task;
  if (block.enables.empty()) return shared_countdown(fast, transfer.ratio);
  const std::string member = "state." + block.identifier;
  statements += "  const bool " + block.identifier + "_release = " + member + "_countdown == 0;\n";
  statements += "  " + member + "_countdown = " + block.identifier + "_release ? " +
                std::to_string(transfer.ratio - 1) + "U : " + member + "_countdown - 1U;\n";
  return block.identifier + "_release";
}

std::string Generator::shared_countdown(std::size_t task, std::uint32_t ratio) {
  return "release_" + std::to_string(task) + "_every_" + std::to_string(ratio);
}

std::vector<std::pair<std::size_t, std::uint32_t>> Generator::shared_countdowns() const {
  std::vector<std::pair<std::size_t, std::uint32_t>> countdowns;
  for (const ProgramBlock& block : program_.blocks) {
    if (block.type() != "RateTransition" || !block.enables.empty()) continue;
    const Transfer transfer = transfer_of(program_, block);
    if (transfer.kind == Transfer::Kind::latest) continue;
    const std::size_t fast = transfer.kind == Transfer::Kind::fast_to_slow ? block.update_task : block.task;
    if (std::find(countdowns.begin(), countdowns.end(), std::pair{fast, transfer.ratio}) == countdowns.end()) {
      countdowns.emplace_back(fast, transfer.ratio);
    }
  }
  return countdowns;
}

std::string Generator::task_prologue(std::size_t task) const {
  std::string text;
  for (const auto& [fast, ratio] : shared_countdowns()) {
    if (fast != task) continue;
    const std::string name = shared_countdown(fast, ratio);
    text += "  const bool " + name + " = state." + name + " == 0;  // the rate " + std::to_string(ratio) +
            " times slower releases now\n";
  }
  return text;
}

std::string Generator::task_epilogue(std::size_t task) const {
  std::string text;
  for (const auto& [fast, ratio] : shared_countdowns()) {
    if (fast != task) continue;
    const std::string name = shared_countdown(fast, ratio);
    text += "  state." + name + " = " + name + " ? " + std::to_string(ratio - 1) + "U : state." + name + " - 1U;\n";
  }
  return text;
}

std::string Generator::rate_transition_output(const ProgramBlock& block) const {
  const Transfer transfer = transfer_of(program_, block);
  const std::size_t y = block.outputs[0];
  const std::size_t n = program_.signals[y].type.elements();
  const std::string member = "state." + block.identifier;
  std::string text;
  const std::string read = transfer.kind == Transfer::Kind::slow_to_fast
                               ? member + ".read(" + release_flag(block, text) + ")"
                               : member + ".read()";
  if (n == 1) return text + "  " + element(y, "0") + " = " + read + ";\n";
  return text + "  {\n    const auto& value = " + read + ";\n" +
         indented(for_each(n, element(y, "i") + " = value[i];")) + "  }\n";
}

std::string Generator::rate_transition_update(const ProgramBlock& block) const {
  const Transfer transfer = transfer_of(program_, block);
  const std::size_t u = block.inputs.at(0);
  const std::size_t n = program_.signals[u].type.elements();
  const std::string member = "state." + block.identifier;
  std::string value = element(u, "0");
  if (n > 1) {
    value = "std::array<" + type_of(program_.signals[u].type.type) + ", " + std::to_string(n) + ">{";
    for (std::size_t i = 0; i < n; ++i) value += (i == 0 ? "" : ", ") + element(u, i);
    value += "}";
  }
  if (transfer.kind == Transfer::Kind::fast_to_slow) {
    std::string text;
    const std::string release = release_flag(block, text);
    return text + "  " + member + ".write(" + value + ", " + release + ");\n";
  }
  return "  " + member + ".write(" + value + ");\n";
}

}  // namespace duet::model
