#include "duet/studio/library.hpp"

#include "duet/model/block_documentation.hpp"
#include "duet/model/block_types.hpp"

namespace duet::studio {

using nlohmann::json;

namespace {

json names(const std::vector<std::string_view>& list) {
  json result = json::array();
  for (std::string_view name : list) result.push_back(name);
  return result;
}

json parameter_json(const model::ParameterSpec& spec, const model::ParameterDocumentation* documentation) {
  using Kind = model::ParameterDocumentation::Kind;
  json entry = {{"name", spec.name}, {"required", spec.required},
                {"kind", "number"},  {"choices", json::array()},
                {"min", nullptr},    {"max", nullptr},
                {"integer", false},  {"description", ""}};
  if (documentation == nullptr) return entry;
  entry["kind"] = documentation->kind == Kind::number ? "number"
                  : documentation->kind == Kind::word ? "word"
                                                      : "data_type";
  for (std::string_view choice : documentation->choices) entry["choices"].push_back(choice);
  if (documentation->minimum) entry["min"] = *documentation->minimum;
  if (documentation->maximum) entry["max"] = *documentation->maximum;
  entry["integer"] = documentation->integer;
  entry["description"] = documentation->description;
  return entry;
}

}  // namespace

json library_json() {
  json library = json::array();
  for (const model::BlockType& type : model::block_types()) {
    const model::BlockDocumentation* documentation = model::find_block_documentation(type.name);
    json parameters = json::array();
    for (const model::ParameterSpec& spec : type.parameters) {
      parameters.push_back(parameter_json(
          spec, documentation != nullptr ? model::find_parameter_documentation(*documentation, spec.name) : nullptr));
    }
    library.push_back({{"type", type.name},
                       {"summary", documentation != nullptr ? documentation->summary : ""},
                       {"category", documentation != nullptr ? documentation->category : ""},
                       {"inputs", names(type.inputs)},
                       {"outputs", names(type.outputs)},
                       {"variadic_inputs", type.variadic_inputs},
                       {"optional_inputs", names(type.optional_inputs)},
                       {"user_defined_ports", type.user_defined_ports},
                       {"direct_feedthrough", type.direct_feedthrough},
                       {"parameters", std::move(parameters)}});
  }
  return library;
}

}  // namespace duet::studio
