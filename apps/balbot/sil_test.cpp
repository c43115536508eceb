// Software in the loop: balbot_sil, the generated firmware on the PC, records what duet sim records for the model,
// bit for bit; over the link to `duet plant serve balbot` it balances the robot and ends where the run in one process
// ends. Both programs run as child processes, as a user runs them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "child_program.hpp"
#include "duet/link/tcp.hpp"
#include "duet/model/model_file.hpp"
#include "duet/model/program.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plant/balbot/balbot_plant.hpp"
#include "duet/plant/balbot/balbot_scenario.hpp"
#include "duet/plot/csv.hpp"
#include "duet/support/text_file.hpp"
#include "recorded_daq_step.hpp"
#include "sil_run.hpp"

namespace duet::sil {
namespace {

Program balbot_sil(const std::vector<std::string>& arguments, const std::string& name) {
  return Program{BALBOT_SIL_PROGRAM, arguments, name};
}

plant::BalbotScenario release_scenario() {
  auto scenario = plant::load_balbot_scenario(DUET_BALBOT_SCENARIO);
  EXPECT_TRUE(scenario.ok()) << scenario.error();
  return scenario ? scenario.value() : plant::BalbotScenario{};
}

TEST(BalbotSil, TheFirmwareOnThePcRecordsWhatDuetSimRecords) {
  const TemporaryFile csv{"firmware.csv"};
  Program program = balbot_sil(
      {"--plant", "balbot", "--scenario", DUET_BALBOT_SCENARIO, "--duration", "10", "--csv", csv.path()}, "same");
  ASSERT_TRUE(program.started());
  const std::string summary = program.line();
  ASSERT_EQ(program.wait(), 0) << program.errors();
  EXPECT_TRUE(summary.starts_with("balbot_sil: 10001 ticks (lock-step, plant balbot in process); final theta "))
      << summary;

  auto model = model::load_model(DUET_BALBOT_MODEL);
  ASSERT_TRUE(model.ok()) << model.error();
  const model::ProgramBuild build = model::build_program(model.value());
  ASSERT_TRUE(build.program.has_value());
  const auto robot = plant::make_balbot_plant(release_scenario());
  model::SimulationOptions options;
  options.duration_s = 10;
  options.record_plant = false;  // the firmware's measurable signals only
  auto simulated = model::simulate(*build.program, *robot, options);
  ASSERT_TRUE(simulated.ok()) << simulated.error();
  const std::string expected = model::to_csv(simulated.value().recording);

  auto written = read_text_file(csv.path());
  ASSERT_TRUE(written.ok()) << written.error();
  const std::string& actual = written.value();
  if (actual != expected) {  // say where, not the megabytes
    const auto [differs, _] = std::mismatch(expected.begin(), expected.end(), actual.begin(), actual.end());
    const auto line = std::count(expected.begin(), differs, '\n') + 1;
    const auto start = expected.rfind('\n', static_cast<std::size_t>(differs - expected.begin()));
    const auto begin = start == std::string::npos ? 0 : start + 1;
    FAIL() << "line " << line << " differs; duet sim: " << expected.substr(begin, expected.find('\n', begin) - begin);
  }
  EXPECT_GT(number_after(summary, "largest |theta| after 4 s "), 0.0);  // it moved, and stayed up:
  EXPECT_LT(number_after(summary, "largest |theta| after 4 s "), 1.0);
}

TEST(BalbotSil, OverTheLinkItBalancesAndEndsWhereTheRunInOneProcessEnds) {
  const TemporaryFile robot_csv{"robot.csv"};
  Program server{DUET_PROGRAM,
                 {"plant", "serve", "balbot", "--scenario", DUET_BALBOT_SCENARIO, "--listen", "127.0.0.1:0", "--once",
                  "--csv", robot_csv.path()},
                 "server"};
  ASSERT_TRUE(server.started());
  const std::string address = listening_address(server);
  ASSERT_FALSE(address.empty());

  Program firmware = balbot_sil({"--link", address, "--duration", "5"}, "firmware");
  ASSERT_TRUE(firmware.started());
  const std::string summary = firmware.line();
  ASSERT_EQ(firmware.wait(), 0) << firmware.errors();
  const std::string served = server.line();
  ASSERT_EQ(server.wait(), 0) << server.errors();
  EXPECT_TRUE(summary.starts_with("balbot_sil: 5001 ticks (lock-step, plant at " + address + "); final theta "))
      << summary;
  EXPECT_NE(served.find(": 5001 ticks, "), std::string::npos) << served;

  // The robot's own view (the server's CSV): standing, 2 s after the release and on.
  auto text = read_text_file(robot_csv.path());
  ASSERT_TRUE(text.ok()) << text.error();
  auto robot = plot::read_csv(text.value(), robot_csv.path());
  ASSERT_TRUE(robot.ok()) << robot.error();
  ASSERT_EQ(robot.value().time.size(), 5001U);
  const auto theta = std::find_if(robot.value().series.begin(), robot.value().series.end(),
                                  [](const plot::Series& series) { return series.name == "theta_deg"; });
  ASSERT_NE(theta, robot.value().series.end());
  EXPECT_EQ(theta->values.front(), 5.0);  // held at 5 degrees at first
  double largest = 0;
  for (std::size_t k = 4000; k < theta->values.size(); ++k) largest = std::max(largest, std::abs(theta->values[k]));
  EXPECT_LT(largest, 1.0);

  // In lock-step the link changes nothing: the firmware ends where it ends against the robot in this process.
  const auto local = plant::make_balbot_plant(release_scenario());
  auto in_process = run_sil(*local, {.duration_s = 5});
  ASSERT_TRUE(in_process.ok()) << in_process.error();
  EXPECT_EQ(in_process.value().ticks, 5001U);
  EXPECT_TRUE(same_bits(number_after(summary, "final theta "), in_process.value().final_theta_deg))
      << summary << " against " << in_process.value().final_theta_deg;
  ASSERT_TRUE(in_process.value().largest_theta_after_4_s_deg.has_value());
  EXPECT_TRUE(
      same_bits(number_after(summary, "largest |theta| after 4 s "), *in_process.value().largest_theta_after_4_s_deg))
      << summary;
}

TEST(BalbotSil, BadCommandLinesAndAMissingPlantSayWhatIsWrong) {
  Program both = balbot_sil({"--plant", "balbot", "--link", "127.0.0.1:5601"}, "both");
  EXPECT_EQ(both.wait(), 2);
  EXPECT_NE(both.errors().find("excludes"), std::string::npos) << both.errors();

  Program scenario_alone = balbot_sil({"--scenario", DUET_BALBOT_SCENARIO}, "scenario");
  EXPECT_EQ(scenario_alone.wait(), 2);
  EXPECT_NE(scenario_alone.errors().find("requires --plant"), std::string::npos) << scenario_alone.errors();

  Program bad_address = balbot_sil({"--link", "localhost"}, "address");
  EXPECT_EQ(bad_address.wait(), 2);
  EXPECT_NE(bad_address.errors().find("'localhost' is not HOST:PORT"), std::string::npos) << bad_address.errors();

  Program unknown_plant = balbot_sil({"--plant", "balbott"}, "unknown");
  EXPECT_EQ(unknown_plant.wait(), 1);
  EXPECT_EQ(unknown_plant.errors(), "balbot_sil: unknown plant 'balbott' (did you mean 'balbot'?)\n");

  // A port nobody listens on: the one a listener had a moment ago.
  std::string address;
  {
    auto listener = link::TcpListener::open({"127.0.0.1", 0});
    ASSERT_TRUE(listener.ok()) << listener.error();
    address = link::to_string(listener.value().address());
  }
  Program nobody = balbot_sil({"--link", address, "--duration", "1"}, "nobody");
  EXPECT_EQ(nobody.line(), "");
  EXPECT_EQ(nobody.wait(), 1);
  EXPECT_TRUE(nobody.errors().starts_with("balbot_sil: ")) << nobody.errors();
  EXPECT_NE(nobody.errors().find(address), std::string::npos) << nobody.errors();
}

TEST(BalbotSil, InRealTimeTheTicksFollowTheWallClock) {
  const auto start = std::chrono::steady_clock::now();
  Program program = balbot_sil({"--plant", "balbot", "--duration", "0.3", "--real-time"}, "real_time");
  const std::string summary = program.line();
  EXPECT_EQ(program.wait(), 0) << program.errors();
  EXPECT_GE(std::chrono::steady_clock::now() - start, 300ms);
  EXPECT_TRUE(summary.starts_with("balbot_sil: 301 ticks (real time, ")) << summary;
  EXPECT_NE(summary.find("largest |theta| after 4 s none"), std::string::npos) << summary;
}

// DAQ timestamps are the executive's time on the PC too: the 1 ms task's samples advance by 1 ms on average.
TEST(BalbotSil, DaqTimestampsOfTheMillisecondTaskAdvanceByItsPeriod) {
  Program program =
      balbot_sil({"--plant", "balbot", "--duration", "15", "--real-time", "--xcp", "127.0.0.1:0"}, "sil_daq");
  const std::string xcp = program.line();  // "balbot_sil: XCP on tcp://HOST:PORT"
  const std::size_t url = xcp.find("tcp://");
  ASSERT_NE(url, std::string::npos) << xcp;
  EXPECT_NEAR(recorded_daq_step(DUET_BALBOT_A2L, xcp.substr(url)), 1e-3, 1e-7);
}

}  // namespace
}  // namespace duet::sil
