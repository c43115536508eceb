#pragma once
// The motion between two integration points as cubic Hermite polynomials of the normalised time tau in [0, 1], from
// the positions and velocities at both ends.
// Sensors sampled between the points, and encoder edges, are read off these curves, so that an event that changes
// nothing does not cost an integration step.

#include "mechanics.hpp"

namespace duet::plant::balbot {

struct Cubic {
  double c0 = 0, c1 = 0, c2 = 0, c3 = 0;

  [[nodiscard]] double value(double t) const { return c0 + t * (c1 + t * (c2 + t * c3)); }
  [[nodiscard]] double slope(double t) const { return c1 + t * (2 * c2 + t * 3 * c3); }
  [[nodiscard]] double curvature(double t) const { return 2 * c2 + 6 * c3 * t; }
  [[nodiscard]] Cubic scaled(double factor, double offset) const {
    return {c0 * factor + offset, c1 * factor, c2 * factor, c3 * factor};
  }
};

// From the values and the derivatives (per unit of tau) at tau = 0 and tau = 1.
inline Cubic hermite(double p0, double d0, double p1, double d1) {
  return {p0, d0, 3 * (p1 - p0) - 2 * d0 - d1, 2 * (p0 - p1) + d0 + d1};
}

struct Segment {
  Cubic x, theta;
  Cubic wheel;                // the wheels' angle relative to the body
  double inverse_length = 0;  // 1 / h: from d/dtau to d/dt

  Segment() = default;
  Segment(const MechanicalState& s0, const MechanicalState& s1, double h, double wheel_radius)
      : x(hermite(s0.x, h * s0.v, s1.x, h * s1.v)),
        theta(hermite(s0.theta, h * s0.omega, s1.theta, h * s1.omega)),
        inverse_length(1 / h) {
    const double to_angle = 1 / wheel_radius;
    wheel = {x.c0 * to_angle + theta.c0, x.c1 * to_angle + theta.c1, x.c2 * to_angle + theta.c2,
             x.c3 * to_angle + theta.c3};
  }

  // The velocities are the positions' slopes: exact at both ends, within O(h^3) between.
  [[nodiscard]] MechanicalState at(double tau) const {
    return {x.value(tau), theta.value(tau), x.slope(tau) * inverse_length, theta.slope(tau) * inverse_length};
  }
};

}  // namespace duet::plant::balbot
