// Steps per second of the robot's controller (apps/balbot/balbot.yaml) exported as an FMI 3.0 co-simulation FMU
// (docs/FMI.md, "Export"): one fmi3DoStep of one base period (1 ms) per iteration, driven through dlopen as any
// importer drives it. The FMU's library is built -O2 whatever the build of this program.
#include <benchmark/benchmark.h>
#include <dlfcn.h>

#include <filesystem>

#include "duet/fmi/archive.hpp"
#include "duet/fmi/fmi3_api.h"
#include "duet/fmi/model_description_reader.hpp"
#include "duet/fmu_export/fmu_export.hpp"
#include "duet/model/model_file.hpp"
#include "duet/support/temporary_folder.hpp"

namespace {

template <typename Function>
Function* function(void* library, const char* name) {
  return reinterpret_cast<Function*>(dlsym(library, name));
}

void exported_balbot_steps(benchmark::State& state) {
  const std::string file = std::string{DUET_SOURCE_DIR} + "/apps/balbot/balbot.yaml";
  auto model = duet::model::load_model(file);
  const duet::model::ProgramBuild build = duet::model::build_program(model.value());
  auto folder = duet::TemporaryFolder::make("fmu_bench_").value();
  const std::filesystem::path fmu = folder.path() / "balbot.fmu";
  if (auto exported = duet::fmu_export::export_fmu(*build.program, file, fmu, duet::fmi::FmiVersion::v3); !exported) {
    state.SkipWithError(exported.error().c_str());
    return;
  }
  auto archive = duet::fmi::Archive::open(fmu).value();
  const auto description = duet::fmi::read_model_description(archive.read("modelDescription.xml").value()).value();
  const auto unpacked = archive.extract().value();
  void* library = dlopen((unpacked.path() / "binaries/x86_64-linux/balbot.so").c_str(), RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) {
    state.SkipWithError(dlerror());
    return;
  }
  fmi3Instance instance = function<fmi3InstantiateCoSimulationTYPE>(library, "fmi3InstantiateCoSimulation")(
      "bench", description.token.c_str(), nullptr, false, false, false, false, nullptr, 0, nullptr, nullptr, nullptr);
  function<fmi3EnterInitializationModeTYPE>(library, "fmi3EnterInitializationMode")(instance, false, 0, 0, false, 0);
  function<fmi3ExitInitializationModeTYPE>(library, "fmi3ExitInitializationMode")(instance);
  auto* do_step = function<fmi3DoStepTYPE>(library, "fmi3DoStep");
  const double period = *description.co_simulation.fixed_internal_step_size;
  std::uint64_t steps = 0;
  for (auto _ : state) {
    fmi3Boolean event = false, terminate = false, early = false;
    fmi3Float64 last = 0;
    const fmi3Status status =
        do_step(instance, static_cast<double>(steps) * period, period, true, &event, &terminate, &early, &last);
    ++steps;
    benchmark::DoNotOptimize(status);
  }
  state.counters["steps_per_second"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
  function<fmi3FreeInstanceTYPE>(library, "fmi3FreeInstance")(instance);
  dlclose(library);
}
BENCHMARK(exported_balbot_steps);

}  // namespace
