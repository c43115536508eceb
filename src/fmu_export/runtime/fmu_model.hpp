#pragma once
// What an exported FMU's glue knows of its model: a table that `duet fmu export` writes for each model
// (fmu_model.cpp, beside the model's generated code) and the glue of both FMI versions reads (docs/FMI.md, "Export").
// Compiled into the FMU only, never into duet.

#include <cstddef>
#include <cstdint>
#include <span>

#include "duet/rt/task_table.hpp"

namespace duet::fmu {

// The model's data types (duet::model::DataType), as the FMU stores them.
enum class ValueType : std::uint8_t { float64, float32, int8, int16, int32, uint8, uint16, uint32, boolean };

// Where a variable's value lives, and who may set it when.
enum class Role : std::uint8_t {
  time,               // the independent variable: the instance's time
  input,              // what the model reads from a hardware resource: the instance's inputs, as doubles
  output,             // what the model writes to a hardware resource: the instance's outputs, as doubles
  fixed_parameter,    // on the model's parameter page, read only while initialising: set before the first step
  tunable_parameter,  // on the model's parameter page, read by the steps: set before any step
  local,              // a measurable signal
  interrupt_count     // how often the importer raised an interrupt: the instance's counter of it
};

struct VariableSlot {
  const char* name;
  ValueType type;
  Role role;
  std::size_t index;  // input, output, interrupt count: the place among the instance's inputs, outputs or counters
  void* (*address)(void* storage);  // parameters and locals: where the value is in the instance's model storage
};

// A hardware resource as the port names it ("gpio:LED0"), and where its values are among the inputs or outputs.
struct ResourceSlot {
  const char* name;
  bool read;  // the model reads it (FMU inputs); otherwise it writes it (FMU outputs)
  std::size_t first;
  std::size_t count;
};

// An interrupt task and the counter that raises it (ModelTable::interrupts), by their places.
struct InterruptTask {
  std::size_t counter;
  std::size_t task;  // in ModelTable::tasks
};

struct ModelTable {
  const char* token;  // 3.0's instantiationToken, 2.0's guid
  std::uint64_t base_period_ns;
  std::span<const VariableSlot> variables;  // by value reference
  std::span<const ResourceSlot> resources;
  std::size_t inputs;
  std::size_t outputs;
  void* (*create)();               // a new instance of the model's storage, its parameters the model's values
  void (*destroy)(void* storage);  //
  void (*load_reference_parameters)(void* storage);
  void (*bind)(void* storage);  // makes `storage` the one the model's functions work on, in this thread
  void (*initialize)();
  void (*terminate)();
  std::span<const rt::Task> tasks;
  std::span<const char* const> interrupts;  // the interrupts the importer raises, by counter: "EXTI8"
  std::span<const InterruptTask> interrupt_tasks;
};

extern const ModelTable model;

}  // namespace duet::fmu
