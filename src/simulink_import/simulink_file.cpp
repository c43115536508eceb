#include "duet/simulink_import/simulink_file.hpp"

#include "duet/simulink_import/classic_mdl.hpp"
#include "duet/simulink_import/slx_model.hpp"
#include "duet/simulink_import/slx_parts.hpp"
#include "duet/support/text_file.hpp"

namespace duet::simulink_import {

Result<SimulinkModel> read_simulink_file(const std::filesystem::path& file) {
  auto bytes = read_text_file(file.string());
  if (!bytes) return Failure{bytes.error()};
  const std::string name = file.string();
  if (bytes.value().starts_with("PK\x03\x04")) {  // a zip's first local header
    auto parts = read_slx_parts(file);
    if (!parts) return Failure{parts.error()};
    return read_slx_model(parts.value(), name);
  }
  if (is_packaged_mdl(bytes.value())) {
    auto parts = read_packaged_mdl_parts(bytes.value(), name);
    if (!parts) return Failure{parts.error()};
    auto model = read_slx_model(parts.value(), name);
    if (model) model.value().format = "mdl (packaged text)";
    return model;
  }
  return read_classic_mdl(bytes.value(), name);
}

}  // namespace duet::simulink_import
