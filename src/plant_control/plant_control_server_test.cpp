// The plant-control endpoint over TCP: description, requests applied at the served plant's next tick and answered
// with its time, news for the other connections, refusals of every kind, requests the plant never takes.
#include "duet/plant_control/plant_control_server.hpp"

#include <boost/asio.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <optional>
#include <thread>

#include "served_plant.hpp"

namespace duet::plant_control {
namespace {

using nlohmann::json;
using namespace std::chrono_literals;
namespace asio = boost::asio;
using testing::ShovablePlant;
using Ticking = testing::TickingPlant;

// A client reading and writing lines, each read bounded by a timeout.
class LineClient {
 public:
  explicit LineClient(const std::string& address) {
    const std::size_t colon = address.rfind(':');
    socket_.connect({asio::ip::make_address(address.substr(0, colon)),
                     static_cast<std::uint16_t>(std::stoi(address.substr(colon + 1)))});
    const timeval patience{5, 0};
    ::setsockopt(socket_.native_handle(), SOL_SOCKET, SO_RCVTIMEO, &patience, sizeof(patience));
  }
  void send(const json& request) { send_text(request.dump() + "\n"); }
  void send_text(const std::string& text) { asio::write(socket_, asio::buffer(text)); }
  // The next line as JSON; none at the end of the stream or after 5 s.
  std::optional<json> next() {
    boost::system::error_code error;
    const std::size_t length = asio::read_until(socket_, asio::dynamic_buffer(input_), '\n', error);
    if (error) return std::nullopt;
    const std::string line = input_.substr(0, length - 1);
    input_.erase(0, length);
    return json::parse(line);
  }

 private:
  asio::io_context io_;
  asio::ip::tcp::socket socket_{io_};
  std::string input_;
};

struct Endpoint {
  explicit Endpoint(std::chrono::milliseconds apply_within = 2000ms) {
    auto started = PlantControlServer::start(
        controls, {.host = "127.0.0.1", .port = 0, .plant = "shovable", .apply_within = apply_within});
    EXPECT_TRUE(started.ok()) << started.error();
    if (started) server = std::move(started).value();
  }
  plant::PlantControls controls{ShovablePlant::kinds()};
  std::unique_ptr<PlantControlServer> server;
};

TEST(PlantControlServer, AConnectionGetsTheDescriptionFirstAndOnRequest) {
  Endpoint endpoint;
  ASSERT_TRUE(endpoint.server);
  EXPECT_TRUE(endpoint.server->address().starts_with("127.0.0.1:"));
  LineClient client{endpoint.server->address()};
  const auto description = client.next();
  ASSERT_TRUE(description.has_value());
  EXPECT_EQ((*description)["type"], "description");
  EXPECT_EQ((*description)["plant"], "shovable");
  EXPECT_EQ((*description)["actions"].size(), 2U);
  client.send({{"type", "describe"}});
  EXPECT_EQ(client.next(), description);
}

TEST(PlantControlServer, ARequestIsAnsweredWithTheModelTimeItWasAppliedAtAndTheOthersAreTold) {
  Endpoint endpoint;
  Ticking ticking{endpoint.controls};
  LineClient asker{endpoint.server->address()};
  LineClient watcher{endpoint.server->address()};
  (void)asker.next();
  (void)watcher.next();
  asker.send({{"type", "plant"}, {"action", "push"}, {"force_n", 7.5}, {"id", 1}});
  const auto answer = asker.next();
  ASSERT_TRUE(answer.has_value());
  EXPECT_EQ((*answer)["type"], "plant");
  EXPECT_EQ((*answer)["id"], 1);
  EXPECT_EQ((*answer)["action"], "push");
  EXPECT_EQ((*answer)["arguments"], (json{{"force_n", 7.5}, {"duration_s", 0.05}}));  // the default duration
  ASSERT_TRUE((*answer)["time_s"].is_number());
  const auto applied = endpoint.controls.applied();
  ASSERT_EQ(applied.size(), 1U);
  EXPECT_EQ((*answer)["time_s"].get<double>(), applied[0].time_s);  // the tick it acts from
  EXPECT_GT(applied[0].time_s, 0.0);
  const auto news = watcher.next();
  ASSERT_TRUE(news.has_value());
  EXPECT_FALSE(news->contains("id"));
  EXPECT_EQ((*news)["time_s"], (*answer)["time_s"]);
}

TEST(PlantControlServer, BadRequestsAreRefusedNamingTheProblemAndTheConnectionGoesOn) {
  Endpoint endpoint;
  Ticking ticking{endpoint.controls};
  LineClient client{endpoint.server->address()};
  (void)client.next();
  const auto refusal = [&](const json& request) {
    client.send(request);
    const auto answer = client.next();
    EXPECT_TRUE(answer.has_value());
    return answer ? *answer : json{};
  };
  EXPECT_EQ(
      refusal({{"type", "plant"}, {"action", "kick"}, {"id", "a"}}),
      (json{{"type", "plant"}, {"action", "kick"}, {"error", "unknown action 'kick': push, restart"}, {"id", "a"}}));
  EXPECT_EQ(refusal({{"type", "plant"}, {"action", "push"}, {"force_n", 500}})["error"],
            "push: force_n = 500 N is outside -50 to 50 N");
  EXPECT_EQ(refusal({{"type", "plant"}, {"action", "push"}, {"duration_s", "long"}})["error"],
            "push: duration_s is a number (s)");
  EXPECT_EQ(refusal({{"type", "shove"}})["message"], "unknown request type 'shove': plant or describe");
  client.send_text("{not json\n");
  EXPECT_EQ(client.next().value_or(json{})["type"], "error");
  EXPECT_TRUE(endpoint.controls.applied().empty());
  client.send({{"type", "plant"}, {"action", "restart"}});  // still served
  const auto applied = client.next();
  ASSERT_TRUE(applied.has_value());
  EXPECT_TRUE(applied->contains("time_s")) << applied->dump();
}

TEST(PlantControlServer, WithoutAServedPlantARequestIsRefusedAtOnce) {
  Endpoint endpoint;
  LineClient client{endpoint.server->address()};
  (void)client.next();
  client.send({{"type", "plant"}, {"action", "restart"}});
  EXPECT_EQ(client.next().value_or(json{})["error"], "the plant is not running (no firmware is connected to it)");
}

TEST(PlantControlServer, ARequestThePlantDoesNotTakeInTimeIsWithdrawnAndRefused) {
  Endpoint endpoint{200ms};
  auto plant = std::make_unique<plant::ControlledPlant>(std::make_unique<ShovablePlant>(), endpoint.controls);
  LineClient client{endpoint.server->address()};
  (void)client.next();
  client.send({{"type", "plant"}, {"action", "push"}, {"id", 9}});
  const auto answer = client.next();  // nobody advances the plant
  ASSERT_TRUE(answer.has_value());
  EXPECT_EQ((*answer)["id"], 9);
  EXPECT_EQ((*answer)["action"], "push");
  EXPECT_EQ((*answer)["error"], "not applied: the plant did not advance within 200 ms (is the firmware running?)");
  plant->advance(0.001, {});
  EXPECT_TRUE(endpoint.controls.applied().empty());  // it does not land later by surprise
}

TEST(PlantControlServer, ALineTooLongEndsTheConnection) {
  Endpoint endpoint;
  LineClient client{endpoint.server->address()};
  (void)client.next();
  client.send_text(std::string(5000, 'x'));
  EXPECT_EQ(client.next().value_or(json{})["message"], "a line is at most 4096 bytes; closing");
  EXPECT_FALSE(client.next().has_value());
}

TEST(PlantControlServer, ServesThisMachineOnly) {
  plant::PlantControls controls{ShovablePlant::kinds()};
  auto refused = PlantControlServer::start(controls, {.host = "0.0.0.0", .port = 0, .plant = "shovable"});
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error(),
            "plant control: 0.0.0.0 is not this machine's loopback address: the endpoint serves this machine only");
  EXPECT_TRUE(PlantControlServer::start(controls, {.host = "localhost", .port = 0, .plant = "shovable"}).ok());
}

}  // namespace
}  // namespace duet::plant_control
