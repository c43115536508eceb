#pragma once
// Real-time pacing for the firmware's side of the link: waits until the wall clock reaches a tick's time, counted
// from the first tick. In lock-step nothing waits; in real time a RemotePlant sends each TICK when its time comes,
// as a timer interrupt would, and the plant on the other side neither knows nor cares.

#include <chrono>
#include <cstdint>
#include <optional>

namespace duet::link {

class Pacer {
 public:
  using Clock = std::chrono::steady_clock;

  // Blocks until `time_s` seconds after the time the first call was made for (the first call returns at once and
  // fixes the origin: now - time_s). A call that comes after its time has passed returns at once and counts as late.
  void wait_until(double time_s);

  // Calls that came after their time (by more than `tolerance`), and the latest they came.
  [[nodiscard]] std::uint64_t late() const { return late_; }
  [[nodiscard]] std::chrono::nanoseconds worst_lateness() const { return worst_; }
  void set_tolerance(std::chrono::nanoseconds tolerance) { tolerance_ = tolerance; }

 private:
  std::optional<Clock::time_point> origin_;
  std::uint64_t late_ = 0;
  std::chrono::nanoseconds worst_{0};
  std::chrono::nanoseconds tolerance_{std::chrono::microseconds{100}};
};

}  // namespace duet::link
