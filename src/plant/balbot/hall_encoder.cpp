#include "hall_encoder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace duet::plant::balbot {
namespace {

// Larger than the phase the wheel turns in the half nanosecond an edge's time is rounded by (1e-6 cycles at full
// speed), and than the difference between the interpolated and the integrated motion where a segment is split.
constexpr double hysteresis_cycles = 1e-4;

// The root of p(t) = level in [a, b], where p is monotone and p(a) - level, p(b) - level differ in sign: Newton's
// method from the linear interpolation, kept inside the bracket (bisecting when a step would leave it).
double root(const Cubic& p, double level, double a, double b, double pa, double pb) {
  double low = a;
  double high = b;
  const bool rising = pb > pa;
  double t = pb != pa ? a + (b - a) * std::clamp((level - pa) / (pb - pa), 0.0, 1.0) : a;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double error = p.value(t) - level;
    // 1e-7 cycles: far inside the hysteresis; in time, below a nanosecond down to 100 cycles of A per second.
    if (std::abs(error) < 1e-7) return t;
    if ((error < 0) == rising) {
      low = t;
    } else {
      high = t;
    }
    const double slope = p.slope(t);
    double next = slope != 0 ? t - error / slope : 0.5 * (low + high);
    if (!(next > low && next < high)) next = 0.5 * (low + high);
    if (std::abs(next - t) < 1e-10) return next;  // 1e-10 of a 1 ms step: far below the 1 ns of an edge's time
    t = next;
  }
  return t;
}

}  // namespace

TurningPoints turning_points(const Cubic& wheel_angle) {
  TurningPoints turns;
  turns.bounds[turns.count++] = 0;
  const auto add = [&turns](double t) {
    if (t > 0 && t < 1) turns.bounds[turns.count++] = t;
  };
  const double qa = 3 * wheel_angle.c3;
  const double qb = 2 * wheel_angle.c2;
  const double qc = wheel_angle.c1;
  if (qa != 0) {
    const double discriminant = qb * qb - 4 * qa * qc;
    if (discriminant > 0) {
      const double q = -0.5 * (qb + std::copysign(std::sqrt(discriminant), qb));
      add(q / qa);
      if (q != 0) add(qc / q);
    }
  } else if (qb != 0) {
    add(-qc / qb);
  }
  if (turns.count == 3 && turns.bounds[2] < turns.bounds[1]) std::swap(turns.bounds[1], turns.bounds[2]);
  turns.bounds[turns.count++] = 1;
  for (std::size_t i = 0; i < turns.count; ++i) turns.angles[i] = wheel_angle.value(turns.bounds[i]);
  return turns;
}

HallEncoder::HallEncoder(double direction, int edges_per_turn, double phase_offset_cycles)
    : cycles_per_radian_(direction * edges_per_turn / (2 * std::numbers::pi)), offset_(phase_offset_cycles) {}

void HallEncoder::start(double wheel_angle) {
  half_cycle_ = static_cast<std::int64_t>(std::floor(2 * (wheel_angle * cycles_per_radian_ + offset_)));
  planned_ = applied_ = event_ = 0;
}

void HallEncoder::plan(const Cubic& wheel_angle, const TurningPoints& turns, Nanoseconds start, Nanoseconds length,
                       double from) {
  planned_ = applied_ = event_ = 0;
  const double up_first = 0.5 * static_cast<double>(half_cycle_ + 1) + hysteresis_cycles;
  const double down_first = 0.5 * static_cast<double>(half_cycle_) - hysteresis_cycles;
  bool stays = from == 0;  // most segments cross nothing: the extremes tell at once
  for (std::size_t i = 0; stays && i < turns.count; ++i) {
    const double phase = turns.angles[i] * cycles_per_radian_ + offset_;
    stays = phase < up_first && phase > down_first;
  }
  if (stays) return;
  const Cubic phase = wheel_angle.scaled(cycles_per_radian_, offset_);
  std::int64_t half_cycle = half_cycle_;
  const auto add = [&](double tau, bool upward) {
    half_cycle += upward ? 1 : -1;
    const Nanoseconds time = start + std::llround(tau * static_cast<double>(length));
    plan_[planned_++] = {tau, time, upward, (half_cycle & 1) == 0};
    return planned_ < most_planned;
  };
  for (std::size_t piece = 0; piece + 1 < turns.count; ++piece) {
    double a = std::max(turns.bounds[piece], from);
    const double b = turns.bounds[piece + 1];
    if (a >= b) continue;
    double pa = phase.value(a);
    const double pb = phase.value(b);
    // Monotone on [a, b]: cross the boundaries between pa and pb one after the other.
    for (;;) {
      const double up = 0.5 * static_cast<double>(half_cycle + 1) + hysteresis_cycles;
      const double down = 0.5 * static_cast<double>(half_cycle) - hysteresis_cycles;
      bool upward = false;
      double level = 0;
      if (pb >= up) {
        upward = true;
        level = up;
      } else if (pb <= down) {
        level = down;
      } else {
        break;
      }
      const double tau = (upward ? pa >= level : pa <= level) ? a : root(phase, level, a, b, pa, pb);
      if (!add(tau, upward)) break;
      a = tau;
      pa = level;
    }
    if (planned_ == most_planned) break;
  }
  event_ = applied_;
  while (event_ < planned_ && !plan_[event_].rising && event_ + 1 < most_planned) ++event_;
}

std::optional<HallCrossing> HallEncoder::next_event() const {
  if (event_ >= planned_) return std::nullopt;
  return plan_[event_];
}

HallEncoder::Taken HallEncoder::take_next() {
  Taken taken;
  if (event_ >= planned_) return taken;
  for (; applied_ <= event_; ++applied_) half_cycle_ += plan_[applied_].upward ? 1 : -1;
  taken.rising_edge = plan_[event_].rising;
  taken.tau = plan_[event_].tau;
  taken.plan_again = planned_ == most_planned && applied_ == planned_;
  event_ = applied_;
  while (event_ < planned_ && !plan_[event_].rising && event_ + 1 < most_planned) ++event_;
  return taken;
}

void HallEncoder::apply_before(Nanoseconds time) {
  for (; applied_ < planned_ && plan_[applied_].time < time; ++applied_) {
    half_cycle_ += plan_[applied_].upward ? 1 : -1;
  }
  planned_ = applied_ = event_ = 0;
}

bool HallEncoder::b_high(double wheel_angle) const {
  const double phase = wheel_angle * cycles_per_radian_ + offset_;
  const double within = phase - std::floor(phase);
  return within >= 0.25 && within < 0.75;
}

}  // namespace duet::plant::balbot
