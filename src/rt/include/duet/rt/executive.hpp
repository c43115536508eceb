#pragma once
// The executive: runs a model's periodic rates from a base timer interrupt and its interrupt tasks from their
// interrupt handlers, measures every task, detects overruns, and carries the model through its lifecycle:
//
//   initialize() -> [wait for a start request] -> running -> stop (model, external mode, final tick, overrun)
//                -> terminate()
//
// The board owns main: it calls initialize(), run() and terminate(), and forwards its interrupt handlers to
// on_base_tick(), on_rate_interrupt() and on_interrupt_task(). The port (see ExecutivePort) is the only thing the
// executive knows of the hardware.

#include <array>
#include <atomic>
#include <concepts>
#include <cstddef>
#include <cstdint>

#include "duet/rt/ceiling.hpp"
#include "duet/rt/net_timing.hpp"
#include "duet/rt/task_statistics.hpp"
#include "duet/rt/task_table.hpp"
#include "duet/rt/tick_count.hpp"

namespace duet::rt {

// What the executive needs of the platform. Interrupt-side calls must not block.
template <typename Port>
concept ExecutivePort = requires(Port& port, std::size_t rate, std::uint32_t period_ns) {
  { port.cycles() } -> std::same_as<std::uint32_t>;  // a free-running cycle counter; wraps
  port.start_base_timer(period_ns);                  // calls on_base_tick() every period from now on
  port.stop_base_timer();
  { port.base_tick_pending() } -> std::same_as<bool>;  // the next tick came while this one ran
  port.skip_base_tick();                               // forget that pending tick
  port.trigger_rate(rate);  // multitasking: pend the software interrupt that calls on_rate_interrupt(rate)
  port.idle();              // what the core does between interrupts
  // While it exists, masks the interrupts at and below a ceiling (ceiling.hpp) and leaves the more urgent ones be.
  requires std::constructible_from<typename Port::CriticalSection, Ceiling>;
};

enum class ExecutiveState : std::uint8_t { created, waiting_for_start, ready, running, stopping, stopped, terminated };
enum class StopReason : std::uint8_t { none, model, external, final_tick, overrun };

template <ExecutivePort Port, std::size_t TaskCapacity>
class Executive {
 public:
  Executive(const ModelDescription& model, Port& port) : model_(model), port_(port) {}

  // Checks the task table and runs the model's initialize. Nothing else runs if this fails.
  [[nodiscard]] TaskTableError initialize() {
    if (model_.tasks.size() > TaskCapacity) return TaskTableError::too_many_tasks;
    if (const TaskTableError error = check(model_); error != TaskTableError::none) return error;
    rates_ = rate_count(model_);
    for (std::size_t task = 0; task < model_.tasks.size(); ++task) entries_[task] = model_.tasks[task].entry;
    stop_tick_ = model_.final_tick != 0 ? model_.final_tick : UINT64_MAX;
    ceiling_ = rt::tasks_ceiling(model_);
    for (std::size_t task = 0; task < model_.tasks.size(); ++task) {
      at_ceiling_[task] = group_priority(model_, task) == ceiling_.priority;
    }
    model_.initialize();
    state_ = model_.wait_for_start ? ExecutiveState::waiting_for_start : ExecutiveState::ready;
    return TaskTableError::none;
  }

  // Runs the model until it stops: waits for start() if the model asks for it, then begin(), idle, end().
  // Blocks; call from main.
  void run() {
    while (state_ == ExecutiveState::waiting_for_start) port_.idle();
    if (begin()) {
      while (state_ == ExecutiveState::running) port_.idle();
    }
    end();
  }

  // The two halves of run() for a caller that drives time itself (lock-step simulation): begin() starts the base
  // timer if the model is ready (returns false otherwise), end() stops it.
  bool begin() {
    ExecutiveState ready = ExecutiveState::ready;
    if (!state_.compare_exchange_strong(ready, ExecutiveState::running)) return false;
    began_cycles_ = previous_tick_cycles_ = port_.cycles();  // the core load counts from here
    port_.start_base_timer(model_.base_period_ns);
    return true;
  }

  void end() {
    port_.stop_base_timer();
    state_ = ExecutiveState::stopped;
  }

  // Runs the model's terminate, once, after run() returned.
  void terminate() {
    if (state_ == ExecutiveState::stopped) {
      model_.terminate();
      state_ = ExecutiveState::terminated;
    }
  }

  // External mode's start request. Interrupt-safe.
  void start() {
    ExecutiveState waiting = ExecutiveState::waiting_for_start;
    state_.compare_exchange_strong(waiting, ExecutiveState::ready);
  }

  // Stops the model at the end of the current tick; the first reason given is kept. Interrupt-safe.
  void request_stop(StopReason reason) {
    for (ExecutiveState state : {ExecutiveState::waiting_for_start, ExecutiveState::ready, ExecutiveState::running}) {
      ExecutiveState expected = state;
      if (state_.compare_exchange_strong(expected, ExecutiveState::stopping)) {
        stop_reason_ = reason;
        return;
      }
    }
  }

  // The base timer's interrupt handler. Single-tasking runs every due rate here, fastest first; multitasking runs
  // the base rate and triggers the software interrupt of each due slower rate.
  void on_base_tick() {
    if (state_.load(std::memory_order_relaxed) != ExecutiveState::running) return;
    const std::uint32_t now = port_.cycles();
    if (now < previous_tick_cycles_) ++cycle_counter_wraps_;  // a base period is far shorter than a wrap
    previous_tick_cycles_ = now;

    run_measured(0, now);
    if (rates_ > 1) {
      release_slower_rates();
      count_down_releases();
    }
    count_tick();

    if (port_.base_tick_pending()) overrun(0);
  }

  // Multitasking: the software interrupt of a slower rate.
  void on_rate_interrupt(std::size_t rate) {
    if (state_.load(std::memory_order_relaxed) == ExecutiveState::running) run_measured(rate, port_.cycles());
    rate_released_[rate] = false;
  }

  // The interrupt handler of an interrupt-triggered task (its index in the task table).
  void on_interrupt_task(std::size_t task) {
    if (state_.load(std::memory_order_relaxed) == ExecutiveState::running) run_measured(task, port_.cycles());
  }

  // A critical section at `ceiling` for as long as the returned object exists (ceiling.hpp: the ceiling of the tasks
  // that share what it guards), measured: the longest at each ceiling is longest_section(). For data a model's tasks
  // share beyond the rate transitions, which need none.
  class Section {
   public:
    Section(Executive& owner, Ceiling ceiling)
        : masked_(ceiling), executive_(owner), ceiling_(ceiling), start_(owner.port_.cycles()) {}
    // The time is recorded before the mask is lifted (members are destroyed after the body).
    ~Section() { executive_.sections_.record(ceiling_, executive_.port_.cycles() - start_); }
    Section(const Section&) = delete;
    Section& operator=(const Section&) = delete;

   private:
    const typename Port::CriticalSection masked_;
    Executive& executive_;
    Ceiling ceiling_;
    std::uint32_t start_;
  };
  [[nodiscard]] Section section(Ceiling ceiling) { return Section{*this, ceiling}; }
  // For a section timed by code that cannot name the executive's type (a library shared by several images): records
  // its length among the measured ones. Call inside the section, before its mask is lifted.
  void record_section(Ceiling ceiling, std::uint32_t cycles) { sections_.record(ceiling, cycles); }

  // True while the base tick `ticks()` releases `rate`: what deterministic rate transitions ask in the faster task.
  [[nodiscard]] bool is_release_tick(std::size_t rate) const { return ticks_until_release_[rate] == 0; }

  // Base ticks so far; during a base-rate step, the index of the current tick. Whole, never torn, from the base tick
  // and any less urgent context (tick_count.hpp).
  [[nodiscard]] std::uint64_t ticks() const { return ticks_.read(); }
  [[nodiscard]] ExecutiveState state() const { return state_; }
  [[nodiscard]] StopReason stop_reason() const { return stop_reason_; }
  [[nodiscard]] const TaskStatistics& statistics(std::size_t task) const { return statistics_[task]; }
  [[nodiscard]] CoreLoad load() const {
    const std::uint64_t elapsed = (std::uint64_t{cycle_counter_wraps_} << 32U) + previous_tick_cycles_ - began_cycles_;
    return {timing_.busy_cycles(), elapsed};
  }
  // The ceiling of what all tasks share (the executive's own sections), and the longest section measured at a
  // ceiling, in cycles: blocking for `duet sched`.
  [[nodiscard]] Ceiling tasks_ceiling() const { return ceiling_; }
  [[nodiscard]] std::uint32_t longest_section(Ceiling ceiling) const { return sections_.longest(ceiling); }

 private:
  // `start` is the cycle count at which the task's handler began: the base tick has read it already.
  // Inlined: the base tick runs it on every tick, and a call costs its registers' saving there.
  [[gnu::always_inline]] void run_measured(std::size_t task, std::uint32_t start) {
    // The timing of nested tasks is shared by every task: a task at their ceiling is never preempted by another and
    // takes no section; the others take one at the ceiling to end theirs (beginning only reads a word).
    const NetTiming::Start started = timing_.begin(start);
    if constexpr (requires { port_.task_started(task); }) port_.task_started(task);
    entries_[task]();
    if constexpr (requires { port_.task_finished(task); }) port_.task_finished(task);
    std::uint32_t net_cycles = 0;
    if (at_ceiling_[task]) {
      net_cycles = timing_.end(started, port_.cycles());
    } else {
      [[maybe_unused]] const Section section{*this, ceiling_};
      net_cycles = timing_.end(started, port_.cycles());
    }
    statistics_[task].record(net_cycles);
  }

  // Single-tasking runs each slower rate due at this tick here, fastest first; multitasking triggers its software
  // interrupt. Out of line: the base tick of a model with one rate does not pay for it.
  [[gnu::noinline]] void release_slower_rates() {
    for (std::size_t rate = 1; rate < rates_; ++rate) {
      if (!is_release_tick(rate)) continue;
      if (model_.tasking_mode == TaskingMode::single) {
        run_measured(rate, port_.cycles());
      } else if (rate_released_[rate].exchange(true)) {
        overrun(rate);  // the previous activation has not finished
      } else {
        port_.trigger_rate(rate);
      }
    }
  }

  void overrun(std::size_t task) {
    ++statistics_[task].overruns;
    if (model_.overrun_policy == OverrunPolicy::stop) {
      request_stop(StopReason::overrun);
    } else if (task == 0) {
      port_.skip_base_tick();
      // The tick happened; its activations are dropped.
      if (rates_ > 1) count_down_releases();
      count_tick();
    }
  }

  void count_tick() {
    const std::uint32_t low = ticks_.increment();
    if (low == static_cast<std::uint32_t>(stop_tick_) && ticks_.read_in_writer() == stop_tick_)
      request_stop(StopReason::final_tick);
  }

  // Counts down to each rate's next release rather than dividing the 64-bit tick count on every tick.
  void count_down_releases() {
    for (std::size_t rate = 1; rate < rates_; ++rate) {
      std::uint32_t& countdown = ticks_until_release_[rate];
      countdown = countdown == 0 ? model_.tasks[rate].period_ticks - 1U : countdown - 1U;
    }
  }

  const ModelDescription& model_;
  Port& port_;
  std::size_t rates_ = 0;
  std::array<void (*)(), TaskCapacity> entries_{};  // the task table's, one load away
  std::atomic<ExecutiveState> state_{ExecutiveState::created};
  StopReason stop_reason_ = StopReason::none;
  TickCount<> ticks_;
  std::uint64_t stop_tick_ = UINT64_MAX;  // the final tick, if the model has one
  // The cycles elapsed from begin() to the last base tick, counted without a 64-bit addition on every tick.
  std::uint32_t began_cycles_ = 0;
  std::uint32_t previous_tick_cycles_ = 0;
  std::uint32_t cycle_counter_wraps_ = 0;
  std::array<std::uint32_t, TaskCapacity> ticks_until_release_{};  // 0: the current tick releases the rate
  std::array<std::atomic<bool>, TaskCapacity> rate_released_{};
  std::array<TaskStatistics, TaskCapacity> statistics_{};
  NetTiming timing_;
  Ceiling ceiling_;
  std::array<bool, TaskCapacity> at_ceiling_{};
  SectionTiming sections_;
};

}  // namespace duet::rt
