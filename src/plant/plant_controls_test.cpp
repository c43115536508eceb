// Disturbances asked for from other threads, applied at the plant's next advance and answered with its time.
#include "duet/plant/plant_controls.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <optional>
#include <thread>

namespace duet::plant {
namespace {

// Says, in order, what it was asked to do.
class TellingPlant : public Plant {
 public:
  void advance(double time_s, const RaiseInterrupt&) override { calls.push_back("advance " + std::to_string(time_s)); }
  void write(std::string_view, std::span<const double>) override {}
  void read(std::string_view, std::span<double>) override {}
  [[nodiscard]] std::vector<DisturbanceKind> disturbances() const override { return kinds(); }
  void disturb(const Disturbance& disturbance, double time_s) override {
    std::string call = disturbance.name;
    for (const double value : disturbance.arguments) call += " " + std::to_string(value);
    calls.push_back(call + " at " + std::to_string(time_s));
  }

  static std::vector<DisturbanceKind> kinds() {
    return {{"push", "a shove", {{"force_n", "N", -50, 50, 5}, {"duration_s", "s", 0.001, 1, 0.05}}},
            {"restart", "again", {}}};
  }
  std::vector<std::string> calls;
};

// A served plant whose calls the test reads through `telling`.
struct Served {
  PlantControls controls{TellingPlant::kinds()};
  TellingPlant* telling = nullptr;
  std::optional<ControlledPlant> plant;
  Served() {
    auto made = std::make_unique<TellingPlant>();
    telling = made.get();
    plant.emplace(std::move(made), controls);
  }
};

TEST(PlantControls, ChecksARequestAgainstWhatThePlantOffers) {
  const std::vector<DisturbanceKind> offered = TellingPlant::kinds();
  EXPECT_TRUE(check_disturbance(offered, {"push", {5, 0.05}}).ok());
  EXPECT_TRUE(check_disturbance(offered, {"push", {-50, 1}}).ok());  // the limits are allowed
  EXPECT_TRUE(check_disturbance(offered, {"restart", {}}).ok());
  EXPECT_EQ(check_disturbance(offered, {"shove", {}}).error(), "no disturbance named 'shove' (offered: push, restart)");
  EXPECT_EQ(check_disturbance({}, {"push", {}}).error(), "no disturbance named 'push' (the plant offers none)");
  EXPECT_EQ(check_disturbance(offered, {"push", {5}}).error(), "push takes 2 arguments, not 1");
  EXPECT_EQ(check_disturbance(offered, {"push", {80, 0.05}}).error(), "push: force_n = 80 N is outside -50 to 50 N");
  EXPECT_EQ(check_disturbance(offered, {"push", {5, 0}}).error(), "push: duration_s = 0 s is outside 0.001 to 1 s");
  EXPECT_FALSE(check_disturbance(offered, {"push", {std::nan(""), 0.05}}).ok());
}

TEST(PlantControls, NothingIsTakenWhileNoPlantIsServed) {
  PlantControls controls{TellingPlant::kinds()};
  bool answered = false;
  auto refused = controls.request({"restart", {}}, [&](const Result<AppliedDisturbance>&) { answered = true; });
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error(), "the plant is not running (no firmware is connected to it)");
  EXPECT_FALSE(answered);
  auto bad = controls.request({"push", {99, 0.05}}, [](const Result<AppliedDisturbance>&) {});
  EXPECT_EQ(bad.error(), "push: force_n = 99 N is outside -50 to 50 N");  // checked first, served or not
}

TEST(PlantControls, ARequestActsFromTheNextAdvanceAndIsAnsweredWithItsTime) {
  Served served;
  served.plant->advance(0.001, {});
  std::optional<Result<AppliedDisturbance>> answer;
  auto ticket =
      served.controls.request({"push", {5, 0.05}}, [&](const Result<AppliedDisturbance>& got) { answer = got; });
  ASSERT_TRUE(ticket.ok()) << ticket.error();
  EXPECT_FALSE(answer.has_value());  // not before the plant moves on
  served.plant->advance(0.002, {});
  ASSERT_TRUE(answer.has_value());
  ASSERT_TRUE(answer->ok()) << answer->error();
  EXPECT_EQ(answer->value().time_s, 0.002);
  EXPECT_EQ(answer->value().disturbance.name, "push");
  // Handed over before the plant advanced to that time, so it acts from then on.
  EXPECT_EQ(served.telling->calls,
            (std::vector<std::string>{"advance 0.001000", "push 5.000000 0.050000 at 0.002000", "advance 0.002000"}));
  const auto applied = served.controls.applied();
  ASSERT_EQ(applied.size(), 1U);
  EXPECT_EQ(applied[0].time_s, 0.002);
  EXPECT_EQ(applied[0].disturbance.arguments, (std::vector<double>{5, 0.05}));
  EXPECT_FALSE(served.controls.withdraw(ticket.value()));  // applied already
}

TEST(PlantControls, AWithdrawnRequestIsNeitherAppliedNorAnswered) {
  Served served;
  bool answered = false;
  auto ticket = served.controls.request({"restart", {}}, [&](const Result<AppliedDisturbance>&) { answered = true; });
  ASSERT_TRUE(ticket.ok());
  EXPECT_TRUE(served.controls.withdraw(ticket.value()));
  EXPECT_FALSE(served.controls.withdraw(ticket.value()));
  served.plant->advance(0.001, {});
  EXPECT_FALSE(answered);
  EXPECT_TRUE(served.controls.applied().empty());
  EXPECT_EQ(served.telling->calls, (std::vector<std::string>{"advance 0.001000"}));
}

TEST(PlantControls, RequestsWaitingWhenThePlantStopsAreAnsweredSo) {
  Served served;
  std::optional<Result<AppliedDisturbance>> answer;
  ASSERT_TRUE(served.controls.request({"restart", {}}, [&](const Result<AppliedDisturbance>& got) { answer = got; }));
  served.plant.reset();
  ASSERT_TRUE(answer.has_value());
  EXPECT_EQ(answer->error(), "restart was not applied: the plant stopped running first");
  EXPECT_FALSE(served.controls.request({"restart", {}}, [](const Result<AppliedDisturbance>&) {}).ok());
}

TEST(PlantControls, RequestsFromAnotherThreadLandInTheOrderAskedAtTicksThatGoOn) {
  Served served;
  constexpr int requests = 200;
  std::atomic<int> answered{0};
  std::vector<double> times(requests, -1);
  std::thread asker{[&] {
    for (int k = 0; k < requests; ++k) {
      auto ticket = served.controls.request({"push", {static_cast<double>(k % 50), 0.05}},
                                            [&, k](const Result<AppliedDisturbance>& got) {
                                              times[static_cast<std::size_t>(k)] = got ? got.value().time_s : -2;
                                              ++answered;
                                            });
      EXPECT_TRUE(ticket.ok());
      std::this_thread::yield();
    }
  }};
  for (int tick = 1; answered.load() < requests && tick < 10'000'000; ++tick) served.plant->advance(tick * 1e-3, {});
  asker.join();
  ASSERT_EQ(answered.load(), requests);
  for (std::size_t k = 1; k < times.size(); ++k) EXPECT_LE(times[k - 1], times[k]) << k;
  EXPECT_GT(times.front(), 0);
  const auto applied = served.controls.applied();
  ASSERT_EQ(applied.size(), static_cast<std::size_t>(requests));
  for (int k = 0; k < requests; ++k) EXPECT_EQ(applied[static_cast<std::size_t>(k)].disturbance.arguments[0], k % 50);
}

}  // namespace
}  // namespace duet::plant
