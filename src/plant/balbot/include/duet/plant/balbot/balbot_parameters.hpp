#pragma once
// The simulated self-balancing robot's physical constants. Where each number comes from (thesis, data sheet, or
// chosen and why) is in src/plant/balbot/README.md; the defaults are the robot of the thesis.

namespace duet::plant {

struct BalbotParameters {
  // Mechanics (thesis section 5.8, eqs. 5.17-5.29).
  double wheel_mass_kg = 0.090;                              // m_w, both wheels together
  double body_mass_kg = 0.706;                               // m_p
  double axle_to_centre_of_mass_m = 0.1485;                  // l
  double body_depth_m = 0.070;                               // b of the cuboid
  double body_height_m = 2 * 0.1485;                         // h of the cuboid: chosen 2 l (centre of mass mid-height)
  double wheel_radius_m = 0.031;                             // r_w
  double gravity_m_s2 = 9.81;                                // g
  double wheel_inertia_kg_m2 = 0.5 * 0.090 * 0.031 * 0.031;  // both wheels as solid discs about the axle
  // A fallen robot lies on the floor: past the tilt where the cuboid's top touches it (acos(-r_w / h), 96 deg) a
  // stiff, damped contact torque holds the body (chosen; it only shapes what happens after a fall).
  double floor_stiffness_n_m_rad = 20;
  double floor_damping_n_m_s_rad = 0.5;

  // Drive: two DC motors with 1:30 gearboxes on a TB6612FNG, a 2S lithium-ion battery.
  double gear_ratio = 30;                    // motor turns per wheel turn
  double motor_constant_v_s_rad = 8.334e-3;  // k_t = k_e (N m/A = V s/rad), at the motor shaft
  double armature_resistance_ohm = 4.0;      // winding plus the driver's two switches
  double rotor_inertia_kg_m2 = 4.0e-7;       // one motor's rotor and gears, at the motor shaft
  double motor_friction_n_m_s_rad = 1.0e-6;  // viscous, at the motor shaft (brushes, bearings, gearbox)
  double battery_resistance_ohm = 0.2;       // cells, wiring and switch

  // Sensors.
  int hall_edges_per_wheel_turn = 450;  // rising edges of A: 15 per motor turn x 30
  double mpu_int_pulse_s = 50e-6;       // INT pulse when not latched (MPU6500 data sheet)
  double mpu_reset_hold_s = 0.100;      // SPI ignored after a device reset
  double mpu_clock_phase_s = 0.37e-3;   // first sample after power-on, reset or wake-up (chosen: the
                                        // sensor's clock is not the MCU's, so samples fall between ticks)
  double mpu_temperature_c = 25;
  double accel_noise_g = 0.01561;           // per axis: atan(a_x/a_z) variance 0.8 deg^2 at rest (thesis 5.11)
  double gyro_noise_deg_s = 0.01791;        // per axis: after 16.4 LSB/(deg/s) rounding, 330e-6 (deg/s)^2
  double spi_clock_hz = 1e6;                // SPI5, reads and writes
  double ultrasonic_echo_delay_s = 250e-6;  // TRIG falling edge to ECHO rising edge
  double speed_of_sound_m_s = 340;
  double adc_conversion_s = 15e-6;  // one battery conversion
  double adc_noise_counts = 3;      // standard deviation of one conversion
  double adc_reference_v = 3.3;
  double battery_divider_ratio = 3.83;  // (R46 + R47) / R46

  [[nodiscard]] double body_inertia_kg_m2() const {  // J_x, eq. 5.17
    return body_mass_kg * (body_depth_m * body_depth_m + body_height_m * body_height_m) / 12;
  }
};

// The rate (1/s) at which a small tilt grows when the robot stands on the ground with both motors disconnected and
// without friction: theta ~ exp(rate t). From the linearised equations of motion of src/plant/balbot/README.md.
[[nodiscard]] double balbot_tilt_growth_rate_per_s(const BalbotParameters& parameters);

}  // namespace duet::plant
