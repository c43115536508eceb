// How long `duet import simulink` takes for the largest test model (src/simulink_import/testing/options_r2020a, 100
// blocks, zipped as Simulink saves it): reading the .slx and importing it; and for slx_r2021a (64 blocks) and the
// classic .mdl of subsystems.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

#include "duet/fmi/archive_writer.hpp"
#include "duet/simulink_import/import.hpp"
#include "duet/simulink_import/import_options.hpp"
#include "duet/simulink_import/simulink_file.hpp"
#include "duet/support/temporary_folder.hpp"

namespace {

const std::filesystem::path testing = DUET_SIMULINK_TESTING_DIR;

void import_file(benchmark::State& state, const std::filesystem::path& file,
                 const duet::simulink_import::ImportOptions& options) {
  for (auto _ : state) {
    auto model = duet::simulink_import::read_simulink_file(file);
    if (!model) {
      state.SkipWithError(model.error().c_str());
      return;
    }
    const auto imported = duet::simulink_import::import_simulink(model.value(), options);
    if (!imported.problems.empty()) {
      state.SkipWithError(imported.problems.front().c_str());
      return;
    }
    benchmark::DoNotOptimize(imported.model_text.data());
  }
}

// A test package folder zipped as Simulink saves it, then read and imported again and again.
void import_package(benchmark::State& state, const std::string& folder_name,
                    const duet::simulink_import::ImportOptions& options) {
  auto folder = duet::TemporaryFolder::make("simulink_import_bench_");
  if (!folder) {
    state.SkipWithError(folder.error().c_str());
    return;
  }
  const std::filesystem::path parts = testing / folder_name;
  std::vector<duet::fmi::ArchiveInput> inputs;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(parts)) {
    if (entry.is_regular_file())
      inputs.push_back({std::filesystem::relative(entry.path(), parts).generic_string(), entry.path()});
  }
  const std::filesystem::path slx = folder.value().path() / (folder_name + ".slx");
  if (!duet::fmi::write_archive(slx, inputs)) {
    state.SkipWithError("cannot write the .slx");
    return;
  }
  import_file(state, slx, options);
}

void options_slx(benchmark::State& state) {
  auto variables = duet::simulink_import::read_variable_files({(testing / "options_r2020a.m").string()});
  if (!variables) {
    state.SkipWithError(variables.error().c_str());
    return;
  }
  import_package(state, "options_r2020a", {.variables = variables.value()});
}
BENCHMARK(options_slx)->Unit(benchmark::kMicrosecond);

void signal_chain_slx(benchmark::State& state) { import_package(state, "slx_r2021a", {}); }
BENCHMARK(signal_chain_slx)->Unit(benchmark::kMicrosecond);

void subsystems_mdl(benchmark::State& state) {
  duet::simulink_import::ImportOptions options;
  options.interrupts["subsystems/ISR"] = {.interrupt = "TIM2", .priority = 3};
  import_file(state, testing / "subsystems.mdl", options);
}
BENCHMARK(subsystems_mdl)->Unit(benchmark::kMicrosecond);

}  // namespace
