#include "duet/plant/balbot/balbot_scenario.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

namespace duet::plant {
namespace {

Result<BalbotScenario> parse(const std::string& text) { return parse_balbot_scenario(text, "s.yaml"); }

std::string error_of(const std::string& text) {
  const Result<BalbotScenario> result = parse(text);
  return result.ok() ? "(no error)" : result.error();
}

TEST(BalbotScenario, AnEmptyFileGivesTheDefaults) {
  const Result<BalbotScenario> s = parse("");
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.value().initial_tilt_deg, 5);
  EXPECT_TRUE(s.value().noise);
  EXPECT_EQ(s.value().battery_v, 7.4);
  EXPECT_EQ(s.value().wall_distance_m, 1.0);
  EXPECT_EQ(s.value().rig, BalbotRig::on_ground);
  EXPECT_TRUE(s.value().pushes.empty());
}

TEST(BalbotScenario, EveryKeyIsRead) {
  const Result<BalbotScenario> s = parse(
      "initial_tilt_deg: -3.5\n"
      "pushes:\n"
      "  - {time_s: 2, force_n: -1.5, duration_s: 0.1}\n"
      "duty_disturbances:\n"
      "  - {time_s: 1, duty: 1, duration_s: 0.001}\n"
      "noise: false\n"
      "seed: 18446744073709551615\n"
      "battery_v: 8.2\n"
      "wall_distance_m: 0.5\n"
      "ipc_messages:\n"
      "  - {time_s: 0.5, bytes: [1, 2, 255]}\n"
      "sensor_mount_height_m: 0.1\n"
      "rig: wheels_driven\n"
      "driven_wheel_rev_s: -2\n");
  ASSERT_TRUE(s.ok()) << s.error();
  const BalbotScenario& v = s.value();
  EXPECT_EQ(v.initial_tilt_deg, -3.5);
  ASSERT_EQ(v.pushes.size(), 1U);
  EXPECT_EQ(v.pushes[0].time_s, 2);
  EXPECT_EQ(v.pushes[0].force_n, -1.5);
  EXPECT_EQ(v.pushes[0].duration_s, 0.1);
  ASSERT_EQ(v.duty_disturbances.size(), 1U);
  EXPECT_EQ(v.duty_disturbances[0].duty, 1);
  EXPECT_FALSE(v.noise);
  EXPECT_EQ(v.seed, 18446744073709551615ULL);
  EXPECT_EQ(v.battery_v, 8.2);
  EXPECT_EQ(v.wall_distance_m, 0.5);
  ASSERT_EQ(v.ipc_messages.size(), 1U);
  EXPECT_EQ(v.ipc_messages[0].bytes, (std::vector<std::uint8_t>{1, 2, 255}));
  EXPECT_EQ(v.sensor_mount_height_m, 0.1);
  EXPECT_EQ(v.rig, BalbotRig::wheels_driven);
  EXPECT_EQ(v.driven_wheel_rev_s, -2);
}

TEST(BalbotScenario, ProblemsNameTheFileAndLine) {
  EXPECT_EQ(error_of("noise: false\nintial_tilt_deg: 3\n"),
            "s.yaml:2: unknown key 'intial_tilt_deg' (did you mean 'initial_tilt_deg'?)");
  EXPECT_EQ(error_of("bogus: 1\n").substr(0, 29), "s.yaml:1: unknown key 'bogus'");
  EXPECT_EQ(error_of("battery_v: lots\n"), "s.yaml:1: battery_v: expected a number, got 'lots'");
  EXPECT_EQ(error_of("battery_v: 20\n"), "s.yaml:1: battery_v: 20 is outside 0.1..12.6");
  EXPECT_EQ(error_of("noise: maybe\n"), "s.yaml:1: noise: expected true or false, got 'maybe'");
  EXPECT_EQ(error_of("seed: -1\n"), "s.yaml:1: seed: expected a whole number 0..18446744073709551615, got '-1'");
  EXPECT_EQ(error_of("pushes:\n  - {time_s: 1, force_n: 2}\n"), "s.yaml:2: pushes[0]: 'duration_s' is missing");
  EXPECT_EQ(error_of("pushes:\n  - {time_s: 1, force: 2, duration_s: 1}\n"),
            "s.yaml:2: pushes[0]: unknown key 'force' (did you mean 'force_n'?)");
  EXPECT_EQ(error_of("pushes: 3\n"), "s.yaml:1: pushes: expected a list");
  EXPECT_EQ(error_of("duty_disturbances:\n  - {time_s: 1, duty: 2, duration_s: 1}\n"),
            "s.yaml:2: duty_disturbances[0]: duty: 2 is outside -1..1");
  EXPECT_EQ(error_of("ipc_messages:\n  - time_s: 1\n    bytes: [1, 256]\n"),
            "s.yaml:3: ipc_messages[0]: bytes[1]: 256 is more than 255");
  EXPECT_EQ(error_of("rig: upside_down\n"),
            "s.yaml:1: rig: expected on_ground, held_in_air or wheels_driven, got 'upside_down'");
  EXPECT_EQ(error_of("initial_tilt_deg: 95\n"), "s.yaml:1: initial_tilt_deg: 95 is outside -89..89");
  EXPECT_EQ(error_of("- 1\n"), "s.yaml:1: expected a map of scenario keys");
  EXPECT_EQ(error_of("a: [1,\n"), "s.yaml:2: end of sequence flow not found");
}

TEST(BalbotScenario, IsLoadedFromAFile) {
  const std::string path = ::testing::TempDir() + "balbot_scenario_test.yaml";
  {
    std::ofstream out{path};
    out << "wall_distance_m: 0.25\nseed: 9\n";
  }
  const Result<BalbotScenario> s = load_balbot_scenario(path);
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(s.value().wall_distance_m, 0.25);
  EXPECT_EQ(s.value().seed, 9U);
  std::remove(path.c_str());
  EXPECT_EQ(load_balbot_scenario(path).error(), path + ": cannot open");
}

}  // namespace
}  // namespace duet::plant
