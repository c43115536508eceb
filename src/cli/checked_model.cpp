#include "checked_model.hpp"

#include "duet/model/model_file.hpp"

namespace duet::cli {

std::optional<CheckedModel> load_checked_model(const std::string& file, std::ostream& err) {
  auto loaded = model::load_model(file);
  if (!loaded) {
    err << loaded.error() << '\n';
    return std::nullopt;
  }
  auto model = std::make_unique<model::Model>(std::move(loaded).value());
  model::ProgramBuild build = model::build_program(*model);
  for (const model::Diagnostic& diagnostic : build.diagnostics) err << model::format(file, diagnostic) << '\n';
  if (!build.program) return std::nullopt;
  return CheckedModel{std::move(model), std::move(*build.program)};
}

}  // namespace duet::cli
