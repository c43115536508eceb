#include "instance.hpp"

#include <algorithm>
#include <cstdio>

namespace __gnu_cxx {  // NOLINT: libstdc++'s own namespace
void __freeres();      // libstdc++'s: frees what it keeps until the process ends (valgrind calls it at exit)
}  // namespace __gnu_cxx

namespace duet::fmu {
namespace {

// The FMU links libstdc++ in, whose exception pool lives until the process ends; an importer that unloads the FMU
// (dlclose) would lose it, and a leak checker says so. Given back when the library is unloaded.
[[gnu::destructor]] void give_back_the_standard_librarys_pool() { __gnu_cxx::__freeres(); }

thread_local Instance* running_instance = nullptr;

// A communication point or step size within this share of a base period counts as exact: importers add step sizes
// up, and the sum drifts from the multiple by a few units in the last place.
constexpr double time_tolerance = 1e-6;

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

}  // namespace

// Binds an instance to the model's code and the hardware port for the length of a call; a model's code running
// inside another's step (an FMU importing this FMU in the same thread) gets its own back afterwards.
class Instance::Running {
 public:
  explicit Running(Instance& instance) : outer_(std::exchange(running_instance, &instance)) {
    model.bind(instance.storage_);
  }
  Running(const Running&) = delete;
  Running& operator=(const Running&) = delete;
  ~Running() {
    running_instance = outer_;
    model.bind(outer_ == nullptr ? nullptr : outer_->storage_);
  }

 private:
  Instance* outer_;
};

Instance::Instance(std::string name, Logger logger, bool logging, const Rules& rules)
    : name_(std::move(name)),
      logger_(logger),
      logging_(logging),
      rules_(rules),
      storage_(model.create()),
      inputs_(model.inputs),
      outputs_(model.outputs),
      raised_(model.interrupts.size()),
      handled_(model.interrupts.size()),
      period_s_(static_cast<double>(model.base_period_ns) * 1e-9) {
  initialize_model();
}

Instance::~Instance() { model.destroy(storage_); }

Instance* Instance::current() { return running_instance; }

void Instance::log(Status status, const std::string& message) const {
  if (!logging_ || logger_.log == nullptr) return;
  const char* category = status == Status::ok        ? "logEvents"
                         : status == Status::warning ? "logStatusWarning"
                                                     : "logStatusError";
  logger_.log(logger_, name_.c_str(), status, category, message.c_str());
}

Status Instance::illegal(const char* function) const {
  return refuse(function,
                std::string{"illegal call sequence in state "} + rules_.phase_names[static_cast<std::size_t>(phase_)]);
}

Status Instance::refuse(const char* function, const std::string& reason) const {
  log(Status::error, std::string{function} + ": " + reason);
  return Status::error;
}

Status Instance::set_start_time(const char* function, double start) {
  if (phase_ != Phase::instantiated) return illegal(function);
  start_s_ = start;
  time_ = start;
  return Status::ok;
}

Status Instance::enter_initialization(const char* function) {
  if (phase_ != Phase::instantiated) return illegal(function);
  phase_ = Phase::initialization;
  return Status::ok;
}

// The values at the start time are those of the first tick, as `duet sim` records its first row after the first
// tick: with the parameters and inputs set until now.
Status Instance::exit_initialization(const char* function) {
  if (phase_ != Phase::initialization) return illegal(function);
  initialize_model();
  tick();
  handled_ = raised_;  // the counts given until now are where counting starts
  phase_ = Phase::step;
  set_since_step_ = false;
  return Status::ok;
}

Status Instance::do_step(const char* function, double point, double size) {
  if (phase_ != Phase::step) return illegal(function);
  const double tolerance = period_s_ * time_tolerance;
  if (!(std::fabs(point - time_) <= tolerance)) {
    return refuse(function,
                  "currentCommunicationPoint " + number(point) + " is not the instance's time " + number(time_));
  }
  const double periods = std::round(size / period_s_);
  if (!(periods >= 1) || !(std::fabs(size - periods * period_s_) <= tolerance)) {
    return refuse(function, "a step of " + number(size) + " s is not a whole number of base periods (" +
                                number(period_s_) + " s)");
  }
  if (const Status raised = run_raised_interrupts(function); raised != Status::ok) return raised;
  for (double k = 0; k < periods; ++k) tick();
  set_since_step_ = false;
  return Status::ok;
}

Status Instance::run_raised_interrupts(const char* function) {
  if (raised_ == handled_) return Status::ok;  // most steps
  // A handler runs to its end each time: an importer's runaway counter must not make a step unbounded.
  constexpr std::int64_t most_per_step = 1000;
  for (std::size_t counter = 0; counter < raised_.size(); ++counter) {
    const std::int64_t grown = std::int64_t{raised_[counter]} - handled_[counter];
    if (grown >= 0 && grown <= most_per_step) continue;
    const std::string name = std::string{"interrupt:"} + model.interrupts[counter];
    return refuse(function, grown < 0 ? name + " went back from " + std::to_string(handled_[counter]) + " to " +
                                            std::to_string(raised_[counter]) + ": it counts the interrupts raised"
                                      : name + " grew by " + std::to_string(grown) + " in one step; at most " +
                                            std::to_string(most_per_step) + " interrupts of one kind run in a step");
  }
  // As the NVIC takes pending interrupts: the most urgent group first, then sub-priority, then the task table's order.
  std::vector<const InterruptTask*> pending;
  for (const InterruptTask& task : model.interrupt_tasks) {
    if (raised_[task.counter] != handled_[task.counter]) pending.push_back(&task);
  }
  std::stable_sort(pending.begin(), pending.end(), [](const InterruptTask* a, const InterruptTask* b) {
    const rt::InterruptPriority& first = model.tasks[a->task].priority;
    const rt::InterruptPriority& second = model.tasks[b->task].priority;
    return std::pair{first.group, first.sub} < std::pair{second.group, second.sub};
  });
  const Running running{*this};
  for (const InterruptTask* task : pending) {
    for (std::int32_t k = handled_[task->counter]; k != raised_[task->counter]; ++k) model.tasks[task->task].entry();
  }
  handled_ = raised_;
  return Status::ok;
}

Status Instance::terminate(const char* function) {
  if (phase_ != Phase::step) return illegal(function);
  const Running running{*this};
  model.terminate();
  phase_ = Phase::terminated;
  return Status::ok;
}

void Instance::reset() {
  model.load_reference_parameters(storage_);
  std::fill(inputs_.begin(), inputs_.end(), 0.0);
  std::fill(outputs_.begin(), outputs_.end(), 0.0);
  std::fill(raised_.begin(), raised_.end(), 0);
  std::fill(handled_.begin(), handled_.end(), 0);
  start_s_ = 0;
  phase_ = Phase::instantiated;
  set_since_step_ = false;
  initialize_model();
}

void Instance::initialize_model() {
  const Running running{*this};
  model.initialize();
  ticks_ = 0;
  time_ = start_s_;
}

// One base period: the periodic tasks due at this tick, fastest first, as the executive runs them in `duet sim`
// (single-tasking, lock-step). Interrupt tasks run when the importer raises them (run_raised_interrupts).
void Instance::tick() {
  const Running running{*this};
  for (const rt::Task& task : model.tasks) {
    if (task.kind == rt::TaskKind::periodic && ticks_ % task.period_ticks == 0) task.entry();
  }
  ++ticks_;
  time_ = start_s_ + static_cast<double>(ticks_ - 1) * period_s_;
}

const VariableSlot* Instance::variable(const char* function, std::uint32_t reference, TypeSet accepted) const {
  if (reference >= model.variables.size()) {
    refuse(function, "no variable has the value reference " + std::to_string(reference));
    return nullptr;
  }
  const VariableSlot& slot = model.variables[reference];
  if ((accepted & (1U << static_cast<unsigned>(slot.type))) == 0) {
    refuse(function, "variable '" + std::string{slot.name} + "' (" + std::to_string(reference) +
                         ") is not of the type this function takes");
    return nullptr;
  }
  return &slot;
}

void* Instance::value_address(const VariableSlot& slot) {
  switch (slot.role) {
    case Role::time: return &time_;
    case Role::input: return &inputs_[slot.index];
    case Role::output: return &outputs_[slot.index];
    case Role::interrupt_count: return &raised_[slot.index];
    case Role::fixed_parameter:
    case Role::tunable_parameter:
    case Role::local: break;
  }
  return slot.address(storage_);
}

bool Instance::settable(Role role) const {
  switch (role) {
    case Role::input:
    case Role::interrupt_count:
    case Role::tunable_parameter: return phase_ != Phase::terminated;
    case Role::fixed_parameter: return phase_ == Phase::instantiated || phase_ == Phase::initialization;
    case Role::time:
    case Role::output:
    case Role::local: break;
  }
  return false;
}

void Instance::write_resource(std::string_view name, std::span<const double> values) {
  for (const ResourceSlot& resource : model.resources) {
    if (resource.read || name != resource.name) continue;
    const std::size_t count = std::min(resource.count, values.size());
    std::copy_n(values.begin(), count, outputs_.begin() + static_cast<std::ptrdiff_t>(resource.first));
    return;
  }
}

void Instance::read_resource(std::string_view name, std::span<double> values) const {
  std::fill(values.begin(), values.end(), 0.0);
  for (const ResourceSlot& resource : model.resources) {
    if (!resource.read || name != resource.name) continue;
    const std::size_t count = std::min(resource.count, values.size());
    std::copy_n(inputs_.begin() + static_cast<std::ptrdiff_t>(resource.first), count, values.begin());
    return;
  }
}

}  // namespace duet::fmu
