#include "duet/link/pacer.hpp"

#include <sys/prctl.h>

#include <algorithm>
#include <thread>

namespace duet::link {
namespace {

class SteadyPacingClock final : public PacingClock {
 public:
  time_point now() override { return std::chrono::steady_clock::now(); }
  void sleep_until(time_point deadline) override {
    // Linux lets a thread's timers expire up to 50 us late by default, to gather wake-ups; a thread that keeps
    // real time asks for none (unprivileged, this thread only).
    thread_local const bool precise = ::prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL) == 0;
    static_cast<void>(precise);
    std::this_thread::sleep_until(deadline);
  }
};

}  // namespace

PacingClock& steady_pacing_clock() {
  static SteadyPacingClock clock;
  return clock;
}

double Lateness::late_fraction() const {
  return ticks == 0 ? 0.0 : static_cast<double>(late) / static_cast<double>(ticks);
}

std::optional<std::chrono::microseconds> Lateness::within(double fraction) const {
  std::uint64_t counted = 0;
  for (std::size_t bin = 0; bin < bin_bounds.size(); ++bin) {
    counted += histogram[bin];
    if (static_cast<double>(counted) >= fraction * static_cast<double>(ticks)) return bin_bounds[bin];
  }
  return std::nullopt;
}

std::optional<double> PacingReport::loop_speed() const {
  if (busy_wall <= std::chrono::nanoseconds::zero()) return std::nullopt;
  return busy_model_s / std::chrono::duration<double>(busy_wall).count();
}

std::chrono::nanoseconds Pacer::worst_lateness() const {
  return std::max(report_.first_second.worst, report_.after_first_second.worst);
}

void Pacer::wait_until(double time_s) {
  // Rounded: 0.501 s as a double is a little less than 501 ms, which truncating would take 1 ns early.
  const auto offset = std::chrono::round<Clock::duration>(std::chrono::duration<double>{time_s});
  const Clock::time_point arrived = clock_->now();
  if (!origin_) {
    origin_ = arrived - offset;
    first_time_s_ = time_s;
    last_went_ = arrived;
    last_time_s_ = time_s;
    count(report_.first_second, {});
    return;
  }
  const bool after_first_second = time_s - first_time_s_ >= 1.0;
  if (after_first_second && report_.after_first_second.ticks == 0) previous_late_ = false;  // a stretch of its own
  if (after_first_second) {
    report_.busy_model_s += time_s - last_time_s_;
    const auto busy = std::chrono::duration_cast<std::chrono::nanoseconds>(arrived - last_went_);
    report_.busy_wall += busy;
    report_.longest_busy = std::max(report_.longest_busy, busy);
  }
  const Clock::time_point deadline = *origin_ + offset;
  Clock::time_point went = arrived;
  if (arrived < deadline) {
    clock_->sleep_until(deadline);
    went = clock_->now();  // a wake-up later than the deadline is lateness too
  }
  last_went_ = went;
  last_time_s_ = time_s;
  const auto late_by =
      std::max(std::chrono::nanoseconds::zero(), std::chrono::duration_cast<std::chrono::nanoseconds>(went - deadline));
  count(after_first_second ? report_.after_first_second : report_.first_second, late_by);
}

void Pacer::count(Lateness& lateness, std::chrono::nanoseconds late_by) {
  ++lateness.ticks;
  std::size_t bin = 0;
  while (bin < Lateness::bin_bounds.size() && late_by > Lateness::bin_bounds[bin]) ++bin;
  ++lateness.histogram[bin];
  lateness.worst = std::max(lateness.worst, late_by);
  const bool late = late_by > report_.late_threshold;
  if (late) {
    ++lateness.late;
    if (!previous_late_) ++lateness.late_stretches;
    current_stretch_ = previous_late_ ? current_stretch_ + 1 : 1;
    lateness.longest_stretch = std::max(lateness.longest_stretch, current_stretch_);
  }
  previous_late_ = late;
}

}  // namespace duet::link
