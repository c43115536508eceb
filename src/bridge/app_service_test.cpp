// The application channel through the bridge, in-process: the robot's application on a pty <-> AppService <->
// WebSocket clients.
#include "app_service.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "pty_application.hpp"
#include "served_plant.hpp"
#include "websocket_client.hpp"

namespace duet::bridge {
namespace {

using dashboard::testing::WebSocketClient;
using nlohmann::json;

class AppServiceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    application->start();
    AppServiceOptions options;
    options.channel.path = application->path();
    options.channel_uri = "tty:" + application->path();
    options.websocket_port = 0;
    options.extra_status = [] { return std::string{R"({"xcp": {"frames_to_master": 7}})"}; };
    service = std::make_unique<AppService>(options);
    ASSERT_TRUE(service->start().ok());
    thread = std::thread{[this] { EXPECT_TRUE(service->run().ok()); }};
  }
  void TearDown() override {
    service->stop();
    thread.join();
  }

  std::unique_ptr<PtyApplication> application = std::make_unique<PtyApplication>();
  std::unique_ptr<AppService> service;
  std::thread thread;
};

TEST_F(AppServiceTest, StatusCarriesTheExecutivesAccount) {
  WebSocketClient client{service->websocket_port()};
  std::optional<json> status;
  // The application gives its first account after a second of samples; a loaded machine may take far longer.
  const auto given_up = std::chrono::steady_clock::now() + std::chrono::seconds{20};
  while (!(status && status->contains("executive")) && std::chrono::steady_clock::now() < given_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds{100});
    client.send({{"type", "status"}});
    status = client.next("status");
  }
  ASSERT_TRUE(status && status->contains("executive")) << (status ? status->dump() : "no status");
  const json& executive = (*status)["executive"];
  EXPECT_DOUBLE_EQ(executive["core_load"].get<double>(), 0.012);
  EXPECT_EQ(executive["overruns"], 1);
  EXPECT_DOUBLE_EQ(executive["time_s"].get<double>(), executive["ticks"].get<double>() * 0.01);
  ASSERT_EQ(executive["tasks"].size(), 2U);
  EXPECT_EQ(executive["tasks"][1]["name"], "IPCC_RX1");
  EXPECT_DOUBLE_EQ(executive["tasks"][0]["max_us"].get<double>(), 10.0);  // 250 cycles at 25 MHz
  EXPECT_EQ((*status)["link"]["state"], "open");
}

TEST_F(AppServiceTest, ADashboardGetsTheDescriptionTelemetryAndSetsTheGains) {
  WebSocketClient client{service->websocket_port()};
  const auto description = client.next("description");
  ASSERT_TRUE(description);
  EXPECT_EQ((*description)["application"], "balbot");
  ASSERT_EQ((*description)["telemetry"].size(), 3U);
  EXPECT_EQ((*description)["telemetry"][1]["name"], "battery");
  EXPECT_EQ((*description)["telemetry"][1]["unit"], "V");
  EXPECT_EQ((*description)["parameters"][2]["name"], "D");
  EXPECT_EQ((*description)["parameters"][2]["type"], "float32");
  EXPECT_FALSE(description->contains("plant"));                   // the board's bridge: no simulated plant behind it
  EXPECT_EQ((*description)["mdf4"]["recorder"], "recorder.mf4");  // Save as MDF4 (docs/DASHBOARD.md)

  const auto sample = client.next("telemetry");
  ASSERT_TRUE(sample);
  ASSERT_EQ((*sample)["values"].size(), 3U);
  EXPECT_FLOAT_EQ((*sample)["values"][1].get<float>(), 7.4F);

  for (const auto& [name, value] : {std::pair{"P", 0.05}, {"I", 0.01}, {"D", 0.02}}) {
    client.send({{"type", "set"}, {"name", name}, {"value", value}});
    const auto answer = client.answer_on(name);
    ASSERT_TRUE(answer) << name;
    EXPECT_EQ((*answer)["status"], "applied");
    EXPECT_FLOAT_EQ((*answer)["value"].get<float>(), static_cast<float>(value));
  }
  EXPECT_FLOAT_EQ(application->p, 0.05F);
  EXPECT_FLOAT_EQ(application->i, 0.01F);
  EXPECT_FLOAT_EQ(application->d, 0.02F);

  client.send({{"type", "status"}});
  const auto status = client.next("status");
  ASSERT_TRUE(status);
  EXPECT_TRUE((*status)["application_channel"]["open"].get<bool>());
  EXPECT_GT((*status)["application_channel"]["samples"].get<int>(), 0);
  EXPECT_EQ((*status)["xcp"]["frames_to_master"], 7);  // the relay's counters ride along
}

TEST_F(AppServiceTest, BadRequestsGetClearErrorsAndTheServiceGoesOn) {
  WebSocketClient client{service->websocket_port()};
  ASSERT_TRUE(client.next("description"));
  client.send_text("not json");
  EXPECT_NE((*client.next("error"))["message"].get<std::string>().find("JSON object"), std::string::npos);
  client.send({{"type", "launch"}});
  EXPECT_NE((*client.next("error"))["message"].get<std::string>().find("unknown request type 'launch'"),
            std::string::npos);
  client.send({{"type", "set"}, {"name", "Q"}, {"value", 1}});
  EXPECT_NE((*client.next("error"))["message"].get<std::string>().find("no parameter named 'Q'"), std::string::npos);
  client.send({{"type", "set"}, {"name", "P"}, {"value", 3}});
  EXPECT_NE((*client.next("error"))["message"].get<std::string>().find("outside its limits"), std::string::npos);
  client.send({{"type", "set"}, {"name", "P"}});
  EXPECT_NE((*client.next("error"))["message"].get<std::string>().find("needs"), std::string::npos);
  client.send({{"type", "set"}, {"name", "P"}, {"value", 0.5}});
  ASSERT_TRUE(client.answer_on("P"));
  EXPECT_FLOAT_EQ(application->p, 0.5F);
}

TEST_F(AppServiceTest, GarbageOnTheChannelIsSkipped) {
  WebSocketClient client{service->websocket_port()};
  ASSERT_TRUE(client.next("description"));
  application->inject({0x00, 0x13, 0xFF, 0x07, 0x01, 0x02, 0x03, 0x99, 0x10, 0x00});
  ASSERT_TRUE(client.next("telemetry"));
  client.send({{"type", "set"}, {"name", "I"}, {"value", 0.25}});
  ASSERT_TRUE(client.answer_on("I"));
  client.send({{"type", "status"}});
  EXPECT_GT((*client.next("status"))["application_channel"]["garbage_bytes"].get<int>(), 0);
}

TEST(AppServiceRestart, ARestartedApplicationIsDescribedAgainAndServes) {
  const std::filesystem::path link =
      std::filesystem::temp_directory_path() / ("duet_app_channel_" + std::to_string(::getpid()));
  auto application = std::make_unique<PtyApplication>();
  application->start();
  std::filesystem::remove(link);
  std::filesystem::create_symlink(application->path(), link);  // a stable name, as /dev/ttyRPMSG1 is across restarts
  AppServiceOptions options;
  options.channel.path = link.string();
  options.channel_uri = "tty:" + link.string();
  options.websocket_port = 0;
  AppService service{options};
  ASSERT_TRUE(service.start().ok());
  std::thread thread{[&service] { EXPECT_TRUE(service.run().ok()); }};

  WebSocketClient client{service.websocket_port()};
  ASSERT_TRUE(client.next("description"));
  application.reset();  // the firmware stops: the channel closes
  const auto closed = client.next("channel");
  ASSERT_TRUE(closed);
  EXPECT_FALSE((*closed)["open"].get<bool>());
  application = std::make_unique<PtyApplication>();  // restarted
  application->start();
  std::filesystem::remove(link);
  std::filesystem::create_symlink(application->path(), link);
  EXPECT_TRUE(client.next("description"));  // asked for again when the channel reopened
  client.send({{"type", "set"}, {"name", "D"}, {"value", 0.5}});
  EXPECT_TRUE(client.answer_on("D"));
  EXPECT_FLOAT_EQ(application->d, 0.5F);
  client.send({{"type", "status"}});
  EXPECT_EQ((*client.next("status"))["application_channel"]["opens"], 2);

  service.stop();
  thread.join();
  std::filesystem::remove(link);
}

TEST(AppServicePlant, BesideDuetPilThePageMayPushThePlant) {
  plant_control::testing::ServedPlant plant;
  ASSERT_TRUE(plant.listening());
  PtyApplication application;
  application.start();
  AppServiceOptions options;
  options.channel.path = application.path();
  options.channel_uri = "tty:" + application.path();
  options.websocket_port = 0;
  options.plant_control = dashboard::PlantControlAddress{plant.host(), plant.port()};
  AppService service{options};
  ASSERT_TRUE(service.start().ok());
  std::thread thread{[&service] { EXPECT_TRUE(service.run().ok()); }};

  WebSocketClient client{service.websocket_port()};
  std::optional<json> description;
  for (int attempt = 0; attempt < 10 && !(description && description->contains("plant")); ++attempt) {
    description = client.next("description");
  }
  ASSERT_TRUE(description && description->contains("plant"));
  EXPECT_EQ((*description)["application"], "balbot");
  EXPECT_EQ((*description)["plant"]["actions"][1]["name"], "restart");
  client.send({{"type", "plant"}, {"action", "restart"}});
  const auto answer = client.next("plant");
  ASSERT_TRUE(answer);
  EXPECT_GT((*answer)["time_s"].get<double>(), 0.0) << answer->dump();
  EXPECT_EQ(plant.controls().applied().size(), 1U);

  service.stop();
  thread.join();
}

}  // namespace
}  // namespace duet::bridge
