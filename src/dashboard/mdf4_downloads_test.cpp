// The dashboard's MDF4 files over HTTP: the recorder's last capture (GET recorder.mf4) and the Scope's samples
// (POST scope.mf4), read back by duet::mdf4's reader; bad scope requests answered 400 with the problem.
#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>
#include <thread>

#include "duet/dashboard/dashboard.hpp"
#include "duet/mdf4/reader.hpp"
#include "duet/mdf4/summary.hpp"
#include "http_client.hpp"
#include "served_dashboard.hpp"
#include "websocket_client.hpp"

namespace duet::dashboard {
namespace {

namespace asio = boost::asio;
namespace http = boost::beast::http;
using nlohmann::json;
using testing::http_request;
using testing::WebSocketClient;

// A back end's dashboard whose target samples theta (float32), count (uint16), ratio (int16, but the values have
// halves, as a converted value would) and free (a type the back end does not know), every 10 ms.
class Backend : public testing::ServedDashboard {
 public:
  Backend()
      : ServedDashboard({"robot",
                         "monitor",
                         10000,
                         {{"theta", "deg", "float32", -90, 90},
                          {"count", "", "uint16", 0, 65535},
                          {"ratio", "%", "int16", -100, 100},
                          {"free", "V", "", 0, 0}},
                         {}}) {}
  // Samples k = 0 .. count-1 at k * 10 ms on the io_context's thread: theta rises through 0 at k = 50.
  void feed(int count) {
    std::vector<double> time_s;
    std::vector<std::vector<double>> values(4);
    for (int k = 0; k < count; ++k) {
      time_s.push_back(k * 0.01);
      values[0].push_back((k - 50) * 0.25);
      values[1].push_back(k);
      values[2].push_back(k * 0.5);
      values[3].push_back(k * 0.1);
    }
    asio::post(io, [this, time_s, values] { dashboard->samples(time_s, values); });
  }
};

mdf4::Reader read_back(const std::string& body) {
  auto reader = mdf4::Reader::from_bytes({body.begin(), body.end()}, "download");
  EXPECT_TRUE(reader.ok()) << (reader.ok() ? "" : reader.error());
  return std::move(reader.value());
}

std::vector<std::string> types_of(const mdf4::GroupInfo& group) {
  std::vector<std::string> types;
  for (const auto& channel : group.channels) types.push_back(channel.name + " " + mdf4::type_text(channel));
  return types;
}

TEST(Mdf4Downloads, TheDescriptionSaysWhereTheFilesAre) {
  Backend backend;
  WebSocketClient client{backend.port()};
  const auto description = client.next("description");
  ASSERT_TRUE(description.has_value());
  EXPECT_EQ((*description)["mdf4"]["recorder"], "recorder.mf4");
  EXPECT_EQ((*description)["mdf4"]["scope"], "scope.mf4");
  EXPECT_EQ((*description)["mdf4"]["max_request_bytes"], ServerOptions{}.max_upload_size);
}

TEST(Mdf4Downloads, TheRecordersLastCaptureIsAFileOfItsSignalsInTheirTypes) {
  Backend backend;
  const auto before = http_request(backend.port(), http::verb::get, "/recorder.mf4");
  EXPECT_EQ(before.result(), http::status::not_found);
  EXPECT_NE(before.body().find("no capture yet"), std::string::npos);

  WebSocketClient client{backend.port()};
  client.send(
      {{"type", "record"}, {"signal", "theta"}, {"level", 0}, {"edge", "rising"}, {"pre_s", 0.1}, {"post_s", 0.2}});
  const auto armed = client.next("recorder");
  ASSERT_TRUE(armed.has_value());
  ASSERT_EQ((*armed)["state"], "armed");
  backend.feed(100);
  const auto capture = client.next("capture");
  ASSERT_TRUE(capture.has_value());

  const auto file = http_request(backend.port(), http::verb::get, "/recorder.mf4?any=thing");
  ASSERT_EQ(file.result(), http::status::ok) << file.body();
  EXPECT_EQ(file[http::field::content_type], "application/octet-stream");
  EXPECT_TRUE(file[http::field::content_disposition].starts_with("attachment; filename=\"capture-theta-"));
  EXPECT_TRUE(file[http::field::content_disposition].ends_with(".mf4\""));
  const mdf4::Reader reader = read_back(file.body());
  EXPECT_TRUE(reader.info().finalised);
  ASSERT_EQ(reader.info().groups.size(), 1U);
  const mdf4::GroupInfo& group = reader.info().groups[0];
  EXPECT_EQ(group.name, "recorder");
  EXPECT_EQ(group.comment, "trigger: theta rising through 0 at 0.5 s; pre-trigger 0.1 s, post-trigger 0.2 s");
  EXPECT_EQ(types_of(group), (std::vector<std::string>{"time f64", "theta f32", "count u16", "ratio f64", "free f64"}));
  EXPECT_EQ(group.channels[1].unit, "deg");
  EXPECT_NE(group.channels[3].comment.find("described as int16"), std::string::npos);
  EXPECT_NE(group.channels[4].comment.find("not known"), std::string::npos);

  const json& time_s = (*capture)["time_s"];
  ASSERT_EQ(group.samples, time_s.size());
  ASSERT_GT(group.samples, 20U);
  std::size_t row = 0;
  const Status read = reader.for_each_record(0, [&](const mdf4::Record& record) {
    EXPECT_EQ(record.time(), time_s[row].get<double>());
    EXPECT_EQ(std::get<float>(record.value(1)), (*capture)["values"][0][row].get<float>());
    EXPECT_EQ(std::get<std::uint64_t>(record.value(2)), (*capture)["values"][1][row].get<std::uint64_t>());
    EXPECT_EQ(std::get<double>(record.value(3)), (*capture)["values"][2][row].get<double>());
    EXPECT_EQ(std::get<double>(record.value(4)), (*capture)["values"][3][row].get<double>());
    ++row;
  });
  EXPECT_TRUE(read.ok());
  EXPECT_EQ(row, time_s.size());

  EXPECT_EQ(http_request(backend.port(), http::verb::post, "/recorder.mf4", "{}").result(),
            http::status::method_not_allowed);
}

TEST(Mdf4Downloads, TheScopesSamplesComeBackAsAFileWithGapsAsMissingSamples) {
  Backend backend;
  const json request = {{"time_s", {0, 0.1, 0.1, 0.2}},
                        {"signals",
                         {{{"name", "theta"}, {"unit", "deg"}, {"values", {1.5, nullptr, 2.5, -3}}},
                          {{"name", "extra"}, {"unit", "V"}, {"values", {0.1, 0.2, 0.3, 0.4}}}}}};
  const auto file = http_request(backend.port(), http::verb::post, "/scope.mf4", request.dump());
  ASSERT_EQ(file.result(), http::status::ok) << file.body();
  EXPECT_TRUE(file[http::field::content_disposition].starts_with("attachment; filename=\"scope-"));
  const mdf4::Reader reader = read_back(file.body());
  ASSERT_EQ(reader.info().groups.size(), 1U);
  const mdf4::GroupInfo& group = reader.info().groups[0];
  EXPECT_EQ(group.name, "scope");
  EXPECT_EQ(types_of(group), (std::vector<std::string>{"time f64", "theta f32", "extra f64"}));
  EXPECT_EQ(group.channels[2].unit, "V");
  std::vector<double> times, theta, extra;
  std::vector<bool> theta_valid;
  ASSERT_TRUE(reader
                  .for_each_record(0,
                                   [&](const mdf4::Record& record) {
                                     times.push_back(record.time());
                                     theta.push_back(mdf4::to_double(record.value(1)));
                                     theta_valid.push_back(record.valid(1));
                                     extra.push_back(std::get<double>(record.value(2)));
                                   })
                  .ok());
  EXPECT_EQ(times, (std::vector<double>{0, 0.1, 0.1, 0.2}));
  EXPECT_EQ(theta_valid, (std::vector<bool>{true, false, true, true}));
  EXPECT_EQ(theta[0], 1.5);
  EXPECT_EQ(theta[3], -3);
  EXPECT_EQ(extra, (std::vector<double>{0.1, 0.2, 0.3, 0.4}));
}

struct BadScopeRequest {
  std::string body;
  std::string problem;  // part of the answer
};

TEST(Mdf4Downloads, ABadScopeRequestIsAnswered400WithItsProblem) {
  Backend backend;
  const std::string theta = R"({"name": "theta", "values": [1, 2]})";
  const std::vector<BadScopeRequest> requests = {
      {"not json", "not JSON"},
      {"[1, 2]", "not a JSON object"},
      {R"({"signals": [)" + theta + "]}", "\"time_s\" must be an array"},
      {R"({"time_s": [], "signals": [)" + theta + "]}", "\"time_s\" is empty"},
      {R"({"time_s": [0, "1"], "signals": [)" + theta + "]}", "\"time_s\"[1] is not a number"},
      {R"({"time_s": [0, 1, 0.5], "signals": [{"name": "theta", "values": [1, 2, 3]}]})",
       "\"time_s\"[2] (0.5) is before"},
      {R"({"time_s": [0, 1e999], "signals": [)" + theta + "]}", "scope.mf4: "},
      {R"({"time_s": [0, 1]})", "\"signals\" must be a non-empty array"},
      {R"({"time_s": [0, 1], "signals": []})", "\"signals\" must be a non-empty array"},
      {R"({"time_s": [0, 1], "signals": [{"values": [1, 2]}]})", "\"signals\"[0] has no \"name\""},
      {R"({"time_s": [0, 1], "signals": [{"name": "", "values": [1, 2]}]})", "\"signals\"[0] has no \"name\""},
      {R"({"time_s": [0, 1], "signals": [{"name": "theta", "values": [1]}]})", "has 1 values for 2 times"},
      {R"({"time_s": [0, 1], "signals": [{"name": "theta", "values": [1, "2"]}]})",
       "value 1 is neither a number nor null"},
      {R"({"time_s": [0, 1], "signals": [{"name": "theta", "unit": 3, "values": [1, 2]}]})",
       "\"unit\" is not a string"},
      {R"({"time_s": [0, 1], "signals": [)" + theta + "," + theta + "]}", "'theta' is there twice"},
      {R"({"time_s": [0, 1], "signals": [)" + theta + R"(], "colour": "red"})", "member 'colour'"},
      {R"({"time_s": [0, 1], "signals": [{"name": "theta", "values": [1, 2], "scale": 2}]})", "member 'scale'"},
  };
  for (const BadScopeRequest& bad : requests) {
    const auto answer = http_request(backend.port(), http::verb::post, "/scope.mf4", bad.body);
    EXPECT_EQ(answer.result(), http::status::bad_request) << bad.body;
    EXPECT_NE(answer.body().find(bad.problem), std::string::npos) << bad.body << " -> " << answer.body();
  }
  std::string many = R"({"time_s": [0)";
  for (int sample = 1; sample <= 400'000; ++sample) many += ",0";
  const auto too_many = http_request(backend.port(), http::verb::post, "/scope.mf4", many + R"(], "signals": []})");
  EXPECT_EQ(too_many.result(), http::status::bad_request);
  EXPECT_NE(too_many.body().find("400001 samples, more than 400000"), std::string::npos);
  EXPECT_EQ(http_request(backend.port(), http::verb::get, "/scope.mf4").result(), http::status::method_not_allowed);
}

}  // namespace
}  // namespace duet::dashboard
