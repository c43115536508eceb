// The firmware's end and the PC's end of the application channel, talking through a byte pipe.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "duet/app_channel/endpoint.hpp"
#include "duet/app_channel/host/peer.hpp"

namespace duet::app_channel {
namespace {

using host::Description;
using host::ParameterReport;
using host::Peer;
using host::Sample;

struct Robot {
  float theta = 1.5F;
  float battery = 7.4F;
  std::uint16_t distance = 42;
  float p = 0.0196F;
  float i = 0.0F;
  double d = 0.0187;
  std::int8_t mode = 0;
};

// The firmware's end of an application, with the queue and buffers it needs.
struct FirmwareEnd {
  explicit FirmwareEnd(const Application& application)
      : endpoint{application, queue, {}, decoder_buffer, packet_buffer} {}
  std::array<std::uint8_t, 512> ring{};
  xcp::TransmitQueue queue{ring, {}};
  std::array<std::uint8_t, decoder_buffer_size> decoder_buffer{};
  std::array<std::uint8_t, max_packet> packet_buffer{};
  Endpoint endpoint;
};

class AppChannel : public ::testing::Test {
 protected:
  // Firmware -> PC until nothing is left, through a line that takes `line_size` bytes at a time (the framer sends
  // whole frames only: the largest, an item or a task with a 63-byte name, needs 92).
  template <std::size_t line_size = 64>
  void exchange() {
    std::array<std::uint8_t, line_size> line{};
    while (const std::size_t sent = endpoint.transmit(line)) peer.receive(std::span{line}.first(sent));
  }
  void request(const std::vector<std::uint8_t>& frame) {
    endpoint.receive(frame);
    exchange();
  }

  Robot robot;
  const std::array<Item, 3> telemetry{item("theta", "deg", robot.theta, -90, 90),
                                      item("battery", "V", robot.battery, 0, 12.6),
                                      item("distance", "cm", robot.distance, 0, 400)};
  const std::array<Item, 4> parameters{item("P", "", robot.p, 0, 1), item("I", "", robot.i, 0, 1),
                                       item("D", "", robot.d, 0, 1), item("mode", "", robot.mode, -1, 3)};
  const Application application{"balbot", 10000, telemetry, parameters};
  FirmwareEnd firmware{application};
  Endpoint& endpoint = firmware.endpoint;

  std::vector<Description> descriptions;
  std::vector<Sample> samples;
  std::vector<ParameterReport> reports;
  std::vector<host::ExecutiveReport> executives;
  std::vector<std::string> problems;
  Peer peer{{.description = [this](const Description& d) { descriptions.push_back(d); },
             .telemetry = [this](const Sample& s) { samples.push_back(s); },
             .parameter = [this](const ParameterReport& r) { reports.push_back(r); },
             .executive = [this](const host::ExecutiveReport& e) { executives.push_back(e); },
             .problem = [this](const std::string& p) { problems.push_back(p); }}};
};

TEST_F(AppChannel, TheFirmwareDescribesItselfAtStart) {
  exchange();
  ASSERT_EQ(descriptions.size(), 1U);
  const Description& description = descriptions[0];
  EXPECT_EQ(description.application, "balbot");
  EXPECT_EQ(description.telemetry_period_us, 10000U);
  ASSERT_EQ(description.telemetry.size(), 3U);
  EXPECT_EQ(description.telemetry[1].name, "battery");
  EXPECT_EQ(description.telemetry[1].unit, "V");
  EXPECT_EQ(description.telemetry[2].type, ValueType::u16);
  EXPECT_DOUBLE_EQ(description.telemetry[1].maximum, 12.6);
  ASSERT_EQ(description.parameters.size(), 4U);
  EXPECT_EQ(description.parameters[2].name, "D");
  EXPECT_EQ(description.parameters[2].type, ValueType::f64);
  ASSERT_EQ(reports.size(), 4U);  // and every parameter's value
  EXPECT_EQ(reports[0].status, ParameterStatus::reported);
  EXPECT_FLOAT_EQ(static_cast<float>(*peer.parameter_values()[0]), 0.0196F);
  EXPECT_DOUBLE_EQ(*peer.parameter_values()[2], 0.0187);
  EXPECT_TRUE(problems.empty());
}

TEST_F(AppChannel, TheExecutivesAccountArrivesWhole) {
  exchange();
  const std::array<TaskReport, 2> tasks{
      TaskReport{"rate 1", 1000, 0, 180, 186, 240},
      TaskReport{"a task whose name is longer than sixty-three characters, cut short", 100, 2, 500, 520, 900}};
  ASSERT_TRUE(endpoint.publish_executive({.ticks = 0x1'0000'0005ULL,
                                          .base_period_ns = 1'000'000,
                                          .busy_ppm = 52'000,
                                          .overruns = 2,
                                          .cycle_hz = 25'000'000,
                                          .tasks = tasks}));
  exchange<128>();
  ASSERT_EQ(executives.size(), 1U);
  const host::ExecutiveReport& report = executives[0];
  EXPECT_EQ(report.ticks, 0x1'0000'0005ULL);
  EXPECT_EQ(report.busy_ppm, 52'000U);
  EXPECT_EQ(report.cycle_hz, 25'000'000U);
  ASSERT_EQ(report.tasks.size(), 2U);
  EXPECT_EQ(report.tasks[0].name, "rate 1");
  EXPECT_EQ(report.tasks[0].mean_cycles, 186U);
  EXPECT_EQ(report.tasks[1].name.size(), max_name_length);
  EXPECT_EQ(report.tasks[1].overruns, 2U);
  EXPECT_TRUE(problems.empty());
}

TEST_F(AppChannel, AnAccountWithATaskLostIsNotHandedOn) {
  exchange();
  const std::array<TaskReport, 2> tasks{TaskReport{"rate 1", 1, 0, 1, 1, 1}, TaskReport{"rate 10", 1, 0, 1, 1, 1}};
  ASSERT_TRUE(endpoint.publish_executive({.ticks = 1, .cycle_hz = 1, .tasks = tasks}));
  // The line loses the frame of the first task: the executive packet's frame is 4 + 26 + 2 bytes, the task's next
  // 4 + 29 + 1 (fill) + 2.
  std::array<std::uint8_t, 512> line{};
  std::size_t sent = 0;
  while (const std::size_t more = endpoint.transmit(std::span{line}.subspan(sent))) sent += more;
  const std::size_t executive_frame = 4 + 26 + 2;
  const std::size_t task_frame = 4 + 29 + 1 + 2;
  peer.receive(std::span{line}.first(executive_frame));
  peer.receive(std::span{line}.subspan(executive_frame + task_frame, sent - executive_frame - task_frame));
  EXPECT_TRUE(executives.empty());
  ASSERT_TRUE(endpoint.publish_executive({.ticks = 2, .cycle_hz = 1, .tasks = tasks}));
  exchange();
  ASSERT_EQ(executives.size(), 1U);
  EXPECT_EQ(executives[0].ticks, 2U);
}

TEST_F(AppChannel, TelemetryArrivesAsNamedValues) {
  exchange();
  for (std::uint32_t step = 0; step < 5; ++step) {
    robot.theta = static_cast<float>(step);
    ASSERT_TRUE(endpoint.publish(step));
  }
  exchange();
  ASSERT_EQ(samples.size(), 5U);
  EXPECT_EQ(samples[3].sample, 3U);
  EXPECT_DOUBLE_EQ(samples[3].values[0], 3.0);
  EXPECT_FLOAT_EQ(static_cast<float>(samples[3].values[1]), 7.4F);
  EXPECT_DOUBLE_EQ(samples[3].values[2], 42.0);
  EXPECT_EQ(peer.counters().samples, 5U);
  EXPECT_EQ(peer.counters().frames_lost, 0U);
}

TEST_F(AppChannel, ParametersAreSetWithinTheirLimits) {
  exchange();
  reports.clear();
  request(peer.set_request("P", 0.5).value());
  request(peer.set_request("D", 0.25).value());
  request(peer.set_request("mode", -1).value());
  EXPECT_FLOAT_EQ(robot.p, 0.5F);
  EXPECT_DOUBLE_EQ(robot.d, 0.25);
  EXPECT_EQ(robot.mode, -1);
  ASSERT_EQ(reports.size(), 3U);
  EXPECT_EQ(reports[1].status, ParameterStatus::applied);
  EXPECT_DOUBLE_EQ(*reports[1].value, 0.25);
  EXPECT_DOUBLE_EQ(*peer.parameter_values()[3], -1.0);
}

TEST_F(AppChannel, ThePcRefusesWhatTheFirmwareWouldNotTake) {
  EXPECT_NE(peer.set_request("P", 0.5).error().find("not described"), std::string::npos);
  exchange();
  EXPECT_NE(peer.set_request("Q", 0.5).error().find("no parameter named 'Q'"), std::string::npos);
  EXPECT_NE(peer.set_request("P", 2).error().find("outside its limits"), std::string::npos);
  EXPECT_NE(peer.set_request("P", std::nan("")).error().find("not a number"), std::string::npos);
  EXPECT_NE(peer.set_request("mode", 1.5).error().find("integer"), std::string::npos);
}

TEST_F(AppChannel, TheFirmwareClampsAndRejectsOnItsOwn) {
  exchange();
  reports.clear();
  // Requests another PC might send: out of limits, a wrong index, a wrong size.
  const auto frame = [](std::vector<std::uint8_t> packet) {
    std::vector<std::uint8_t> bytes(framing.frame_size(packet.size()));
    bytes.resize(xcp::write_frame(framing, bytes, 0, packet));
    return bytes;
  };
  const float too_large = 5.0F;
  std::vector<std::uint8_t> set_p{0x82, 0};
  set_p.insert(set_p.end(), reinterpret_cast<const std::uint8_t*>(&too_large),
               reinterpret_cast<const std::uint8_t*>(&too_large) + 4);
  request(frame(set_p));
  request(frame({0x82, 9, 0, 0, 0, 0}));
  request(frame({0x82, 0, 1}));
  request(frame({0x82}));
  ASSERT_EQ(reports.size(), 4U);
  EXPECT_EQ(reports[0].status, ParameterStatus::clamped);
  EXPECT_FLOAT_EQ(robot.p, 1.0F);
  EXPECT_EQ(reports[1].status, ParameterStatus::unknown_parameter);
  EXPECT_EQ(reports[2].status, ParameterStatus::malformed);
  EXPECT_EQ(reports[3].status, ParameterStatus::unknown_parameter);
  EXPECT_FLOAT_EQ(robot.p, 1.0F);
}

// The firmware checks a value against its limits in the value's own type (a double by the order of its bits, so that
// the Cortex-M4 needs no software double): every type, negative limits, an integer's fractional limits (rounded
// inward), -0 and NaN.
TEST(AppChannelLimits, EachTypeIsCheckedInItsOwnType) {
  struct Values {
    double wide = 0;
    float narrow = 0;
    std::int16_t count = 0;
    std::uint8_t level = 0;
  } values;
  const std::array<Item, 0> telemetry{};
  const std::array<Item, 4> parameters{
      item("wide", "", values.wide, -2.5, -0.5), item("narrow", "", values.narrow, -1, 1),
      item("count", "", values.count, -3.5, 2.5), item("level", "", values.level, 0.5, 1000)};
  const Application application{"limits", 1000, telemetry, parameters};
  FirmwareEnd firmware{application};
  std::vector<ParameterReport> reports;
  Peer peer{{.parameter = [&reports](const ParameterReport& report) { reports.push_back(report); }}};
  const auto set = [&](std::uint8_t index, auto value) {
    std::vector<std::uint8_t> packet{0x82, index};
    const auto bytes = std::bit_cast<std::array<std::uint8_t, sizeof value>>(value);
    packet.insert(packet.end(), bytes.begin(), bytes.end());
    std::vector<std::uint8_t> frame(framing.frame_size(packet.size()));
    frame.resize(xcp::write_frame(framing, frame, 0, packet));
    firmware.endpoint.receive(frame);
    std::array<std::uint8_t, 64> line{};
    while (const std::size_t sent = firmware.endpoint.transmit(line)) peer.receive(std::span{line}.first(sent));
    return reports.back().status;
  };
  EXPECT_EQ(set(0, -1.0), ParameterStatus::applied);
  EXPECT_EQ(values.wide, -1.0);
  EXPECT_EQ(set(0, -0.4), ParameterStatus::clamped);  // above -0.5: the bits of negative doubles order reversed
  EXPECT_EQ(values.wide, -0.5);
  EXPECT_EQ(set(0, -3.0), ParameterStatus::clamped);
  EXPECT_EQ(values.wide, -2.5);
  EXPECT_EQ(set(0, 1e300), ParameterStatus::clamped);
  EXPECT_EQ(values.wide, -0.5);
  EXPECT_EQ(set(0, std::numeric_limits<double>::quiet_NaN()), ParameterStatus::clamped);
  EXPECT_EQ(values.wide, -2.5);  // NaN to the lower limit
  EXPECT_EQ(set(1, -0.0F), ParameterStatus::applied);
  EXPECT_EQ(set(1, 1.5F), ParameterStatus::clamped);
  EXPECT_EQ(values.narrow, 1.0F);
  EXPECT_EQ(set(1, -std::numeric_limits<float>::infinity()), ParameterStatus::clamped);
  EXPECT_EQ(values.narrow, -1.0F);
  EXPECT_EQ(set(2, std::int16_t{-3}), ParameterStatus::applied);
  EXPECT_EQ(set(2, std::int16_t{-4}), ParameterStatus::clamped);  // -3.5 rounds in to -3
  EXPECT_EQ(values.count, -3);
  EXPECT_EQ(set(2, std::int16_t{3}), ParameterStatus::clamped);  // 2.5 rounds in to 2
  EXPECT_EQ(values.count, 2);
  EXPECT_EQ(set(3, std::uint8_t{0}), ParameterStatus::clamped);  // 0.5 rounds in to 1
  EXPECT_EQ(values.level, 1);
  EXPECT_EQ(set(3, std::uint8_t{255}), ParameterStatus::applied);  // 1000 saturates at the type's 255
  EXPECT_EQ(values.level, 255);
}

TEST_F(AppChannel, ADescribeRequestRepeatsTheDescription) {
  exchange();
  request(peer.describe_request());
  EXPECT_EQ(descriptions.size(), 2U);
}

TEST_F(AppChannel, GarbageAndLostBytesAreSurvived) {
  std::array<std::uint8_t, 512> line{};
  std::vector<std::uint8_t> stream;
  for (std::size_t sent = endpoint.transmit(line); sent != 0; sent = endpoint.transmit(line)) {
    stream.insert(stream.end(), line.begin(), line.begin() + static_cast<std::ptrdiff_t>(sent));
  }
  for (std::uint32_t step = 0; step < 20; ++step) (void)endpoint.publish(step);
  const std::size_t description_bytes = stream.size();
  for (std::size_t sent = endpoint.transmit(line); sent != 0; sent = endpoint.transmit(line)) {
    stream.insert(stream.end(), line.begin(), line.begin() + static_cast<std::ptrdiff_t>(sent));
  }
  stream.erase(stream.begin() + static_cast<std::ptrdiff_t>(description_bytes) + 30);  // a byte lost in sample 1
  stream.insert(stream.begin(), {0x55, 0x13, 0x00, 0xFF, 0x04});                       // noise before it all
  peer.receive(stream);
  ASSERT_EQ(descriptions.size(), 1U);
  EXPECT_GE(samples.size(), 18U);  // the damaged sample is gone, the rest arrive
  EXPECT_LT(samples.size(), 20U);
  EXPECT_EQ(samples.back().sample, 19U);
  EXPECT_GT(peer.counters().garbage_bytes, 0U);
  EXPECT_GE(peer.counters().frames_lost, 1U);
}

TEST_F(AppChannel, AFullQueueDropsTelemetryButNeverAnswers) {
  exchange();
  reports.clear();
  std::uint32_t published = 0;
  while (endpoint.publish(published)) ++published;
  EXPECT_EQ(endpoint.samples_dropped(), 1U);
  request(peer.set_request("I", 0.1).value());
  ASSERT_EQ(reports.size(), 1U);
  EXPECT_EQ(reports[0].status, ParameterStatus::applied);
  EXPECT_EQ(samples.size(), published);
}

TEST_F(AppChannel, AnAccountThatDoesNotFitIsCounted) {
  exchange();
  std::uint32_t published = 0;
  while (endpoint.publish(published)) ++published;
  EXPECT_EQ(endpoint.reports_dropped(), 0U);
  EXPECT_FALSE(endpoint.publish_executive({.ticks = 1, .cycle_hz = 1}));
  EXPECT_EQ(endpoint.reports_dropped(), 1U);
}

TEST_F(AppChannel, AnswersThatFindTheQueueFullAreCounted) {
  exchange();
  std::uint32_t published = 0;
  while (endpoint.publish(published)) ++published;
  const std::vector<std::uint8_t> request = peer.set_request("I", 0.1).value();
  for (int k = 0; k < 8; ++k) endpoint.receive(request);  // a peer that writes without reading
  EXPECT_GT(endpoint.answers_dropped(), 0U);
  EXPECT_LT(endpoint.answers_dropped(), 8U);  // the room kept for answers took some
}

TEST_F(AppChannel, AValueChangedByOtherMeansIsReported) {
  exchange();
  reports.clear();
  robot.p = 0.05F;  // as the application would after taking a gain from elsewhere
  EXPECT_TRUE(endpoint.report(0));
  EXPECT_FALSE(endpoint.report(9));
  exchange();
  ASSERT_EQ(reports.size(), 1U);
  EXPECT_EQ(reports[0].status, ParameterStatus::reported);
  EXPECT_FLOAT_EQ(static_cast<float>(*reports[0].value), 0.05F);
}

TEST(AppChannelLabels, NamedValuesArriveWithTheirNames) {
  std::uint8_t state = 1;
  std::uint8_t controller = 0;
  static constexpr const char* state_names[] = {"initialising", "balancing", "stopped"};
  static constexpr const char* controller_names[] = {"PID", "LQR"};
  const std::array<Item, 1> telemetry{named_item("state", state, state_names)};
  const std::array<Item, 1> parameters{named_item("controller", controller, controller_names)};
  const Application application{"robot", 10000, telemetry, parameters};
  FirmwareEnd firmware{application};
  std::vector<Description> descriptions;
  Peer peer{{.description = [&](const Description& d) { descriptions.push_back(d); }}};
  std::array<std::uint8_t, 256> line{};
  while (const std::size_t sent = firmware.endpoint.transmit(line)) peer.receive(std::span{line}.first(sent));
  ASSERT_EQ(descriptions.size(), 1U);
  EXPECT_EQ(descriptions[0].telemetry[0].labels, (std::vector<std::string>{"initialising", "balancing", "stopped"}));
  EXPECT_DOUBLE_EQ(descriptions[0].telemetry[0].maximum, 2);
  EXPECT_EQ(descriptions[0].parameters[0].labels, (std::vector<std::string>{"PID", "LQR"}));
  EXPECT_FALSE(peer.set_request("controller", 2).ok());  // beyond the last name
}

// Item packets as docs/APP_CHANNEL.md lays them out, written here byte by byte: with value names, and without them as
// firmware before names sent them.
TEST(AppChannelLabels, ThePcReadsItemsWithAndWithoutNames) {
  std::vector<Description> descriptions;
  std::vector<std::string> problems;
  Peer peer{{.description = [&](const Description& d) { descriptions.push_back(d); },
             .problem = [&](const std::string& p) { problems.push_back(p); }}};
  std::uint16_t counter = 0;
  const auto send = [&](std::vector<std::uint8_t> packet) {
    std::vector<std::uint8_t> bytes(framing.frame_size(packet.size()));
    bytes.resize(xcp::write_frame(framing, bytes, counter++, packet));
    peer.receive(bytes);
  };
  const auto item = [](std::uint8_t index, std::vector<std::uint8_t> tail) {
    std::vector<std::uint8_t> packet{0x02, 0, index, 1};          // item, telemetry, index, uint8
    for (int k = 0; k < 8; ++k) packet.push_back(0);              // minimum 0.0
    packet.insert(packet.end(), {0, 0, 0, 0, 0, 0, 0xF0, 0x3F});  // maximum 1.0
    packet.insert(packet.end(), tail.begin(), tail.end());
    return packet;
  };
  send({0x01, 1, 1, 'r', 0x10, 0x27, 0, 0, 2, 0});                    // hello: version 1, "r", 10000 us, 2 and 0 items
  send(item(0, {2, 'o', 'n', 0, 2, 2, 'n', 'o', 3, 'y', 'e', 's'}));  // "on", no unit, names "no" and "yes"
  send(item(1, {1, 'x', 1, 'V'}));                                    // "x" in V, no names
  send({0x03});
  EXPECT_TRUE(problems.empty()) << problems.front();
  ASSERT_EQ(descriptions.size(), 1U);
  EXPECT_EQ(descriptions[0].telemetry[0].name, "on");
  EXPECT_EQ(descriptions[0].telemetry[0].labels, (std::vector<std::string>{"no", "yes"}));
  EXPECT_EQ(descriptions[0].telemetry[1].unit, "V");
  EXPECT_TRUE(descriptions[0].telemetry[1].labels.empty());
  send(item(0, {2, 'o', 'n', 0, 3, 2, 'n', 'o'}));  // three names announced, one follows
  ASSERT_EQ(problems.size(), 1U);
  EXPECT_EQ(problems[0], "an item description is malformed");
}

}  // namespace
}  // namespace duet::app_channel
