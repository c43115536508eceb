// The robot's linear model: its unstable pole by hand, its equations of motion, and the motor's steady state.
#include "duet/control/balbot_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "duet/control/riccati.hpp"

namespace duet::control {
namespace {

TEST(BalbotModel, TheThesisBodyInertia) {
  // J_x = m_p (b^2 + h^2) / 12 with h = 2 l = 0.297 m: 0.706 (0.0049 + 0.088209) / 12 = 0.00547791 kg m^2.
  EXPECT_NEAR(body_inertia({}), 0.00547791, 1e-8);
  EXPECT_EQ(body_inertia({.body_inertia = 0.01}), 0.01);
}

// The thesis' robot: no wheel or rotor inertia, and here no motor (no torque, no drag).
constexpr BalbotParameters thesis_without_motor{
    .wheel_inertia = 0, .torque_constant = 0, .rotor_inertia = 0, .motor_friction = 0};

TEST(BalbotModel, WithoutMotorTheUprightPoleIsTheCartPendulums) {
  // No torque: x_w'' = m_p l theta'' / M (eq. 5.33a with F = 0, M = m_w + m_p), so (eq. 5.33b)
  // (J_x + m_p l^2 - m_p^2 l^2 / M) theta'' = m_p g l theta, and theta grows as e^(p t) with
  //   p = sqrt(m_p g l / (J_x + m_p l^2 - m_p^2 l^2 / M))
  //     = sqrt(1.0284902 / (0.0054779 + 0.0155689 - 0.0109917 / 0.796)) = sqrt(142.09) = 11.920 rad/s,
  // faster than the pendulum on a fixed axle, sqrt(m_p g l / (J_x + m_p l^2)) = sqrt(48.87) = 6.990 rad/s, because the
  // wheels give way under it. The other poles are 0 and 0 (position and speed: nothing brakes the wheels) and -p.
  auto model = linearise_balbot(thesis_without_motor);
  ASSERT_TRUE(model) << model.error();
  EXPECT_EQ(model.value().b.norm(), 0);
  const Eigen::VectorXcd poles = sorted_eigenvalues(model.value().a);
  EXPECT_NEAR(poles(0).real(), 11.920, 1e-3);
  EXPECT_NEAR(poles(1).real(), -11.920, 1e-3);
  EXPECT_NEAR(std::abs(poles(2)), 0, 1e-9);
  EXPECT_NEAR(std::abs(poles(3)), 0, 1e-9);
  // Very heavy wheels stand still: the fixed-axle pendulum.
  BalbotParameters pinned = thesis_without_motor;
  pinned.wheel_mass = 1e9;
  auto fixed = linearise_balbot(pinned);
  ASSERT_TRUE(fixed) << fixed.error();
  EXPECT_NEAR(sorted_eigenvalues(fixed.value().a)(0).real(), 6.990, 1e-3);
}

TEST(BalbotModel, TheRotorsSlowTheFall) {
  // With solid-disc wheels (J_w = 0.5 m_w r_w^2 = 4.3245e-5) and the rotors (J_r = 2 * 30^2 * 4e-7 = 7.2e-4 seen from
  // the wheels, turning with the wheels relative to the body), still without torque:
  //   M_xx = 0.796 + (4.3245e-5 + 7.2e-4) / 0.031^2 = 1.59022, M_xt = 7.2e-4 / 0.031 - 0.104841 = -0.0816152,
  //   M_tt = 0.0210468 + 7.2e-4 = 0.0217668, det = M_xx M_tt - M_xt^2 = 0.0279530,
  //   p = sqrt(m_p g l M_xx / det) = sqrt(1.0284902 * 1.59022 / 0.0279530) = 7.649 rad/s.
  BalbotParameters robot = thesis_without_motor;
  robot.wheel_inertia = 0.5 * 0.090 * 0.031 * 0.031;
  robot.rotor_inertia = 4e-7;
  auto model = linearise_balbot(robot);
  ASSERT_TRUE(model) << model.error();
  EXPECT_NEAR(sorted_eigenvalues(model.value().a)(0).real(), 7.649, 1e-3);
}

TEST(BalbotModel, TheAccelerationsObeyTheEquationsOfMotion) {
  // At rest and upright the torque is the stall torque, tau = motors gear_ratio k_t u / R, and the accelerations must
  // satisfy M_xx x_w'' + M_xt theta'' = tau / r_w and M_xt x_w'' + M_tt theta'' = tau (the header's equations).
  const BalbotParameters robot;  // the defaults: wheels and rotors with inertia
  auto model = linearise_balbot(robot);
  ASSERT_TRUE(model) << model.error();
  const double volts = 2;
  const double x_acceleration = model.value().b(1, 0) * volts;
  const double theta_acceleration = model.value().b(3, 0) * volts;
  const double tau = 2 * 30 * robot.torque_constant * volts / robot.armature_resistance;
  const double l = robot.axle_to_centre_of_mass;
  const double r_w = robot.wheel_radius;
  const double rotors = 2 * 30 * 30 * robot.rotor_inertia;
  const double m_xx = robot.wheel_mass + robot.body_mass + (robot.wheel_inertia + rotors) / (r_w * r_w);
  const double m_xt = rotors / r_w - robot.body_mass * l;
  const double m_tt = body_inertia(robot) + robot.body_mass * l * l + rotors;
  EXPECT_NEAR(m_xx * x_acceleration + m_xt * theta_acceleration, tau / r_w, 1e-12);
  EXPECT_NEAR(m_xt * x_acceleration + m_tt * theta_acceleration, tau, 1e-12);
  // Forward voltage drives forward and tilts the body back (theta grows).
  EXPECT_GT(x_acceleration, 0);
  EXPECT_GT(theta_acceleration, 0);
}

TEST(BalbotModel, UprightAtFullSpeedTheMotorsBalanceTheirBackEmf) {
  // Rolling upright at v = r_w u / (gear_ratio k_e) the back-EMF equals u: without friction no current, no torque,
  // nothing accelerates.
  const BalbotParameters robot{.motor_friction = 0, .volts_per_input = 7.4};  // the input: duty of a 7.4 V battery
  auto model = linearise_balbot(robot);
  ASSERT_TRUE(model) << model.error();
  const double duty = 0.5;
  const double speed = robot.wheel_radius * duty * 7.4 / (robot.gear_ratio * robot.back_emf_constant);
  const Eigen::Vector4d state{0, speed, 0, 0};
  const Eigen::Vector4d derivative = model.value().a * state + model.value().b * duty;
  EXPECT_NEAR(derivative(0), speed, 1e-15);
  EXPECT_NEAR(derivative(1), 0, 1e-12);
  EXPECT_NEAR(derivative(2), 0, 1e-15);
  EXPECT_NEAR(derivative(3), 0, 1e-12);
}

TEST(BalbotModel, RefusesImpossibleParameters) {
  auto massless = linearise_balbot({.body_mass = 0});
  ASSERT_FALSE(massless);
  EXPECT_EQ(massless.error(), "body_mass must be a positive number; it is 0");
  auto no_motor = linearise_balbot({.motors = 0});
  ASSERT_FALSE(no_motor);
  EXPECT_EQ(no_motor.error(), "motors must be 1 or more; it is 0");
}

}  // namespace
}  // namespace duet::control
