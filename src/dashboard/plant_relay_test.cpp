// The dashboard's relay to a simulated plant: its description's `plant` member while the plant-control endpoint is
// reachable, requests relayed and answered with the model time, refusals to the asker only, an endpoint that is not
// there or goes away, and a back end without one.
#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <optional>
#include <thread>

#include "duet/dashboard/dashboard.hpp"
#include "served_dashboard.hpp"
#include "served_plant.hpp"
#include "websocket_client.hpp"

namespace duet::dashboard {
namespace {

namespace asio = boost::asio;
using nlohmann::json;
using plant_control::testing::ServedPlant;
using testing::WebSocketClient;

PlantControlAddress address_of(const ServedPlant& plant) { return {plant.host(), plant.port()}; }

// A back end's dashboard whose target samples theta.
class Backend : public testing::ServedDashboard {
 public:
  explicit Backend(std::optional<PlantControlAddress> plant_control)
      : ServedDashboard({"robot", "bridge", 10000, {{"theta", "deg", "float32", -90, 90}}, {}},
                        std::move(plant_control)) {}
};

// The first description with (or without) a plant member; later ones follow as the endpoint comes and goes.
std::optional<json> description_where(WebSocketClient& client, bool with_plant) {
  for (int attempts = 0; attempts < 20; ++attempts) {
    auto description = client.next("description");
    if (!description) return std::nullopt;
    if (description->contains("plant") == with_plant) return description;
  }
  return std::nullopt;
}

TEST(PlantRelay, TheDescriptionSaysWhatThePlantOffersAndAPushIsAnsweredWithItsModelTime) {
  ServedPlant plant;
  Backend backend{address_of(plant)};
  WebSocketClient asker{backend.dashboard->port()};
  WebSocketClient watcher{backend.dashboard->port()};
  const auto description = description_where(asker, true);
  ASSERT_TRUE(description.has_value());
  EXPECT_EQ((*description)["plant"]["name"], "shovable");
  ASSERT_EQ((*description)["plant"]["actions"].size(), 2U);
  EXPECT_EQ((*description)["plant"]["actions"][0]["arguments"][0]["name"], "force_n");
  EXPECT_EQ((*description)["application"], "robot");  // the target's description, with the plant's beside it
  ASSERT_TRUE(description_where(watcher, true).has_value());

  asker.send({{"type", "plant"}, {"action", "push"}, {"force_n", 5}, {"duration_s", 0.05}});
  const auto answer = asker.next("plant");
  ASSERT_TRUE(answer.has_value());
  EXPECT_EQ((*answer)["action"], "push");
  EXPECT_EQ((*answer)["arguments"], (json{{"force_n", 5.0}, {"duration_s", 0.05}}));
  EXPECT_FALSE(answer->contains("id"));  // the relay's own
  const auto applied = plant.controls().applied();
  ASSERT_EQ(applied.size(), 1U);
  EXPECT_EQ((*answer)["time_s"].get<double>(), applied[0].time_s);
  EXPECT_EQ(watcher.next("plant"), answer);  // every page shows the last push

  asker.send({{"type", "status"}});
  const auto status = asker.next("status");
  ASSERT_TRUE(status.has_value());
  EXPECT_EQ((*status)["plant"]["link"]["state"], "open");
  EXPECT_EQ((*status)["plant"]["requests"], 1);
  EXPECT_EQ((*status)["plant"]["applied"], 1);
}

TEST(PlantRelay, RefusalsGoToTheAskerOnlyAndAreCounted) {
  ServedPlant plant;
  Backend backend{address_of(plant)};
  WebSocketClient asker{backend.dashboard->port()};
  ASSERT_TRUE(description_where(asker, true).has_value());
  const auto refusal = [&](const json& request) {
    asker.send(request);
    const auto answer = asker.next("plant");
    EXPECT_TRUE(answer.has_value());
    return answer ? (*answer)["error"] : json{};
  };
  EXPECT_EQ(refusal({{"type", "plant"}, {"action", "kick"}}), "unknown action 'kick': push, restart");
  EXPECT_EQ(refusal({{"type", "plant"}, {"action", "push"}, {"force_n", 1000}}),
            "push: force_n = 1000 N is outside -50 to 50 N");
  EXPECT_EQ(refusal({{"type", "plant"}}), "a plant request needs \"action\": push, restart");
  asker.send({{"type", "status"}});
  const auto status = asker.next("status");
  ASSERT_TRUE(status.has_value());
  EXPECT_EQ((*status)["plant"]["refused"], 3);
  EXPECT_EQ((*status)["plant"]["applied"], 0);
  EXPECT_TRUE(plant.controls().applied().empty());
}

TEST(PlantRelay, AnEndpointThatIsNotThereOrGoesAwayLeavesNoPlantInTheDescription) {
  auto plant = std::make_unique<ServedPlant>();
  const PlantControlAddress address = address_of(*plant);
  Backend backend{address};
  WebSocketClient client{backend.dashboard->port()};
  ASSERT_TRUE(description_where(client, true).has_value());
  plant->stop_serving();
  ASSERT_TRUE(description_where(client, false).has_value());  // described again, without
  client.send({{"type", "plant"}, {"action", "restart"}});
  const auto answer = client.next("plant");
  ASSERT_TRUE(answer.has_value());
  EXPECT_EQ((*answer)["action"], "restart");
  EXPECT_TRUE((*answer)["error"].get<std::string>().starts_with("the plant is not reachable at 127.0.0.1:"))
      << answer->dump();
  client.send({{"type", "status"}});
  const auto status = client.next("status");
  ASSERT_TRUE(status.has_value());
  EXPECT_EQ((*status)["plant"]["link"]["state"], "connecting");
  EXPECT_EQ((*status)["plant"]["unreachable"], 1);
}

TEST(PlantRelay, WithoutAnEndpointThereIsNoPlant) {
  Backend backend{std::nullopt};
  WebSocketClient client{backend.dashboard->port()};
  const auto description = client.next("description");
  ASSERT_TRUE(description.has_value());
  EXPECT_FALSE(description->contains("plant"));
  client.send({{"type", "plant"}, {"action", "push"}});
  EXPECT_EQ(client.next("plant").value_or(json{})["error"],
            "no simulated plant behind this target (no --plant-control)");
  client.send({{"type", "status"}});
  EXPECT_FALSE(client.next("status").value_or(json{{"plant", 1}}).contains("plant"));
}

}  // namespace
}  // namespace duet::dashboard
