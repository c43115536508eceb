#include "model_table.hpp"

namespace duet::fmu_export {
namespace {

std::string quoted(const std::string& text) {
  std::string result = "\"";
  for (const char character : text) {
    if (character == '"' || character == '\\') result += '\\';
    result += character;
  }
  return result + "\"";
}

std::string_view role_name(Role role) {
  switch (role) {
    case Role::time: return "time";
    case Role::input: return "input";
    case Role::output: return "output";
    case Role::fixed_parameter: return "fixed_parameter";
    case Role::tunable_parameter: return "tunable_parameter";
    case Role::interrupt_count: return "interrupt_count";
    case Role::local: break;
  }
  return "local";
}

std::string_view type_name(model::DataType type) {
  switch (type) {
    case model::DataType::float64: return "float64";
    case model::DataType::float32: return "float32";
    case model::DataType::int8: return "int8";
    case model::DataType::int16: return "int16";
    case model::DataType::int32: return "int32";
    case model::DataType::uint8: return "uint8";
    case model::DataType::uint16: return "uint16";
    case model::DataType::uint32: return "uint32";
    case model::DataType::boolean: break;
  }
  return "boolean";
}

}  // namespace

std::string model_table_source(const FmuInterface& interface, const std::string& model_name, const std::string& token) {
  const std::string& name = model_name;
  std::string text = "// Written by duet fmu export: the table of " + name + " for the FMU's glue (docs/FMI.md).\n";
  text += "#include <array>\n\n#include \"" + name + ".hpp\"\n#include \"fmu_model.hpp\"\n\nnamespace {\n\n";
  text += "using duet::fmu::Role;\nusing duet::fmu::ValueType;\n\n";
  text += name + "::Instance& as_model(void* storage) { return *static_cast<" + name + "::Instance*>(storage); }\n\n";
  text += "const std::array<duet::fmu::VariableSlot, " + std::to_string(interface.bindings.size()) + "> variables{{\n";
  for (std::size_t k = 0; k < interface.bindings.size(); ++k) {
    const Binding& binding = interface.bindings[k];
    const std::string address =
        binding.member.empty() ? "nullptr"
                               : "[](void* storage) -> void* { return &as_model(storage)." + binding.member + "; }";
    text += "    {" + quoted(interface.description.variables[k].name) +
            ", ValueType::" + std::string{type_name(binding.type)} + ", Role::" + std::string{role_name(binding.role)} +
            ", " + std::to_string(binding.index) + ", " + address + "},\n";
  }
  text += "}};\n\nconst std::array<duet::fmu::ResourceSlot, " + std::to_string(interface.resources.size()) +
          "> resources{{\n";
  for (const Resource& resource : interface.resources) {
    text += "    {" + quoted(resource.name) + ", " + (resource.read ? "true" : "false") + ", " +
            std::to_string(resource.first) + ", " + std::to_string(resource.count) + "},\n";
  }
  text += "}};\n\nconst std::array<const char*, " + std::to_string(interface.interrupts.size()) + "> interrupts{{";
  for (const std::string& interrupt : interface.interrupts) text += quoted(interrupt) + ", ";
  text += "}};\n\nconst std::array<duet::fmu::InterruptTask, " + std::to_string(interface.interrupt_tasks.size()) +
          "> interrupt_tasks{{\n";
  for (const InterruptTask& task : interface.interrupt_tasks)
    text += "    {" + std::to_string(task.counter) + ", " + std::to_string(task.task) + "},\n";
  text += "}};\n\n}  // namespace\n\nnamespace duet::fmu {\n\nconst ModelTable model{\n";
  text += "    .token = " + quoted(token) + ",\n";
  text += "    .base_period_ns = " + name + "::description.base_period_ns,\n";
  text += "    .variables = variables,\n    .resources = resources,\n";
  text += "    .inputs = " + std::to_string(interface.inputs) + ",\n";
  text += "    .outputs = " + std::to_string(interface.outputs) + ",\n";
  text += "    .create = []() -> void* { return new " + name + "::Instance{.parameters = " + name +
          "::reference_parameters, .memory = {}}; },\n";
  text += "    .destroy = [](void* storage) { delete static_cast<" + name + "::Instance*>(storage); },\n";
  text += "    .load_reference_parameters = [](void* storage) { as_model(storage).parameters = " + name +
          "::reference_parameters; },\n";
  text +=
      "    .bind = [](void* storage) { " + name + "::instance = static_cast<" + name + "::Instance*>(storage); },\n";
  text += "    .initialize = " + name + "::initialize,\n    .terminate = " + name + "::terminate,\n";
  text += "    .tasks = " + name + "::tasks,\n";
  text += "    .interrupts = interrupts,\n    .interrupt_tasks = interrupt_tasks,\n};\n\n}  // namespace duet::fmu\n";
  return text;
}

}  // namespace duet::fmu_export
