#pragma once
// What happens to the simulated robot during a run: its start, pushes and disturbances, the battery, the wall ahead,
// messages from the Linux side. Read from YAML by load_balbot_scenario (the keys are the member names).

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "duet/support/result.hpp"

namespace duet::plant {

// Where the robot is.
enum class BalbotRig {
  on_ground,      // free: it balances or falls
  held_in_air,    // the body is held still at the initial tilt, the wheels turn freely (no load)
  wheels_driven,  // the body is held still and the wheels are turned at driven_wheel_rev_s (a test rig)
};

struct BalbotPush {  // a horizontal force at the body's centre of mass, towards +x when positive
  double time_s = 0;
  double force_n = 0;
  double duration_s = 0;
};

struct BalbotDutyDisturbance {  // added to both motors' forward duty fraction, like the thesis' z1 (fig. 5.71)
  double time_s = 0;
  double duty = 0;
  double duration_s = 0;
};

struct BalbotIpcMessage {  // bytes the Linux side sends at time_s (at most 496, one RPMsg payload)
  double time_s = 0;
  std::vector<std::uint8_t> bytes;
};

struct BalbotScenario {
  double initial_tilt_deg = 5;  // theta at time 0; positive: the body behind the axle
  // Until then the robot is held still at the initial tilt, wheels on the ground (as one holds it while it starts
  // up); on_ground only.
  double release_time_s = 0;
  std::vector<BalbotPush> pushes;
  std::vector<BalbotDutyDisturbance> duty_disturbances;
  bool noise = true;  // sensor noise on the MPU6500 and the battery ADC
  std::uint64_t seed = 1;
  double battery_v = 7.4;        // open-circuit voltage
  double wall_distance_m = 1.0;  // from the starting position, ahead (+x)
  std::vector<BalbotIpcMessage> ipc_messages;
  double sensor_mount_height_m = 0.075;  // MPU6500 above the axle, along the body
  BalbotRig rig = BalbotRig::on_ground;
  double driven_wheel_rev_s = 0;  // for BalbotRig::wheels_driven: forward wheel speed
};

// Reads a scenario file. Errors name "file:line: the problem"; unknown keys are errors.
[[nodiscard]] Result<BalbotScenario> load_balbot_scenario(const std::string& path);
// The same for text already read; `file` names it in messages.
[[nodiscard]] Result<BalbotScenario> parse_balbot_scenario(const std::string& text, const std::string& file);

}  // namespace duet::plant
