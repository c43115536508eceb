// The plant-control protocol's messages: description, requests read against what the plant offers, answers.
#include "duet/plant_control/plant_messages.hpp"

#include <gtest/gtest.h>

namespace duet::plant_control {
namespace {

using nlohmann::json;

std::vector<plant::DisturbanceKind> offered() {
  return {{"push", "a shove", {{"force_n", "N", -50, 50, 5}, {"duration_s", "s", 0.001, 1, 0.05}}},
          {"restart", "again", {}}};
}

TEST(PlantMessages, TheDescriptionListsEveryActionWithItsArguments) {
  const json message = description_message("balbot", offered());
  EXPECT_EQ(message["type"], "description");
  EXPECT_EQ(message["plant"], "balbot");
  ASSERT_EQ(message["actions"].size(), 2U);
  EXPECT_EQ(message["actions"][0]["name"], "push");
  EXPECT_EQ(message["actions"][0]["summary"], "a shove");
  EXPECT_EQ(message["actions"][0]["arguments"][0],
            (json{{"name", "force_n"}, {"unit", "N"}, {"min", -50.0}, {"max", 50.0}, {"default", 5.0}}));
  EXPECT_EQ(message["actions"][1]["arguments"], json::array());
}

TEST(PlantMessages, ARequestNamesItsArgumentsAndLeavesOutDefaults) {
  auto full =
      read_request({{"type", "plant"}, {"action", "push"}, {"force_n", -3}, {"duration_s", 0.2}, {"id", 4}}, offered());
  ASSERT_TRUE(full.ok()) << full.error();
  EXPECT_EQ(full.value().name, "push");
  EXPECT_EQ(full.value().arguments, (std::vector<double>{-3, 0.2}));
  auto defaults = read_request({{"type", "plant"}, {"action", "push"}, {"force_n", 7}}, offered());
  ASSERT_TRUE(defaults.ok());
  EXPECT_EQ(defaults.value().arguments, (std::vector<double>{7, 0.05}));
  auto restart = read_request({{"type", "plant"}, {"action", "restart"}}, offered());
  ASSERT_TRUE(restart.ok());
  EXPECT_TRUE(restart.value().arguments.empty());
}

TEST(PlantMessages, ABadRequestIsRefusedNamingTheProblem) {
  EXPECT_EQ(read_request({{"type", "plant"}}, offered()).error(), "a plant request needs \"action\": push, restart");
  EXPECT_EQ(read_request({{"type", "plant"}, {"action", 3}}, offered()).error(),
            "a plant request needs \"action\": push, restart");
  EXPECT_EQ(read_request({{"type", "plant"}, {"action", "kick"}}, offered()).error(),
            "unknown action 'kick': push, restart");
  EXPECT_EQ(read_request({{"type", "plant"}, {"action", "push"}, {"forse_n", 5}}, offered()).error(),
            "push takes no argument 'forse_n' (force_n, duration_s)");
  EXPECT_EQ(read_request({{"type", "plant"}, {"action", "restart"}, {"force_n", 5}}, offered()).error(),
            "restart takes no argument 'force_n' (it takes none)");
  EXPECT_EQ(read_request({{"type", "plant"}, {"action", "push"}, {"force_n", "5"}}, offered()).error(),
            "push: force_n is a number (N)");
}

TEST(PlantMessages, AnswersSayWhatWasAppliedWhenOrWhyNot) {
  const json applied = applied_message({{"push", {5, 0.05}}, 12.345}, offered());
  EXPECT_EQ(applied, (json{{"type", "plant"},
                           {"action", "push"},
                           {"arguments", {{"force_n", 5.0}, {"duration_s", 0.05}}},
                           {"time_s", 12.345}}));
  EXPECT_EQ(refused_message({{"action", "push"}}, "too hard"),
            (json{{"type", "plant"}, {"action", "push"}, {"error", "too hard"}}));
  EXPECT_EQ(refused_message(json::object(), "what?"), (json{{"type", "plant"}, {"error", "what?"}}));
}

}  // namespace
}  // namespace duet::plant_control
