// duet studio's server through a WebSocket client, as the page talks to it: a copy of a model in a folder of its
// own, checked, saved, changed behind its back, simulated and generated; bad requests answered with errors.
#include "duet/studio/studio.hpp"

#include <boost/asio.hpp>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include "duet/support/content_hash.hpp"
#include "duet/support/text_file.hpp"
#include "websocket_client.hpp"

namespace duet::studio {
namespace {

using dashboard::testing::WebSocketClient;
using nlohmann::json;
namespace fs = std::filesystem;

class StudioTest : public ::testing::Test {
 protected:
  // The model the server opens, first, and the files beside it, from the source tree.
  [[nodiscard]] virtual std::vector<fs::path> files() const {
    return {"apps/pid_demo/pid_demo.yaml", "apps/pid_demo/motor_logic.hpp"};
  }

  void SetUp() override {
    folder = fs::temp_directory_path() / ("duet_studio_test_" + std::to_string(::getpid()) + "_" +
                                          ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(folder);
    fs::create_directories(folder);
    for (const fs::path& file : files()) fs::copy_file(fs::path{DUET_SOURCE_DIR} / file, folder / file.filename());
    model = folder / files().front().filename();
    original = read_text_file(model.string()).value();
    StudioOptions options;  // member by member: GCC 12 at -O3 takes braced nested options for read before written
    options.model = model;
    options.plant = "none";
    options.duration_s = 0.5;
    auto created = Studio::create(io, std::move(options));
    ASSERT_TRUE(created.ok()) << created.error();
    studio = std::move(created).value();
    ASSERT_TRUE(studio->start().ok());
    serving = std::thread{[this] { io.run(); }};
  }
  void TearDown() override {
    io.stop();
    serving.join();
    studio->stop();
    fs::remove_all(folder);
  }

  fs::path folder, model;
  std::string original;
  boost::asio::io_context io;
  std::unique_ptr<Studio> studio;
  std::thread serving;
};

TEST_F(StudioTest, WelcomesWithTheFileTheLibraryAndTheCheckedModel) {
  WebSocketClient client{studio->port()};
  const auto welcome = client.next("studio");
  ASSERT_TRUE(welcome);
  EXPECT_EQ((*welcome)["file"], "pid_demo.yaml");
  EXPECT_EQ((*welcome)["text"], original);
  EXPECT_EQ((*welcome)["version"], content_hash(original));
  EXPECT_GT((*welcome)["library"].size(), 40U);
  EXPECT_EQ((*welcome)["defaults"]["plant"], "none");
  const auto model_message = client.next("model");
  ASSERT_TRUE(model_message);
  EXPECT_TRUE((*model_message)["ok"]);
  EXPECT_EQ((*model_message)["seq"], 0);
  EXPECT_FALSE((*model_message)["diagram"]["root"]["blocks"].empty());
}

TEST_F(StudioTest, ChecksEachTextItIsSent) {
  WebSocketClient client{studio->port()};
  client.send(
      {{"type", "check"}, {"text", original + "  - {name: bad, type: Gain, inputs: {u: nowhere}}\n"}, {"seq", 7}});
  auto checked = client.next("model");
  while (checked && (*checked)["seq"] != 7) checked = client.next("model");
  ASSERT_TRUE(checked);
  EXPECT_FALSE((*checked)["ok"]);
  bool about_bad = false;
  for (const json& diagnostic : (*checked)["diagnostics"]) about_bad = about_bad || diagnostic["block"] == "bad";
  EXPECT_TRUE(about_bad) << (*checked)["diagnostics"].dump(2);
}

TEST_F(StudioTest, SavesOnlyOverTheVersionItWasEditedFrom) {
  WebSocketClient client{studio->port()};
  const std::string edited = original + "# edited\n";
  client.send({{"type", "save"}, {"text", edited}, {"base", "0000000000000000"}});
  const auto refused = client.next("save_refused");
  ASSERT_TRUE(refused);
  EXPECT_EQ(read_text_file(model.string()).value(), original);

  client.send({{"type", "save"}, {"text", edited}, {"base", content_hash(original)}});
  const auto saved = client.next("saved");
  ASSERT_TRUE(saved);
  EXPECT_EQ((*saved)["version"], content_hash(edited));
  EXPECT_EQ(read_text_file(model.string()).value(), edited);
}

TEST_F(StudioTest, TellsThePageWhenSomeoneElseChangedTheFile) {
  WebSocketClient client{studio->port()};
  ASSERT_TRUE(client.next("model"));
  std::ofstream{model, std::ios::app} << "# from another editor\n";
  const auto changed = client.next("file_changed");
  ASSERT_TRUE(changed);
  client.send({{"type", "reload"}});
  const auto file = client.next("file");
  ASSERT_TRUE(file);
  EXPECT_EQ((*file)["text"], original + "# from another editor\n");
  // Saving over the version the page had would lose the other editor's change: refused.
  client.send({{"type", "save"}, {"text", original}, {"base", content_hash(original)}});
  EXPECT_TRUE(client.next("save_refused"));
}

TEST_F(StudioTest, SimulatesTheTextAgainstAPlant) {
  WebSocketClient client{studio->port()};
  client.send({{"type", "simulate"}, {"text", original}, {"id", 3}, {"plant", "none"}, {"duration_s", 0.2}});
  const auto result = client.next("simulation", std::chrono::seconds{30});
  ASSERT_TRUE(result);
  EXPECT_EQ((*result)["id"], 3);
  EXPECT_FALSE((*result)["cancelled"]);
  ASSERT_EQ((*result)["time_s"].size(), 201U);  // 0 to 0.2 s in 1 ms ticks, both ends
  EXPECT_NEAR((*result)["time_s"].back().get<double>(), 0.2, 1e-9);
  ASSERT_FALSE((*result)["names"].empty());
  EXPECT_EQ((*result)["columns"].size(), (*result)["names"].size());
}

TEST_F(StudioTest, GeneratesTheFilesAndTheTaskTable) {
  WebSocketClient client{studio->port()};
  client.send({{"type", "generate"}, {"text", original}, {"wcet_us", {{"step_rate_1", 20}, {"step_rate_10", 50}}}});
  const auto generated = client.next("generated", std::chrono::seconds{30});
  ASSERT_TRUE(generated);
  std::vector<std::string> names;
  for (const json& file : (*generated)["files"]) names.push_back(file["name"]);
  EXPECT_NE(std::find(names.begin(), names.end(), "pid_demo.a2l"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "pid_demo.cpp"), names.end());
  EXPECT_FALSE((*generated)["tasks"].empty());
  EXPECT_EQ((*generated)["schedulability"]["verdict"], "schedulable") << (*generated)["schedulability"].dump(2);
}

TEST_F(StudioTest, OffersTheYamlFilesBesideTheModelAndBelowIt) {
  fs::create_directories(folder / "scenarios");
  std::ofstream{folder / "scenarios/held.yaml"} << "held: true\n";
  std::ofstream{folder / "heater.yaml"} << "duet_model: 1\n";
  WebSocketClient client{studio->port()};
  const auto welcome = client.next("studio");
  ASSERT_TRUE(welcome);
  EXPECT_EQ((*welcome)["files"], json::array({"heater.yaml", "scenarios/held.yaml"}));
}

TEST_F(StudioTest, AnswersBadRequestsWithErrorsAndReachesNoFileOutsideTheModelsFolder) {
  WebSocketClient client{studio->port()};
  client.send({{"type", "simulate"}, {"text", original}, {"plant", "balbot"}, {"scenario", "../../etc/passwd"}});
  auto error = client.next("error");
  ASSERT_TRUE(error);
  EXPECT_EQ((*error)["request"], "simulate");
  EXPECT_NE((*error)["message"].get<std::string>().find("beside the model"), std::string::npos);
  for (const char* outside : {"/etc/passwd", "scenarios/../../x.yaml", ".hidden.yaml"}) {
    client.send({{"type", "simulate"}, {"text", original}, {"plant", "balbot"}, {"scenario", outside}});
    error = client.next("error");
    ASSERT_TRUE(error) << outside;
    EXPECT_NE((*error)["message"].get<std::string>().find("beside the model"), std::string::npos) << outside;
  }
  client.send({{"type", "check"}});
  error = client.next("error");
  ASSERT_TRUE(error);
  EXPECT_EQ((*error)["request"], "check");
  client.send({{"type", "connect"}, {"address", "nonsense"}});
  error = client.next("error");
  ASSERT_TRUE(error);
  EXPECT_EQ((*error)["request"], "connect");
  client.send({{"type", "set"}, {"name", "Kp"}, {"value", 1}});
  error = client.next("error");
  ASSERT_TRUE(error);
  EXPECT_NE((*error)["message"].get<std::string>().find("not connected"), std::string::npos);
  client.send_text("not json");
  EXPECT_TRUE(client.next("error"));
}

// A model that references another (testing/reference): each file has problems of its own.
class StudioReferenceTest : public StudioTest {
 protected:
  [[nodiscard]] std::vector<fs::path> files() const override {
    return {"src/studio/testing/reference/loop.yaml", "src/studio/testing/reference/controller.yaml"};
  }
};

TEST_F(StudioReferenceTest, NamesTheFileOfEachDiagnosticAndTiesItToItsBlockThere) {
  WebSocketClient client{studio->port()};
  const auto checked = client.next("model");
  ASSERT_TRUE(checked);
  // Line 18 of loop.yaml is block spare's and line 7 block error's: the referenced file's places are not there.
  EXPECT_EQ((*checked)["diagnostics"], json::parse(R"([
    {"severity": "error", "file": "controller.yaml", "line": 18, "column": 14, "block": "controller/limit",
     "message": "input 'u' of block 'limit' reads signal 'pp', which nothing drives", "hint": "did you mean 'p'?"},
    {"severity": "error", "file": "loop.yaml", "line": 17, "column": 14, "block": "spare",
     "message": "input 'u' of block 'spare' reads signal 'nowhere', which nothing drives",
     "hint": "an output of a block, or of the subsystem's inputs, must drive it"},
    {"severity": "warning", "file": "controller.yaml", "line": 7, "column": 3, "block": null,
     "message": "parameter 'Kd' is not used", "hint": "remove it, or use it in a block"}])"))
      << (*checked)["diagnostics"].dump(2);
  // The reference's blocks are drawn inside it at their lines in their own file; the open file's name none.
  const json& blocks = (*checked)["diagram"]["root"]["blocks"];
  const json& controller = blocks[2];
  ASSERT_EQ(controller["id"], "controller");
  EXPECT_FALSE(controller.contains("file"));
  EXPECT_EQ(controller["line"], 8);
  const json& limit = controller["system"]["blocks"][1];
  ASSERT_EQ(limit["id"], "controller/limit");
  EXPECT_EQ(limit["file"], "controller.yaml");
  EXPECT_EQ(limit["line"], 15);
  EXPECT_EQ(limit["end_line"], 19);
  EXPECT_EQ(limit["inputs"][0]["file"], "controller.yaml");
  EXPECT_EQ(limit["inputs"][0]["line"], 18);
}

TEST_F(StudioReferenceTest, AReferencedModelThatDoesNotReadIsAProblemInItsFile) {
  std::string broken = read_text_file((folder / "controller.yaml").string()).value();
  broken.replace(broken.find("{name: duty, type: Outport, inputs: {u: duty}}"), 47, "{name: duty, type: Outport}");
  std::ofstream{folder / "broken.yaml"} << broken;
  std::string text = original;
  text.replace(text.find("controller.yaml"), 15, "broken.yaml");
  WebSocketClient client{studio->port()};
  client.send({{"type", "check"}, {"text", text}, {"seq", 1}});
  auto checked = client.next("model");
  while (checked && (*checked)["seq"] != 1) checked = client.next("model");
  ASSERT_TRUE(checked);
  EXPECT_TRUE((*checked)["diagram"].is_null());
  EXPECT_EQ((*checked)["diagnostics"], json::parse(R"json([
    {"severity": "error", "file": "broken.yaml", "line": 20, "column": 5, "block": null,
     "message": "Outport 'duty' reads no signal (connect it: inputs: {u: SIGNAL})", "hint": ""}])json"))
      << (*checked)["diagnostics"].dump(2);
}

}  // namespace
}  // namespace duet::studio
