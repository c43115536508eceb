#include "duet/host/real_time_port.hpp"

#include <pthread.h>
#include <sched.h>

#include <chrono>
#include <ctime>

namespace duet::host {
namespace {

constexpr std::uint64_t nanoseconds_per_second = 1'000'000'000;
constexpr int timer_thread_priority = 80;  // above ordinary real-time work, below the kernel's own threads (99)

timespec to_timespec(std::uint64_t nanoseconds) {
  return {static_cast<time_t>(nanoseconds / nanoseconds_per_second),
          static_cast<long>(nanoseconds % nanoseconds_per_second)};
}

}  // namespace

RealTimePort::RealTimePort(const rt::ModelDescription& model) : model_(model), interrupts_(model.tasks.size()) {}

RealTimePort::~RealTimePort() { stop_base_timer(); }

std::uint64_t RealTimePort::monotonic_ns() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<std::uint64_t>(now.tv_sec) * nanoseconds_per_second + static_cast<std::uint64_t>(now.tv_nsec);
}

void RealTimePort::raise(std::size_t task) {
  const std::lock_guard lock{mutex_};
  interrupts_.pend(task);
}

void RealTimePort::start_base_timer(std::uint32_t period_ns) {
  stop_base_timer();
  period_ns_ = period_ns;
  next_tick_ns_ = monotonic_ns() + period_ns_;
  timer_running_ = true;
  timer_ = std::thread{[this] { run_timer(); }};
}

void RealTimePort::stop_base_timer() {
  timer_running_ = false;
  if (timer_.joinable() && timer_.get_id() != std::this_thread::get_id()) timer_.join();
}

// The main thread only waits for the model to stop; the timer thread does the work.
void RealTimePort::idle() { std::this_thread::sleep_for(std::chrono::milliseconds(1)); }

void RealTimePort::run_timer() {
  sched_param parameters{};
  parameters.sched_priority = timer_thread_priority;
  real_time_priority_ = pthread_setschedparam(pthread_self(), SCHED_FIFO, &parameters) == 0;
  while (timer_running_) {
    const timespec deadline = to_timespec(next_tick_ns_);
    if (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &deadline, nullptr) != 0) continue;  // a signal: sleep again
    const std::lock_guard lock{mutex_};
    if (!timer_running_) break;
    next_tick_ns_ += period_ns_;
    interrupts_.pend(0);
  }
}

}  // namespace duet::host
