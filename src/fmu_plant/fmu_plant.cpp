#include "duet/fmu_plant/fmu_plant.hpp"

#include <algorithm>

namespace duet::fmu_plant {

FmuPlant::FmuPlant(std::unique_ptr<fmi::ImportedFmu> fmu, FmuMapping mapping)
    : fmu_(std::move(fmu)), mapping_(std::move(mapping)) {}

Result<std::unique_ptr<FmuPlant>> FmuPlant::load(Options options) {
  auto opened = fmi::ImportedFmu::open(options.fmu, std::move(options.log));
  if (!opened) return Failure{opened.error()};
  fmi::ImportedFmu& fmu = *opened.value();
  if (auto checked = check_fmu_mapping(options.mapping, fmu.description()); !checked) return Failure{checked.error()};
  std::unique_ptr<FmuPlant> plant{new FmuPlant(std::move(opened).value(), std::move(options.mapping))};
  const FmuMapping& mapping = plant->mapping_;

  for (const Connection& input : mapping.inputs) plant->inputs_.push_back({fmu.variable(input.variable)});
  for (const Connection& output : mapping.outputs) plant->fetched_.push_back({fmu.variable(output.variable)});
  plant->observed_from_ = plant->fetched_.size();
  std::vector<std::string> observed;
  for (const std::size_t output : fmu.description().outputs)
    observed.push_back(fmu.description().variables[output].name);
  for (const std::string& name : mapping.observed) {
    if (std::find(observed.begin(), observed.end(), name) == observed.end()) observed.push_back(name);
  }
  for (const std::string& name : observed) plant->fetched_.push_back({fmu.variable(name)});
  return plant;
}

Status FmuPlant::start(double base_period_s) {
  if (started_) return Failure{"the FMU plant was started twice"};
  fmi::ImportedFmu& fmu = *fmu_;
  const FmuMapping& mapping = mapping_;
  // Inputs take their values in initialisation mode (2.0 allows no earlier), everything else before it.
  const auto is_input = [&fmu](const Setting& setting) {
    return fmu.variable(setting.variable)->causality == fmi::Causality::input;
  };
  for (const Setting& setting : mapping.settings) {
    if (is_input(setting)) continue;
    if (auto set = fmu.set(*fmu.variable(setting.variable), setting.value); !set)
      return Failure{setting.place + ": " + set.error()};
  }
  const auto set_inputs = [&fmu, &mapping, &is_input]() -> Status {
    for (const Setting& setting : mapping.settings) {
      if (!is_input(setting)) continue;
      if (auto set = fmu.set(*fmu.variable(setting.variable), setting.value); !set)
        return Failure{setting.place + ": " + set.error()};
    }
    return done();
  };
  if (auto initialized = fmu.initialize(0.0, base_period_s, set_inputs); !initialized)
    return Failure{initialized.error()};
  // Connected inputs start from the FMU's own start values until the controller writes them.
  for (Slot& input : inputs_) {
    auto value = fmu.get(*input.variable);
    if (!value) return Failure{value.error()};
    input.value = value.value();
  }
  if (auto fetched = fetch(); !fetched) return Failure{fetched.error()};
  started_ = true;
  return done();
}

Status FmuPlant::fetch() {
  for (Slot& slot : fetched_) {
    auto value = fmu_->get(*slot.variable);
    if (!value) return Failure{value.error()};
    slot.value = value.value();
  }
  return done();
}

void FmuPlant::fail(std::string reason) {
  if (!halt_) halt_ = Halt{.reason = std::move(reason), .failed = true};
}

void FmuPlant::advance(double time_s, const plant::RaiseInterrupt&) {
  if (!started_) return fail("the FMU plant was advanced before it was started");
  if (halt_ || time_s < fmu_->time() + 1e-12) return;  // nothing to step (time 0, or a halted FMU)
  for (const Slot& input : inputs_) {
    if (auto set = fmu_->set(*input.variable, input.value); !set) return fail(set.error());
  }
  if (auto advanced = fmu_->advance_to(time_s); !advanced) return fail(advanced.error());
  if (auto fetched = fetch(); !fetched) return fail(fetched.error());
  if (fmu_->stop_request()) halt_ = Halt{.reason = *fmu_->stop_request(), .failed = false};
}

void FmuPlant::write(std::string_view resource, std::span<const double> values) {
  for (std::size_t k = 0; k < mapping_.inputs.size(); ++k) {
    const Connection& input = mapping_.inputs[k];
    if (input.resource != resource) continue;
    if (input.element >= values.size()) {
      return fail(mapping_.file + ":" + std::to_string(input.line) + ": the controller writes " +
                  std::to_string(values.size()) + " element(s) to " + input.resource + ", and this line connects " +
                  "element " + std::to_string(input.element));
    }
    inputs_[k].value = values[input.element];
  }
}

void FmuPlant::read(std::string_view resource, std::span<double> values) {
  std::fill(values.begin(), values.end(), 0.0);
  std::vector<bool> answered(values.size(), false);
  for (std::size_t k = 0; k < mapping_.outputs.size(); ++k) {
    const Connection& output = mapping_.outputs[k];
    if (output.resource != resource) continue;
    if (output.element >= values.size()) {
      return fail(mapping_.file + ":" + std::to_string(output.line) + ": the controller reads " +
                  std::to_string(values.size()) + " element(s) of " + output.resource +
                  ", and this line connects element " + std::to_string(output.element));
    }
    values[output.element] = fetched_[k].value;
    answered[output.element] = true;
  }
  const auto missing = std::find(answered.begin(), answered.end(), false);
  if (missing != answered.end()) {
    fail(mapping_.file + ": the controller reads " + std::string{resource} + " element " +
         std::to_string(missing - answered.begin()) + ", which no FMU output answers (under outputs)");
  }
}

std::vector<plant::Plant::Observable> FmuPlant::observables() const {
  std::vector<Observable> observables;
  for (std::size_t k = observed_from_; k < fetched_.size(); ++k)
    observables.push_back({fetched_[k].variable->name, fetched_[k].variable->unit});
  return observables;
}

void FmuPlant::observe(std::span<double> values) const {
  for (std::size_t k = observed_from_; k < fetched_.size() && k - observed_from_ < values.size(); ++k)
    values[k - observed_from_] = fetched_[k].value;
}

}  // namespace duet::fmu_plant
