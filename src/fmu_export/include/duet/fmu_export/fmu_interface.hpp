#pragma once
// What an exported FMU shows of a model (docs/FMI.md, "Export"): its variables in value-reference order, with how
// the FMU's glue reaches each one's value, and the hardware resources its inputs and outputs stand for.

#include <cstddef>
#include <string>
#include <vector>

#include "duet/fmi/model_description.hpp"
#include "duet/model/program.hpp"

namespace duet::fmu_export {

// Mirrors the runtime's duet::fmu::Role (runtime/fmu_model.hpp), which the generated table names.
enum class Role { time, input, output, fixed_parameter, tunable_parameter, local, interrupt_count };

struct Binding {
  Role role = Role::local;
  model::DataType type = model::DataType::float64;
  std::size_t index = 0;  // input, output, interrupt count: the place among the inputs, outputs or counters
  std::string member;     // parameter and local: the value in the model's Instance, e.g. "memory.signals.x[1]"
};

struct Resource {
  std::string name;  // as the hardware port names it: "gpio:LED0"
  bool read = false;
  std::size_t first = 0;
  std::size_t count = 0;
};

// An interrupt task and the counter (FmuInterface::interrupts) that raises it.
struct InterruptTask {
  std::size_t counter = 0;
  std::size_t task = 0;  // in the program's tasks
};

struct FmuInterface {
  fmi::ModelDescription description;  // everything but the token, which names the built library
  std::vector<Binding> bindings;      // one per variable of the description, in its order
  std::vector<Resource> resources;
  std::size_t inputs = 0;
  std::size_t outputs = 0;
  std::vector<std::string> interrupts;  // by counter: "EXTI8"
  std::vector<InterruptTask> interrupt_tasks;
};

// Inputs and outputs are the hardware resources the model reads and writes (a plant model's PlantInput and
// PlantOutput blocks, a controller's hardware blocks), as doubles, named by the resource; and for each interrupt
// that triggers a task a counter input "interrupt:NAME": each increment raises it once, running its task at the
// start of the next step. Every parameter is a parameter, fixed when only the initialisation reads it; every
// measurable signal a local.
[[nodiscard]] FmuInterface fmu_interface(const model::Program& program, fmi::FmiVersion version);

}  // namespace duet::fmu_export
