#pragma once
// The executive's port for running a model in real time on Linux (software in the loop): a timer thread wakes at
// absolute deadlines (clock_nanosleep on CLOCK_MONOTONIC, so that periods do not drift) and runs the base tick; the
// thread asks for SCHED_FIFO and keeps the normal policy when it may not. As in LockStepPort, each task has a line
// of a SimulatedInterruptController; one mutex serialises every handler, whichever thread raises it.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <thread>

#include "duet/host/simulated_interrupt_controller.hpp"
#include "duet/host/task_lines.hpp"
#include "duet/rt/ceiling.hpp"
#include "duet/rt/task_table.hpp"

namespace duet::host {

class RealTimePort {
 public:
  struct CriticalSection {  // handlers already run one at a time, under the port's mutex
    explicit CriticalSection(rt::Ceiling /*ceiling*/) {}
  };

  explicit RealTimePort(const rt::ModelDescription& model);
  ~RealTimePort();
  RealTimePort(const RealTimePort&) = delete;
  RealTimePort& operator=(const RealTimePort&) = delete;

  template <typename Executive>
  void attach(Executive& executive) {
    const std::lock_guard lock{mutex_};
    connect_task_lines(interrupts_, model_, executive);
  }

  // An interrupt task's trigger fires now; callable from any thread. Blocks while another handler runs.
  void raise(std::size_t task);
  // Runs `work` while no handler runs, as the lowest priority on the real-time core would (e.g. XCP commands).
  template <typename Work>
  void exclusive(Work&& work) {
    const std::lock_guard lock{mutex_};
    work();
  }
  // Whether the timer thread got SCHED_FIFO (root, or CAP_SYS_NICE, or an rtprio limit).
  [[nodiscard]] bool real_time_priority() const { return real_time_priority_; }

  // ExecutivePort.
  [[nodiscard]] std::uint32_t cycles() const { return static_cast<std::uint32_t>(monotonic_ns()); }
  void start_base_timer(std::uint32_t period_ns);
  void stop_base_timer();
  [[nodiscard]] bool base_tick_pending() const { return monotonic_ns() >= next_tick_ns_; }
  void skip_base_tick() { next_tick_ns_ += period_ns_; }
  void trigger_rate(std::size_t rate) { interrupts_.pend(rate); }  // from the base tick: the mutex is held
  void idle();

  [[nodiscard]] static std::uint64_t monotonic_ns();

 private:
  void run_timer();

  const rt::ModelDescription& model_;
  std::mutex mutex_;
  SimulatedInterruptController interrupts_;
  std::thread timer_;
  std::atomic<bool> timer_running_{false};
  std::atomic<bool> real_time_priority_{false};
  std::uint64_t period_ns_ = 0;
  std::uint64_t next_tick_ns_ = 0;  // the timer thread's, and the base tick's under the mutex
};

}  // namespace duet::host
