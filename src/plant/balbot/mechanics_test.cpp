#include "mechanics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "balbot_test_bench.hpp"

namespace duet::plant {
namespace {

using testing::BalbotBench;

BalbotParameters without_friction() {
  BalbotParameters p;
  p.motor_friction_n_m_s_rad = 0;
  return p;
}

TEST(BalbotMechanics, ReleasedAtFiveDegreesWithTheDriverInStandbyTheRobotFalls) {
  BalbotBench bench;  // the driver starts in standby: STBY low
  bench.run_until(0.3);
  const BalbotTruth early = bench.plant.truth();
  EXPECT_TRUE(early.driver_standby);
  EXPECT_GT(early.theta_deg, 10);
  EXPECT_GT(early.theta_dot_deg_s, 0);
  EXPECT_GT(early.x_m, 0);  // the falling body pushes the wheels the other way
  bench.run_until(2.0);
  const BalbotTruth late = bench.plant.truth();
  // Fallen backwards onto the floor (the cuboid's top touches it at acos(-r_w / h) = 96 deg) and lying there.
  EXPECT_GT(late.theta_deg, 90);
  EXPECT_LT(late.theta_deg, 105);
  EXPECT_LT(std::abs(late.theta_dot_deg_s), 5);
}

TEST(BalbotMechanics, AForwardLeanFallsForward) {
  BalbotScenario scenario = BalbotBench::quiet();
  scenario.initial_tilt_deg = -5;
  BalbotBench bench{scenario};
  bench.run_until(0.3);
  EXPECT_LT(bench.plant.truth().theta_deg, -10);
}

TEST(BalbotMechanics, ASmallTiltGrowsAtTheLinearisedRate) {
  // Without friction and with the motors disconnected, theta = theta0 cosh(rate t) for a small theta0.
  BalbotScenario scenario = BalbotBench::quiet();
  scenario.initial_tilt_deg = 0.001;
  const BalbotParameters p = without_friction();
  BalbotBench bench{scenario, p};
  bench.run_until(0.6);
  const double measured = std::acosh(bench.plant.truth().theta_deg / 0.001) / 0.6;
  const double rate = balbot_tilt_growth_rate_per_s(p);
  EXPECT_NEAR(measured, rate, rate * 0.005);
  // With these numbers: sqrt(m_p g l / (J_x + m_p l^2 + J_rotors - (J_rotors / r_w - m_p l)^2 / M_x)) ~ 7.65 / s,
  // between the pendulum on a fixed pivot (sqrt(m_p g l / (J_x + m_p l^2)) = 6.99 / s) and on a free cart.
  EXPECT_NEAR(rate, 7.65, 0.01);
  EXPECT_NEAR(std::sqrt(p.body_mass_kg * p.gravity_m_s2 * p.axle_to_centre_of_mass_m /
                        (p.body_inertia_kg_m2() + p.body_mass_kg * std::pow(p.axle_to_centre_of_mass_m, 2))),
              6.99, 0.01);
}

TEST(BalbotMechanics, EnergyIsConservedWithoutFrictionWithTheMotorsDisconnected) {
  const BalbotParameters p = without_friction();
  const balbot::Mechanics mechanics{p, BalbotRig::on_ground, 7.4};
  const balbot::Drive open = mechanics.prepared({});
  balbot::MechanicalState s{.theta = 5 * std::numbers::pi / 180};
  const double start = mechanics.energy(s);
  double largest_error = 0;
  for (int step = 0; step < 2000 && s.theta < 1.5; ++step) {  // until about 86 deg, before the floor
    s = mechanics.step(s, mechanics.derivative(s, open), open, 1e-3);
    largest_error = std::max(largest_error, std::abs(mechanics.energy(s) - start));
  }
  EXPECT_GT(s.theta, 1.0);                 // it did fall
  EXPECT_LT(largest_error / start, 1e-5);  // the midpoint rule at 1 ms through a whole fall: 1.1e-6 (RK4: 1e-8)
}

TEST(BalbotMechanics, FrictionAndShortedMotorsTakeEnergy) {
  const balbot::Mechanics mechanics{BalbotParameters{}, BalbotRig::on_ground, 7.4};
  const balbot::Drive shorted =
      mechanics.prepared({.left = {.connected = true, .drive = 0}, .right = {.connected = true, .drive = 0}});
  balbot::MechanicalState s{.theta = 5 * std::numbers::pi / 180};
  const double start = mechanics.energy(s);
  for (int step = 0; step < 200; ++step) s = mechanics.step(s, mechanics.derivative(s, shorted), shorted, 1e-3);
  EXPECT_LT(mechanics.energy(s), start - 1e-4);
}

TEST(BalbotMechanics, DrivingForwardMovesForwardAndTiltsTheBodyBack) {
  BalbotScenario scenario = BalbotBench::quiet();
  scenario.initial_tilt_deg = 0;
  BalbotBench bench{scenario};
  bench.drive_forward(50);
  bench.run_until(0.05);
  const BalbotTruth t = bench.plant.truth();
  EXPECT_GT(t.x_m, 0);
  EXPECT_GT(t.v_m_s, 0);
  EXPECT_GT(t.theta_deg, 0);  // the motors' reaction and the wheels' acceleration tip the body backwards
  EXPECT_EQ(t.left.mode, MotorMode::clockwise);
  EXPECT_EQ(t.right.mode, MotorMode::counter_clockwise);
  EXPECT_GT(t.left.speed_rev_s, 0);
  EXPECT_LT(t.right.speed_rev_s, 0);
}

TEST(BalbotMechanics, APushAtTheCentreOfMassLeansTheBodyForward) {
  BalbotScenario scenario = BalbotBench::quiet();
  scenario.initial_tilt_deg = 0;
  scenario.pushes = {{.time_s = 0.1, .force_n = 2, .duration_s = 0.05}};
  BalbotBench bench{scenario};
  bench.run_until(0.1);
  EXPECT_EQ(bench.plant.truth().theta_deg, 0);
  bench.run_until(0.12);
  EXPECT_EQ(bench.plant.truth().push_force_n, 2);
  bench.run_until(0.2);
  EXPECT_EQ(bench.plant.truth().push_force_n, 0);
  EXPECT_LT(bench.plant.truth().theta_deg, -0.5);
}

}  // namespace
}  // namespace duet::plant
