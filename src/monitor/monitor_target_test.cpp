// duet monitor's back end against a slave running in this process (TestTarget), through a WebSocket client as the
// dashboard's page talks to it.
#include "duet/monitor/monitor_target.hpp"

#include <boost/asio.hpp>
#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <thread>

#include "duet/mdf4/reader.hpp"
#include "duet/mdf4/summary.hpp"
#include "http_client.hpp"
#include "served_plant.hpp"
#include "test_target.hpp"
#include "websocket_client.hpp"

namespace duet::monitor {
namespace {

using namespace duet::xcp::host;
using dashboard::testing::WebSocketClient;
using nlohmann::json;

class MonitorTargetTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(target.server.start({}).ok());
    const Endpoint endpoint{Protocol::tcp, "127.0.0.1", target.server.port()};
    auto created = MonitorTarget::create(io, {.target = endpoint, .a2l = TestTarget::a2l(endpoint)});
    ASSERT_TRUE(created.ok()) << created.error();
    monitor = std::move(created).value();
    ASSERT_TRUE(monitor->start().ok());
    serving = std::thread{[this] { io.run(); }};
    stepping = std::thread{[this] {
      for (std::uint32_t step = 1; !stop; ++step) {
        target.step(step);
        std::this_thread::sleep_for(std::chrono::milliseconds{1});
      }
    }};
  }
  void TearDown() override {
    io.stop();
    serving.join();
    monitor->stop();
    stop = true;
    stepping.join();
  }

  TestTarget target{0};
  boost::asio::io_context io;
  std::unique_ptr<MonitorTarget> monitor;
  std::thread serving, stepping;
  std::atomic<bool> stop{false};
};

TEST_F(MonitorTargetTest, DescribesTheA2lsSignalsAndParametersAndSamplesThemByDaq) {
  WebSocketClient client{monitor->port()};
  const auto description = client.next("description");
  ASSERT_TRUE(description);
  EXPECT_EQ((*description)["backend"], "monitor");
  EXPECT_EQ((*description)["telemetry_period_us"], 1000);  // the fastest event, "1 ms"
  ASSERT_EQ((*description)["telemetry"].size(), 3U);
  EXPECT_EQ((*description)["telemetry"][0]["name"], "counter");
  EXPECT_EQ((*description)["telemetry"][0]["type"], "uint32");
  ASSERT_EQ((*description)["parameters"].size(), 4U);  // gain, scaled, flags[0], flags[1]
  EXPECT_EQ((*description)["parameters"][1]["unit"], "V");
  EXPECT_EQ((*description)["parameters"][3]["name"], "flags[1]");
  EXPECT_EQ((*description)["parameters"][3]["labels"],
            json::parse(R"([{"value": 0, "text": "clear"}, {"value": 1, "text": "set"}])"));  // the A2L's COMPU_VTAB
  EXPECT_FALSE((*description)["parameters"][0].contains("labels"));

  // A block of DAQ samples: the counter goes up by one per sample, and `twice` is twice it.
  std::optional<json> block;
  while ((block = client.next("samples")) && (*block)["time_s"].size() < 2) {
  }
  ASSERT_TRUE(block);
  const json& counter = (*block)["values"][0];
  ASSERT_EQ(counter.size(), (*block)["time_s"].size());
  for (std::size_t k = 1; k < counter.size(); ++k)
    EXPECT_EQ(counter[k].get<double>(), counter[k - 1].get<double>() + 1);
  EXPECT_EQ((*block)["values"][1][0].get<double>(), 2 * counter[0].get<double>());
  EXPECT_NEAR((*block)["time_s"][1].get<double>() - (*block)["time_s"][0].get<double>(), 0.001, 1e-9);
}

TEST_F(MonitorTargetTest, ASetIsDownloadedAndReadBack) {
  WebSocketClient client{monitor->port()};
  ASSERT_TRUE(client.next("samples"));  // connected: writes are taken from now on
  client.send({{"type", "set"}, {"name", "gain"}, {"value", 2.5}});
  const auto answer = client.answer_on("gain");
  ASSERT_TRUE(answer);
  EXPECT_EQ((*answer)["status"], "applied");
  EXPECT_EQ((*answer)["value"], 2.5);
  float gain = 0;
  std::memcpy(&gain, target.parameters.data(), sizeof gain);
  EXPECT_EQ(gain, 2.5F);

  client.send({{"type", "set"}, {"name", "scaled"}, {"value", 3.3}});  // through the conversion: raw 330
  const auto scaled = client.answer_on("scaled");
  ASSERT_TRUE(scaled);
  EXPECT_NEAR((*scaled)["value"].get<double>(), 3.3, 1e-9);
  EXPECT_EQ(target.parameters[4] | target.parameters[5] << 8, 330);
}

TEST_F(MonitorTargetTest, RefusesWritesTheA2lForbids) {
  WebSocketClient client{monitor->port()};
  ASSERT_TRUE(client.next("samples"));
  client.send({{"type", "set"}, {"name", "gain"}, {"value", 1000}});
  auto error = client.next("error");
  ASSERT_TRUE(error);
  EXPECT_NE((*error)["message"].get<std::string>().find("gain"), std::string::npos) << *error;
  client.send({{"type", "set"}, {"name", "counter"}, {"value", 1}});  // a MEASUREMENT
  error = client.next("error");
  ASSERT_TRUE(error);
  EXPECT_NE((*error)["message"].get<std::string>().find("no parameter"), std::string::npos) << *error;
}

TEST_F(MonitorTargetTest, TheRecorderTriggersOnTheDaqSamples) {
  WebSocketClient client{monitor->port()};
  ASSERT_TRUE(client.next("description"));
  const auto first = client.next("samples");
  ASSERT_TRUE(first);
  // A second from now: the recorder is armed before the counter gets there even on a loaded machine.
  const double level = (*first)["values"][0].back().get<double>() + 1000;
  client.send({{"type", "record"},
               {"signal", "counter"},
               {"level", level},
               {"edge", "rising"},
               {"pre_s", 0.01},
               {"post_s", 0.02}});
  const auto armed = client.next("recorder");
  ASSERT_TRUE(armed);
  EXPECT_EQ((*armed)["state"], "armed");
  const auto triggered = client.next("recorder");
  ASSERT_TRUE(triggered);
  EXPECT_EQ((*triggered)["state"], "triggered");
  const auto capture = client.next("capture");
  ASSERT_TRUE(capture);
  const json& counter = (*capture)["values"][0];
  EXPECT_EQ(counter.size(), 31U);  // 10 before, the trigger, 20 after
  EXPECT_EQ(counter[10].get<double>(), level);
  EXPECT_EQ((*capture)["signal"], "counter");
  const auto idle = client.next("recorder");
  ASSERT_TRUE(idle);
  EXPECT_EQ((*idle)["state"], "idle");

  // Saved as MDF4 (docs/DASHBOARD.md): the counter in the A2L MEASUREMENT's type.
  namespace http = boost::beast::http;
  const auto file = dashboard::testing::http_request(monitor->port(), http::verb::get, "/recorder.mf4");
  ASSERT_EQ(file.result(), http::status::ok) << file.body();
  auto reader = mdf4::Reader::from_bytes({file.body().begin(), file.body().end()});
  ASSERT_TRUE(reader.ok()) << reader.error();
  const mdf4::GroupInfo& group = reader.value().info().groups.at(0);
  EXPECT_EQ(group.samples, 31U);
  ASSERT_GE(group.channels.size(), 2U);
  EXPECT_EQ(group.channels[1].name, "counter");
  EXPECT_EQ(mdf4::type_text(group.channels[1]), "u32");
}

TEST_F(MonitorTargetTest, StatusSaysTheLinkIsOpen) {
  WebSocketClient client{monitor->port()};
  ASSERT_TRUE(client.next("samples"));
  client.send({{"type", "status"}});
  const auto status = client.next("status");
  ASSERT_TRUE(status);
  EXPECT_EQ((*status)["link"]["state"], "open");
  EXPECT_EQ((*status)["xcp"]["event"], "1 ms");
  EXPECT_GT((*status)["xcp"]["samples"].get<int>(), 0);
}

TEST(MonitorTargetAway, SaysSoAndRefusesWrites) {
  boost::asio::io_context io;
  const Endpoint nobody{Protocol::tcp, "127.0.0.1", 1};  // refused at once
  auto monitor = MonitorTarget::create(io, {.target = nobody, .a2l = TestTarget::a2l(nobody)});
  ASSERT_TRUE(monitor.ok());
  ASSERT_TRUE(monitor.value()->start().ok());
  std::thread serving{[&io] { io.run(); }};
  {
    WebSocketClient client{monitor.value()->port()};
    const auto description = client.next("description");  // from the A2L, target or not
    ASSERT_TRUE(description);
    EXPECT_FALSE(description->contains("plant"));  // no --plant-control
    client.send({{"type", "set"}, {"name", "gain"}, {"value", 2}});
    const auto error = client.next("error");
    ASSERT_TRUE(error);
    EXPECT_EQ((*error)["message"], "set gain: the target is not connected");
    std::optional<json> status;
    do {
      client.send({{"type", "status"}});
      status = client.next("status");
    } while (status && !(*status)["link"].contains("problem"));
    ASSERT_TRUE(status);
    EXPECT_NE((*status)["link"]["problem"].get<std::string>().find("127.0.0.1:1"), std::string::npos) << *status;
  }
  io.stop();
  serving.join();
  monitor.value()->stop();
}

TEST(MonitorTargetPlant, WithAPlantControlEndpointThePageMayPushThePlant) {
  plant_control::testing::ServedPlant plant;
  ASSERT_TRUE(plant.listening());
  boost::asio::io_context io;
  const Endpoint nobody{Protocol::tcp, "127.0.0.1", 1};  // the plant is there whether the target is or not
  MonitorOptions options;  // member by member: GCC 12 at -O3 takes a designated initializer's strings for uninitialised
  options.target = nobody;
  options.a2l = TestTarget::a2l(nobody);
  options.plant_control = dashboard::PlantControlAddress{plant.host(), plant.port()};
  auto monitor = MonitorTarget::create(io, std::move(options));
  ASSERT_TRUE(monitor.ok());
  ASSERT_TRUE(monitor.value()->start().ok());
  std::thread serving{[&io] { io.run(); }};
  {
    WebSocketClient client{monitor.value()->port()};
    std::optional<json> description;
    for (int attempt = 0; attempt < 10 && !(description && description->contains("plant")); ++attempt) {
      description = client.next("description");
    }
    ASSERT_TRUE(description && description->contains("plant"));
    EXPECT_EQ((*description)["backend"], "monitor");
    client.send({{"type", "plant"}, {"action", "push"}, {"force_n", -2}});
    const auto answer = client.next("plant");
    ASSERT_TRUE(answer);
    EXPECT_EQ((*answer)["arguments"]["force_n"], -2.0) << answer->dump();
    EXPECT_TRUE((*answer)["time_s"].is_number());
  }
  io.stop();
  serving.join();
  monitor.value()->stop();
}

TEST(MonitorTargetOptions, NamesASignalTheA2lLacks) {
  boost::asio::io_context io;
  const Endpoint endpoint{Protocol::tcp, "127.0.0.1", 1};
  auto created = MonitorTarget::create(io, {.target = endpoint, .a2l = TestTarget::a2l(endpoint), .signals = {"nope"}});
  ASSERT_FALSE(created.ok());
  EXPECT_EQ(created.error(), "--signal nope: no MEASUREMENT of that name in the A2L");
  created = MonitorTarget::create(io, {.target = endpoint, .a2l = TestTarget::a2l(endpoint), .event = "5 ms"});
  ASSERT_FALSE(created.ok());
  EXPECT_EQ(created.error(), "--event 5 ms: no such event in the A2L");
}

}  // namespace
}  // namespace duet::monitor
