#pragma once
// What the import tests share: a plant standing in for the imported model's root ports, the imported model checked
// as duet checks it, and the verdict the import gave a block.

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "duet/model/model_file.hpp"
#include "duet/model/program.hpp"
#include "duet/plant/plant.hpp"
#include "duet/simulink_import/import.hpp"
#include "duet/simulink_import/import_options.hpp"
#include "duet/support/result.hpp"

namespace duet::simulink_import {

// A plant that answers the imported model's root inports (fixed values, or by the step) and keeps what its outports
// write; it may raise an interrupt in chosen steps.
class Ports : public plant::Plant {
 public:
  using Inport = std::function<double(std::size_t step)>;
  explicit Ports(const std::map<std::string, double>& inports) {
    for (const auto& [name, value] : inports) inports_[name] = [value](std::size_t) { return value; };
  }
  explicit Ports(std::map<std::string, Inport> inports) : inports_(std::move(inports)) {}
  void advance(double time_s, const plant::RaiseInterrupt& raise) override {
    step_ = static_cast<std::size_t>(std::llround(time_s / period_s));
    if (interrupt_steps.count(step_) != 0) raise(interrupt);
  }
  void write(std::string_view resource, std::span<const double> values) override {
    written[std::string{resource}] = values[0];
    history[std::string{resource}].push_back(values[0]);
  }
  void read(std::string_view resource, std::span<double> values) override {
    values[0] = inports_.at(std::string{resource})(step_);
  }
  std::map<std::string, double> written;               // the last value each outport wrote
  std::map<std::string, std::vector<double>> history;  // every value, a step after a step
  double period_s = 0.01;
  std::string interrupt;
  std::set<std::size_t> interrupt_steps;

 private:
  std::map<std::string, Inport> inports_;
  std::size_t step_ = 0;
};

inline const Verdict& verdict(const ImportResult& result, const std::string& path) {
  for (const Verdict& each : result.report)
    if (each.path == path) return each;
  ADD_FAILURE() << "no verdict for " << path;
  static const Verdict none;
  return none;
}

// A test model imported with the variables of a script in testing/; where either cannot be read, the test fails and
// the result is empty.
inline ImportResult imported_with(const Result<SimulinkModel>& model, const std::string& script) {
  if (!model) {
    ADD_FAILURE() << model.error();
    return {};
  }
  auto variables = read_variable_files({(std::filesystem::path{DUET_SIMULINK_TESTING_DIR} / script).string()});
  if (!variables) {
    ADD_FAILURE() << variables.error();
    return {};
  }
  return import_simulink(model.value(), {.variables = variables.value()});
}

// A duet block's output type in `program`, as integer_problems asks for it.
inline std::function<std::string(const std::string&)> output_type_in(const model::Program& program) {
  return [&program](const std::string& path) {
    for (const model::ProgramBlock& block : program.blocks)
      if (block.path == path && !block.outputs.empty()) return model::describe(program.signals[block.outputs[0]].type);
    return std::string{};
  };
}

// The imported model as duet checks it, or the test fails with the diagnostics and the text.
inline std::optional<model::ProgramBuild> checked(const ImportResult& imported, std::unique_ptr<model::Model>& keep) {
  EXPECT_TRUE(imported.problems.empty()) << ::testing::PrintToString(imported.problems);
  auto parsed = model::parse_model(imported.model_text, "imported.yaml");
  EXPECT_TRUE(parsed) << (parsed ? "" : parsed.error()) << "\n" << imported.model_text;
  if (!parsed) return std::nullopt;
  keep = std::make_unique<model::Model>(std::move(parsed).value());
  model::ProgramBuild build = model::build_program(*keep);
  for (const model::Diagnostic& diagnostic : build.diagnostics)
    ADD_FAILURE() << model::format("imported.yaml", diagnostic) << "\n" << imported.model_text;
  if (!build.program) return std::nullopt;
  EXPECT_EQ(integer_problems(imported, output_type_in(*build.program)), std::vector<std::string>{});
  return build;
}

}  // namespace duet::simulink_import
