#include "user_code.hpp"

#include "duet/model/data_type.hpp"

namespace duet::model {
namespace {

std::string members(const std::vector<Field>& fields) {
  std::string text;
  for (const Field& field : fields) {
    text += "  " + std::string{cpp_type(field.type)} + " " + field.name +
            (field.count > 1 ? "[" + std::to_string(field.count) + "]" : "") + ";\n";
  }
  return text;
}

std::size_t count_of(const std::vector<std::size_t>& shape) {
  std::size_t count = 1;
  for (const std::size_t dimension : shape) count *= dimension;
  return count;
}

}  // namespace

DataType code_parameter_type(const Program& program, const ProgramBlock& block, const std::string& name) {
  for (const auto& [parameter_name, parameter] : block.block->parameters) {
    if (parameter_name != name) continue;
    if (parameter.type) return *parameter.type;
    const Argument* argument = block.argument(name);
    if (argument != nullptr && argument->kind == Argument::Kind::parameter) return program.parameter(*argument).type;
  }
  return DataType::float64;
}

CodeInterface code_interface(const Program& program, const ProgramBlock& block) {
  CodeInterface interface;
  std::vector<Field> inputs;
  for (const Connection& port : block.block->inputs) {
    inputs.push_back({port.port, port.type.value_or(DataType::float64), count_of(port.shape), 0});
  }
  std::vector<Field> outputs;
  for (const Connection& port : block.block->outputs) {
    outputs.push_back({port.port, port.type.value_or(DataType::float64), count_of(port.shape), 0});
  }
  std::vector<Field> state;
  for (const StateVariable& variable : block.block->code->state) {
    state.push_back({variable.name, variable.type, count_of(variable.shape), 0});
  }
  std::vector<Field> parameters;
  for (const auto& [name, argument] : block.arguments) {
    parameters.push_back(
        {name, code_parameter_type(program, block, name), std::max<std::size_t>(1, argument.value.elements.size()), 0});
  }
  interface.inputs = lay_out(inputs, interface.inputs_size);
  interface.outputs = lay_out(outputs, interface.outputs_size);
  interface.state = lay_out(state, interface.state_size);
  interface.parameters = lay_out(parameters, interface.parameters_size);
  return interface;
}

std::string code_structures(const Program& program, const ProgramBlock& block) {
  const CodeInterface interface = code_interface(program, block);
  return "namespace code::" + block.identifier + " {\n// The structures of Code block '" + block.path + "'.\n" +
         "struct Inputs {\n" + members(interface.inputs) + "};\nstruct Outputs {\n" + members(interface.outputs) +
         "};\nstruct State {\n" + members(interface.state) + "};\nstruct Parameters {\n" +
         members(interface.parameters) + "};\n}  // namespace code::" + block.identifier + "\n";
}

}  // namespace duet::model
