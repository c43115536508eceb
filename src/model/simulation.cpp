#include "duet/model/simulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>

#include "duet/model/data_type.hpp"
#include "duet/model/interpreter.hpp"
#include "duet/support/closest_word.hpp"
#include "duet/support/number_text.hpp"

namespace duet::model {
namespace {

constexpr std::size_t max_tasks = 16;  // the NVIC's 16 group levels bound a model's tasks anyway

// The executive calls tasks through plain function pointers: one per task slot, each running that task of the
// interpreter being simulated (one simulation at a time per thread).
thread_local Interpreter* running = nullptr;

template <std::size_t task>
void run_task() {
  running->run_task(task);
}

template <std::size_t... task>
constexpr std::array<void (*)(), sizeof...(task)> task_entries(std::index_sequence<task...>) {
  return {&run_task<task>...};
}
constexpr auto entries = task_entries(std::make_index_sequence<max_tasks>{});

void nothing() {}

struct Column {
  std::size_t signal;
  std::size_t element;
};

// For a name the model does not have: the nearest one, or the names there are (a few).
std::string signal_hint(const Program& program, const std::string& name) {
  std::vector<std::string_view> names;
  for (const ProgramSignal& signal : program.signals) names.emplace_back(signal.name);
  if (const auto closest = closest_word(name, names)) return "did you mean '" + std::string{*closest} + "'?";
  constexpr std::size_t listed = 8;
  std::string text = "its signals: ";
  for (std::size_t k = 0; k < names.size() && k < listed; ++k) text += (k == 0 ? "" : ", ") + std::string{names[k]};
  if (names.size() > listed) text += ", ... (" + std::to_string(names.size()) + " in all)";
  return text;
}

Result<std::vector<std::size_t>> recorded_signals(const Program& program, const SimulationOptions& options) {
  std::vector<std::size_t> chosen;
  for (const std::string& name : options.signals) {
    const auto index = program.find_signal(name);
    if (!index) return Failure{"the model has no signal '" + name + "' (" + signal_hint(program, name) + ")"};
    chosen.push_back(*index);
  }
  if (!chosen.empty()) return chosen;
  for (std::size_t index = 0; index < program.signals.size(); ++index) {
    if (program.signals[index].measurable) chosen.push_back(index);
  }
  if (!chosen.empty()) return chosen;
  for (std::size_t index = 0; index < program.signals.size(); ++index) chosen.push_back(index);
  return chosen;
}

}  // namespace

Result<TaskPriorities> task_priorities(const Program& program) {
  int least_urgent_interrupt = 0;
  for (const ProgramTask& task : program.tasks) {
    if (task.rate.kind == Rate::Kind::interrupt)
      least_urgent_interrupt = std::max(least_urgent_interrupt, task.priority.value_or(0));
  }
  TaskPriorities result;
  int next_rate_group = least_urgent_interrupt + 1;
  for (const ProgramTask& task : program.tasks) {
    const int group = task.rate.kind == Rate::Kind::interrupt ? task.priority.value_or(0) : next_rate_group++;
    if (group < 0 || group > 15) {
      return Failure{"task '" + task.name + "' would need NVIC group " + std::to_string(group) +
                     "; the core has 16 (0 to 15): give the interrupt tasks more urgent priorities"};
    }
    result.priorities.push_back({static_cast<std::uint8_t>(group), 0});
  }
  return result;
}

Result<std::unique_ptr<ModelRunner>> ModelRunner::create(const Program& program, plant::Plant& plant) {
  if (program.tasks.size() > max_tasks) return Failure{"the model has more than 16 tasks"};
  auto priorities = task_priorities(program);
  if (!priorities) return Failure{priorities.error()};
  std::unique_ptr<ModelRunner> runner{new ModelRunner{program}};
  auto user_code = UserCodeLibrary::build(program);
  if (!user_code) return Failure{user_code.error()};
  runner->user_code_ = std::move(user_code).value();
  auto created = Interpreter::create(program, plant, runner->user_code_.get());
  if (!created) return Failure{created.error()};
  runner->interpreter_ = std::move(created).value();
  for (std::size_t index = 0; index < program.tasks.size(); ++index) {
    const ProgramTask& task = program.tasks[index];
    rt::Task entry{.name = task.name, .priority = priorities.value().priorities[index], .entry = entries[index]};
    if (task.rate.kind == Rate::Kind::interrupt) {
      entry.kind = rt::TaskKind::interrupt;
    } else {
      entry.period_ticks = static_cast<std::uint32_t>(task.rate.multiple);
    }
    runner->tasks_.push_back(entry);
  }
  if (runner->tasks_.empty()) {  // a model of constants only still ticks, so that its signals are recorded over time
    runner->tasks_.push_back({.name = "rate 1", .priority = {1, 0}, .entry = nothing});
  }
  runner->description_ = {.name = program.model->name,
                          .base_period_ns = static_cast<std::uint32_t>(std::llround(runner->base_period_s() * 1e9)),
                          .tasks = runner->tasks_,
                          .initialize = nothing,
                          .terminate = nothing};
  runner->port_ = std::make_unique<host::LockStepPort>(runner->description_);
  runner->executive_ = std::make_unique<Executive>(runner->description_, *runner->port_);
  runner->port_->attach(*runner->executive_);
  runner->interpreter_->initialize();
  if (const rt::TaskTableError error = runner->executive_->initialize(); error != rt::TaskTableError::none) {
    return Failure{"the executive refused the model's task table (error " + std::to_string(static_cast<int>(error)) +
                   ")"};
  }
  (void)runner->executive_->begin();
  return runner;
}

ModelRunner::ModelRunner(const Program& program) : program_(program) {}

ModelRunner::~ModelRunner() {
  if (executive_) {
    executive_->request_stop(rt::StopReason::external);
    executive_->end();
  }
}

double ModelRunner::base_period_s() const { return program_.model->base_period_us * 1e-6; }

// The trampolines run whichever interpreter is running: this one, for the length of the call (a plant model ticks
// between the ticks of the model it is the plant of).
void ModelRunner::tick() {
  Interpreter* const outer = std::exchange(running, interpreter_.get());
  port_->advance(1);
  running = outer;
}

void ModelRunner::raise(std::string_view interrupt) {
  Interpreter* const outer = std::exchange(running, interpreter_.get());
  for (std::size_t task = 0; task < program_.tasks.size(); ++task) {
    if (program_.tasks[task].rate.kind == Rate::Kind::interrupt && program_.tasks[task].rate.interrupt == interrupt) {
      port_->raise(task);
    }
  }
  running = outer;
}

std::uint32_t ModelRunner::activations(std::size_t task) const { return executive_->statistics(task).activations; }

Result<SimulationResult> simulate(const Program& program, plant::Plant& plant, const SimulationOptions& options) {
  if (!(options.duration_s >= 0) || !std::isfinite(options.duration_s)) {
    return Failure{"the duration must be a number of seconds, 0 or more"};
  }
  auto signals = recorded_signals(program, options);
  if (!signals) return Failure{signals.error()};
  // Before the model's initialisation, whose writes the plant takes.
  if (Status started = plant.start(program.model->base_period_us * 1e-6); !started) return Failure{started.error()};
  auto created = ModelRunner::create(program, plant);
  if (!created) return Failure{created.error()};
  ModelRunner& runner = *created.value();
  Interpreter& interpreter = runner.interpreter();

  SimulationResult result;
  std::vector<Column> columns;
  for (const std::size_t signal : signals.value()) {
    const ProgramSignal& info = program.signals[signal];
    const std::size_t count = info.type.elements();
    for (std::size_t element = 0; element < count; ++element) {
      columns.push_back({signal, element});
      result.recording.names.push_back(count == 1 ? info.name : info.name + "[" + std::to_string(element) + "]");
      result.recording.units.push_back(info.unit);
      result.recording.signals.emplace_back(signal);
    }
  }
  const std::vector<plant::Plant::Observable> observables =
      options.record_plant ? plant.observables() : std::vector<plant::Plant::Observable>{};
  for (const plant::Plant::Observable& observable : observables) {
    result.recording.names.push_back("plant." + observable.name);
    result.recording.units.push_back(observable.unit);
    result.recording.signals.emplace_back(std::nullopt);
  }
  std::vector<double> observed(observables.size());
  result.recording.columns.resize(columns.size() + observables.size());
  const double base_period_s = runner.base_period_s();
  const auto ticks = static_cast<std::uint64_t>(std::floor(options.duration_s / base_period_s + 1e-9)) + 1U;
  // The recording is kept in memory: refuse one that would not fit rather than run out of it.
  constexpr std::uint64_t most_values = 100'000'000;  // 800 MB of doubles
  const std::uint64_t values = ticks * std::max<std::uint64_t>(columns.size() + observables.size() + 1, 1);
  if (ticks > most_values || values > most_values) {
    return Failure{"recording " + std::to_string(columns.size()) + " columns for " + std::to_string(ticks) +
                   " ticks is more than " + std::to_string(most_values) +
                   " values: simulate a shorter time, or record fewer signals (-s)"};
  }
  const auto raise = [&runner](std::string_view interrupt) { runner.raise(interrupt); };
  for (std::uint64_t tick = 0; tick < ticks; ++tick) {
    const double now = static_cast<double>(tick) * base_period_s;
    if (options.before_tick) options.before_tick(tick, interpreter);
    plant.advance(now, raise);
    runner.tick();
    result.recording.time_s.push_back(now);
    for (std::size_t k = 0; k < columns.size(); ++k) {
      result.recording.columns[k].push_back(interpreter.signal(columns[k].signal, columns[k].element));
    }
    if (!observed.empty()) {
      plant.observe(observed);
      for (std::size_t k = 0; k < observed.size(); ++k)
        result.recording.columns[columns.size() + k].push_back(observed[k]);
    }
    if (const std::optional<plant::Plant::Halt> halt = plant.halted()) {
      if (halt->failed) return Failure{"the plant failed: " + halt->reason};
      result.plant_stop = halt->reason;
      break;
    }
  }
  result.ticks = result.recording.time_s.size();
  for (std::size_t task = 0; task < program.tasks.size(); ++task)
    result.activations.push_back(runner.activations(task));
  return result;
}

std::string to_csv(const Recording& recording) {
  std::string text = "time_s";
  for (const std::string& name : recording.names) text += "," + name;
  text += '\n';
  for (std::size_t row = 0; row < recording.time_s.size(); ++row) {
    text += shortest_text(recording.time_s[row]);
    for (const auto& column : recording.columns) text += "," + shortest_text(column[row]);
    text += '\n';
  }
  return text;
}

}  // namespace duet::model
