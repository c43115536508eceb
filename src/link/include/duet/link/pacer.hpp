#pragma once
// Real-time pacing: waits until the wall clock reaches a tick's time, counted from the first tick. In lock-step
// nothing waits; in real time a RemotePlant sends each TICK when its time comes, as a timer interrupt would, and a
// plant served with ServeOptions::paced advances when the TICK's time comes (docs/LINK.md, "Pacing").
//
// The pacer also measures how well real time was kept: how late each tick went (after its wait, so a wake-up that
// came late counts too), and how much of the wall time the rest of the loop (the firmware, the emulator, the link,
// the plant) took between two ticks, which says whether it could keep real time at all. The first second is counted
// apart: it holds the start-up (QEMU translating the firmware's code the first time it runs it).

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>

namespace duet::link {

// Where the pacer reads the time and sleeps: the steady clock (not moved by changes of the system's time), or a
// test's.
class PacingClock {
 public:
  using time_point = std::chrono::steady_clock::time_point;
  PacingClock() = default;
  PacingClock(const PacingClock&) = delete;
  PacingClock& operator=(const PacingClock&) = delete;
  virtual ~PacingClock() = default;
  [[nodiscard]] virtual time_point now() = 0;
  virtual void sleep_until(time_point deadline) = 0;
};

PacingClock& steady_pacing_clock();

// How late ticks went, over a stretch of a run.
struct Lateness {
  // Upper bounds of the histogram's bins; the last bin holds what is later than the last bound.
  static constexpr std::array<std::chrono::microseconds, 9> bin_bounds{
      std::chrono::microseconds{100},    std::chrono::microseconds{500},    std::chrono::microseconds{1'000},
      std::chrono::microseconds{2'000},  std::chrono::microseconds{5'000},  std::chrono::microseconds{10'000},
      std::chrono::microseconds{20'000}, std::chrono::microseconds{50'000}, std::chrono::microseconds{100'000}};

  std::uint64_t ticks = 0;
  std::uint64_t late = 0;             // ticks later than the pacer's threshold
  std::chrono::nanoseconds worst{0};  // the latest tick's lateness
  std::uint64_t late_stretches = 0;   // runs of consecutive late ticks: each is one fall behind and its catching up
  std::uint64_t longest_stretch = 0;  // in ticks
  std::array<std::uint64_t, bin_bounds.size() + 1> histogram{};  // ticks by lateness: bin k up to bin_bounds[k]

  // The fraction of ticks that were late (0 without ticks).
  [[nodiscard]] double late_fraction() const;
  // The smallest bin bound that at least `fraction` of the ticks were within; none when that is beyond the last.
  [[nodiscard]] std::optional<std::chrono::microseconds> within(double fraction) const;
};

// What a paced run measured.
struct PacingReport {
  std::chrono::nanoseconds late_threshold{std::chrono::milliseconds{1}};
  Lateness first_second;  // ticks whose time is less than a second after the first tick's
  Lateness after_first_second;
  // After the first second: the model time from the first tick counted there to the last, and the wall time the
  // rest of the loop took over it (between each tick's going and the next tick's arrival, the pacer's sleeps left
  // out). Their ratio is how fast the loop could run without pacing: below 1, it cannot keep real time at all.
  double busy_model_s = 0;
  std::chrono::nanoseconds busy_wall{0};
  std::chrono::nanoseconds longest_busy{0};  // the longest such stretch for one tick: a stall
  // Model seconds per wall second the loop could go (busy_model_s / busy_wall); none before it measured any.
  [[nodiscard]] std::optional<double> loop_speed() const;
};

class Pacer {
 public:
  using Clock = std::chrono::steady_clock;

  // `clock` must outlive the pacer.
  explicit Pacer(PacingClock& clock = steady_pacing_clock()) : clock_(&clock) {}

  // Blocks until `time_s` seconds after the time the first call was made for (the first call returns at once and
  // fixes the origin: now - time_s). A call that comes after its time returns at once; each call is counted by
  // how late it returns.
  void wait_until(double time_s);

  // Ticks later than the threshold (1 ms unless set) in the whole run, and the latest.
  [[nodiscard]] std::uint64_t late() const { return report_.first_second.late + report_.after_first_second.late; }
  [[nodiscard]] std::chrono::nanoseconds worst_lateness() const;
  void set_late_threshold(std::chrono::nanoseconds threshold) { report_.late_threshold = threshold; }
  [[nodiscard]] const PacingReport& report() const { return report_; }

 private:
  void count(Lateness& lateness, std::chrono::nanoseconds late_by);

  PacingClock* clock_;
  std::optional<Clock::time_point> origin_;
  double first_time_s_ = 0;
  Clock::time_point last_went_;  // when the previous tick went
  double last_time_s_ = 0;       // and its time
  bool previous_late_ = false;
  std::uint64_t current_stretch_ = 0;  // late ticks in a row so far
  PacingReport report_;
};

}  // namespace duet::link
