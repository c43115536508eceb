// The executive's account as duet monitor finds it in an A2L that duet gen wrote (the robot's, committed) and reads
// it from the bytes of duet/rt/executive_account.hpp's struct.
#include "duet/monitor/executive_account_layout.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "duet/model/generate.hpp"
#include "duet/rt/executive_account.hpp"
#include "duet/support/text_file.hpp"

namespace duet::monitor {
namespace {

using xcp::host::A2lDescription;

A2lDescription robot_a2l() {
  const std::string file = std::string{DUET_SOURCE_DIR} + "/apps/balbot/generated/balbot.a2l";
  auto text = read_text_file(file);
  EXPECT_TRUE(text.ok()) << text.error();
  auto a2l = xcp::host::read_a2l(text.value(), file);
  EXPECT_TRUE(a2l.ok()) << a2l.error();
  return a2l.value();
}

TEST(ExecutiveAccountLayout, ReadsTheAccountDuetGenDescribes) {
  const A2lDescription a2l = robot_a2l();
  const auto layout = ExecutiveAccountLayout::from(a2l);
  ASSERT_TRUE(layout);
  rt::ExecutiveAccount<11> account{};
  EXPECT_EQ(layout->segment().size, sizeof account);
  account.ticks = 4000;
  account.busy_ppm = 52'000;
  account.overruns = 3;
  account.cycle_hz = 25'000'000;
  account.tasks[0] = {4000, 1, 100, 125, 250};
  account.tasks[10] = {7, 2, 2500, 2600, 2750};
  std::vector<std::uint8_t> bytes(sizeof account);
  std::memcpy(bytes.data(), &account, sizeof account);  // the target's bytes: little-endian, as the PC's

  const nlohmann::json decoded = layout->decode(bytes, 1'000'000);  // 1 ms
  EXPECT_DOUBLE_EQ(decoded["time_s"].get<double>(), 4.0);
  EXPECT_DOUBLE_EQ(decoded["core_load"].get<double>(), 0.052);
  EXPECT_EQ(decoded["overruns"], 3);
  ASSERT_EQ(decoded["tasks"].size(), 11U);
  EXPECT_EQ(decoded["tasks"][0]["name"], "rate 1");  // the event's name, not the identifier rate_1
  EXPECT_DOUBLE_EQ(decoded["tasks"][0]["max_us"].get<double>(), 10.0);
  EXPECT_EQ(decoded["tasks"][10]["name"], "IPCC_RX1");
  EXPECT_DOUBLE_EQ(decoded["tasks"][10]["min_us"].get<double>(), 100.0);
  EXPECT_EQ(decoded["tasks"][10]["overruns"], 2);
}

TEST(ExecutiveAccountLayout, TheAccountIsNoSignal) {
  const A2lDescription a2l = robot_a2l();
  const auto account = std::count_if(a2l.measurements.begin(), a2l.measurements.end(), [&](const auto& measurement) {
    return model::is_executive_account(a2l, measurement);
  });
  EXPECT_EQ(account, 4 + 11 * 5);
}

TEST(ExecutiveAccountLayout, ASignalNamedLikeTheAccountIsStillTheModels) {
  A2lDescription a2l = robot_a2l();
  const auto signal = std::find_if(a2l.measurements.begin(), a2l.measurements.end(), [&](const auto& measurement) {
    return !model::is_executive_account(a2l, measurement);
  });
  ASSERT_NE(signal, a2l.measurements.end());
  signal->name = "executive.speed";  // a model's subsystem may be called "executive": the place decides
  EXPECT_FALSE(model::is_executive_account(a2l, *signal));
}

TEST(ExecutiveAccountLayout, AnA2lWithoutOneHasNone) {
  A2lDescription a2l = robot_a2l();
  std::erase_if(a2l.memory, [](const xcp::host::MemoryInfo& info) { return info.name == "executive"; });
  EXPECT_FALSE(ExecutiveAccountLayout::from(a2l));
}

}  // namespace
}  // namespace duet::monitor
