#include "typing.hpp"

#include <algorithm>
#include <set>

#include "duet/model/data_type.hpp"

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
  static const std::map<std::string, DataType> names{
      {"double", DataType::float64}, {"single", DataType::float32}, {"int8", DataType::int8},
      {"int16", DataType::int16},    {"int32", DataType::int32},    {"uint8", DataType::uint8},
      {"uint16", DataType::uint16},  {"uint32", DataType::uint32},  {"boolean", DataType::boolean}};
  const Argument* type = block.argument("type");
  if (type == nullptr) return std::nullopt;
  const auto found = names.find(type->text);
  return found == names.end() ? std::nullopt : std::optional{found->second};
}

std::size_t size_argument(const ProgramBlock& block, const char* name) {
  const Argument* argument = block.argument(name);
  if (argument == nullptr || argument->value.elements.empty()) return 1;
  return static_cast<std::size_t>(std::max(1.0, argument->value.elements.front()));
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
  const auto shape_of = [guess_scalars](const std::optional<SignalType>& input) -> std::optional<std::vector<std::size_t>> {
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
  } else if (type == "Not" || type == "Compare") {
    y = boolean_like(first_known(inputs, {0}));
  } else if (type == "Logic") {
    y = boolean_like(first_known(inputs));
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
  } else if (type == "GpioIn") {
    y = SignalType{DataType::boolean, {}};
  } else if (type == "Exti") {
    y = SignalType{DataType::boolean, {}};
  } else if (type == "InputCapture") {
    outputs[0] = SignalType{DataType::uint32, {}};
    if (outputs.size() > 1) outputs[1] = SignalType{DataType::boolean, {}};
  } else if (type == "SpiDma" || type == "IpcReceive") {
    y = SignalType{DataType::uint8, {size_argument(block, "size")}};
  } else if (type == "AdcDma") {
    y = SignalType{DataType::uint16, {size_argument(block, "count")}};
  } else {  // Gain, Sum, Product, Abs, Saturation, Atan2, delays, integrators, PID, RateTransition: as their inputs
    y = first_known(inputs);
  }
  // Demux and InputCapture name outputs by port: keep each output's type on the port it belongs to.
  if (type == "InputCapture") {
    for (std::size_t k = 0; k < outputs.size(); ++k) {
      outputs[k] = block.output_ports[k] == "edge" ? SignalType{DataType::boolean, {}} : SignalType{DataType::uint32, {}};
    }
  }
  return outputs;
}

void check_types(const Program& program, const ProgramBlock& block, std::vector<Diagnostic>& diagnostics) {
  const std::string& type = block.type();
  const auto input_type = [&](std::size_t k) { return program.signals[block.inputs[k]].type; };
  const auto error = [&](Location where, const std::string& message, const std::string& hint) {
    diagnostics.push_back({Diagnostic::Severity::error, where, message, hint});
  };
  const std::string name = "block '" + block.path + "' (" + type + ")";
  const auto input_location = [&](std::size_t k) {
    for (const Connection& connection : block.block->inputs) {
      if (connection.port == block.input_ports[k]) return connection.location;
    }
    return block.block->location;
  };
  // Inputs that must agree with each other.
  const auto same = [&](std::initializer_list<std::size_t> ports, bool shapes) {
    std::optional<std::size_t> first;
    for (const std::size_t k : ports) {
      if (k >= block.inputs.size()) continue;
      if (!first) {
        first = k;
        continue;
      }
      const SignalType a = input_type(*first);
      const SignalType b = input_type(k);
      if (a.type != b.type || (shapes && a.shape != b.shape)) {
        const bool sizes = a.type == b.type;
        error(input_location(k),
              std::string{sizes ? "size" : "type"} + " mismatch: input '" + block.input_ports[k] + "' of " + name +
                  " is " + describe(b) + ", input '" + block.input_ports[*first] + "' is " + describe(a),
              sizes ? "the inputs of this block have one size" : "convert one of them with a Convert block");
        return;
      }
    }
  };
  std::vector<std::size_t> all(block.inputs.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
  const auto same_all = [&](bool shapes) {
    std::optional<std::size_t> first;
    for (const std::size_t k : all) {
      if (!first) {
        first = k;
      } else if (input_type(*first).type != input_type(k).type ||
                 (shapes && input_type(*first).shape != input_type(k).shape)) {
        same({*first, k}, shapes);
        return;
      }
    }
  };
  const bool floating_only = type == "DiscreteIntegrator" || type == "DiscreteDerivative" || type == "DiscretePid" ||
                             type == "Atan2" || type == "PwmOut";
  if (floating_only && !block.inputs.empty() && !is_floating(input_type(0).type)) {
    error(input_location(0),
          "type mismatch: " + name + " computes in floating point, but input '" + block.input_ports[0] + "' is " +
              describe(input_type(0)),
          "convert it to single or double with a Convert block");
  }
  if ((type == "Abs" || type == "Gain" || type == "Sum" || type == "Product") && !block.inputs.empty() &&
      input_type(0).type == DataType::boolean) {
    error(input_location(0), "type mismatch: " + name + " does arithmetic, but its input is boolean",
          "convert it to a number with a Convert block");
  }
  if (type == "Sum" || type == "Product" || type == "RateTransition") same_all(true);
  if (type == "Mux" || type == "MatrixMultiply") same_all(false);
  if (type == "Switch") same({0, 2}, true);
  if (type == "Atan2") same({0, 1}, true);
  if (type == "MatrixMultiply" && block.inputs.size() == 2) {
    const SignalType a = input_type(0);
    const SignalType b = input_type(1);
    const std::size_t inner = a.shape.size() == 2 ? a.shape[1] : 1;
    const std::size_t b_rows = b.shape.empty() ? 1 : b.shape[0];
    if (inner != b_rows) {
      error(input_location(1), "size mismatch: " + name + " multiplies " + describe(a) + " by " + describe(b),
            "the columns of a must equal the rows of b");
    }
  }
  if (type == "GpioOut" && !block.inputs.empty() && input_type(0) != SignalType{DataType::boolean, {}}) {
    error(input_location(0), "type mismatch: " + name + " writes a boolean, but its input is " + describe(input_type(0)),
          "compare the value (Compare) or convert it to boolean");
  }
  if (type == "Demux" && !block.inputs.empty() && block.outputs.size() > input_type(0).elements()) {
    error(block.block->location,
          "size mismatch: " + name + " has " + std::to_string(block.outputs.size()) + " outputs but its input has " +
              std::to_string(input_type(0).elements()) + " elements",
          "connect at most one output per element");
  }
  // A Code block's inputs are declared: the signals must be what the function takes.
  if (block.block->code) {
    for (std::size_t k = 0; k < block.inputs.size(); ++k) {
      const Connection& port = block.block->inputs[k];
      const SignalType declared{port.type.value_or(DataType::float64), port.shape};
      if (input_type(k) != declared) {
        error(port.location,
              "type mismatch: input '" + port.port + "' of " + name + " is declared " + describe(declared) +
                  " but signal '" + port.signal + "' is " + describe(input_type(k)),
              "declare the port as the signal is, or convert the signal");
      }
    }
  }
  // Parameters: a tunable one must be of the block's type and either a scalar or of the input's size; a literal
  // must be a value of the block's type.
  static const std::set<std::string> numeric{"k",     "lower", "upper", "gain",  "initial", "p",    "i",
                                             "d",     "n",     "value", "limit", "table"};
  if (block.block->code || type == "Constant" || block.outputs.empty()) return;
  const SignalType working = program.signals[block.outputs[0]].type;
  for (const auto& [parameter_name, argument] : block.arguments) {
    if (numeric.count(parameter_name) == 0 || argument.kind == Argument::Kind::word) continue;
    if (type == "Lookup") continue;  // the table gives the output its type
    // A Compare compares in its input's type; every other block computes in its output's.
    const DataType expected = type == "Compare" && !block.inputs.empty() ? input_type(0).type : working.type;
    if (argument.kind == Argument::Kind::parameter) {
      const Parameter& parameter = program.parameter(argument);
      const SignalType given{parameter.type, parameter.value.shape};
      if (given.type != expected) {
        error(argument.location,
              "type mismatch: parameter '" + parameter.name + "' is " + describe(given) + " but " + name +
                  " computes in " + std::string{type_name(expected)},
              "declare '" + parameter.name + "' with type: " + std::string{type_name(expected)});
      } else if (!given.shape.empty() && given.elements() != working.elements()) {
        error(argument.location,
              "size mismatch: parameter '" + parameter.name + "' is " + describe(given) + " but " + name +
                  " computes on " + describe(working),
              "give a scalar, or one value per element");
      }
      continue;
    }
    for (const double element : argument.value.elements) {
      if (!fits(element, expected)) {
        error(argument.location,
              "type mismatch: " + format_number(element) + " (parameter '" + parameter_name + "' of " + name +
                  ") is not a value of " + std::string{type_name(expected)},
              "the block computes in its input's type");
        break;
      }
    }
    if (!argument.value.shape.empty() && argument.value.elements.size() != working.elements()) {
      error(argument.location,
            "size mismatch: parameter '" + parameter_name + "' of " + name + " has " +
                std::to_string(argument.value.elements.size()) + " elements but the block computes on " +
                describe(working),
            "give a scalar, or one value per element");
    }
  }
}

}  // namespace duet::model
