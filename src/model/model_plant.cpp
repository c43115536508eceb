#include "duet/model/model_plant.hpp"

#include <cmath>

#include "duet/model/model_file.hpp"

namespace duet::model {

Result<std::unique_ptr<ModelPlant>> ModelPlant::load(const std::string& path) {
  auto model = load_model(path);
  if (!model) return Failure{model.error()};
  std::unique_ptr<ModelPlant> plant{new ModelPlant};
  plant->model_ = std::make_unique<Model>(std::move(model).value());
  ProgramBuild build = build_program(*plant->model_);
  std::string errors;
  for (const Diagnostic& diagnostic : build.diagnostics) {
    (diagnostic.severity == Diagnostic::Severity::error ? errors : plant->warnings_.emplace_back()) +=
        format(path, diagnostic) + (diagnostic.severity == Diagnostic::Severity::error ? "\n" : "");
  }
  if (!build.program) return Failure{"the plant model has errors:\n" + errors};
  plant->program_ = std::make_unique<Program>(std::move(*build.program));
  auto runner = ModelRunner::create(*plant->program_, plant->resources_);
  if (!runner) return Failure{"the plant model: " + runner.error()};
  plant->runner_ = std::move(runner).value();
  return plant;
}

// Every plant tick due by `time_s` (the plant's tick k is at k times its base period).
void ModelPlant::advance(double time_s, const plant::RaiseInterrupt&) {
  const double period = runner_->base_period_s();
  while (static_cast<double>(ticks_) * period <= time_s + period * 1e-9) {
    runner_->tick();
    ++ticks_;
  }
}

void ModelPlant::write(std::string_view resource, std::span<const double> values) {
  resources_.write(resource, values);
}

void ModelPlant::read(std::string_view resource, std::span<double> values) { resources_.read(resource, values); }

}  // namespace duet::model
