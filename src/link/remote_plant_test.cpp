// RemotePlant and serve() talking over a socket pair, the plant's side in a thread: values and interrupts as with a
// plant in the same process, and peers that break the conversation in every way that gives a clear failure.
#include "duet/link/remote_plant.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "duet/link/channel.hpp"
#include "duet/link/serve.hpp"
#include "duet/plant/plant.hpp"

namespace duet::link {
namespace {

using namespace std::chrono_literals;

constexpr RemotePlantOptions one_ms{LinkMode::lock_step, 1'000'000};
constexpr Hello hello_one_ms{protocol_version, LinkMode::lock_step, 1'000'000};

// serve() in a thread of its own over one end of a stream pair; the other end is the firmware's.
class PlantThread {
 public:
  PlantThread(plant::Plant& plant, std::unique_ptr<Stream> stream)
      : stream_(std::move(stream)), thread_([this, &plant] { result_.emplace(serve(plant, *stream_)); }) {}
  ~PlantThread() {
    if (thread_.joinable()) thread_.join();
  }
  Result<ServeSummary> finish() {
    thread_.join();
    return *result_;
  }

 private:
  std::unique_ptr<Stream> stream_;
  std::optional<Result<ServeSummary>> result_;
  std::thread thread_;
};

// A scripted peer: whatever a test wants the other end to do, frame by frame.
class Peer {
 public:
  explicit Peer(std::unique_ptr<Stream> stream, std::string name)
      : stream_(std::move(stream)), channel_(*stream_, std::move(name)) {}
  // The kind of the next frame (or BYE for the end of the stream).
  FrameKind expect_frame() {
    auto received = channel_.receive("a frame");
    EXPECT_TRUE(received.ok()) << received.error();
    if (!received.ok() || !received.value()) return FrameKind::bye;
    payload_.assign(received.value()->payload.begin(), received.value()->payload.end());
    return received.value()->kind;
  }
  [[nodiscard]] const std::vector<std::uint8_t>& payload() const { return payload_; }
  Channel& channel() { return channel_; }
  Stream& stream() { return *stream_; }
  void close() { stream_.reset(); }

 private:
  std::unique_ptr<Stream> stream_;
  Channel channel_;
  std::vector<std::uint8_t> payload_;
};

struct Linked {
  std::unique_ptr<FdStream> firmware;
  std::unique_ptr<FdStream> plant;
};
Linked linked(Timeout timeout = 2s) {
  auto pair = socket_pair(timeout);
  EXPECT_TRUE(pair.ok()) << (pair.ok() ? "" : pair.error());
  return {std::move(pair.value().first), std::move(pair.value().second)};
}

TEST(RemotePlant, ALoopbackOverTheLinkAnswersWhatWasWritten) {
  plant::Loopback loopback;
  Linked link = linked();
  PlantThread plant_side{loopback, std::move(link.plant)};
  auto connected = RemotePlant::connect(std::move(link.firmware), one_ms);
  ASSERT_TRUE(connected.ok()) << connected.error();
  RemotePlant& remote = *connected.value();
  const double duty[] = {0.25, -0.5, 1e-300};
  remote.write("pwm:TIM1/1", duty);
  remote.advance(0.0, {});
  double back[3] = {9, 9, 9};
  remote.read("pwm:TIM1/1", back);
  EXPECT_EQ(std::vector<double>(back, back + 3), std::vector<double>(duty, duty + 3));
  double never[2] = {9, 9};
  remote.read("gpio:LED0", never);
  EXPECT_EQ(never[0], 0.0);
  EXPECT_EQ(never[1], 0.0);
  remote.advance(0.001, {});
  EXPECT_TRUE(remote.ok());
  EXPECT_TRUE(remote.close().ok());
  auto summary = plant_side.finish();
  ASSERT_TRUE(summary.ok()) << summary.error();
  EXPECT_TRUE(summary.value().said_bye);
  EXPECT_EQ(summary.value().ticks, 2U);
  EXPECT_EQ(summary.value().writes, 1U);
  EXPECT_EQ(summary.value().reads, 2U);
  EXPECT_EQ(summary.value().hello.base_period_ns, 1'000'000U);
  EXPECT_EQ(summary.value().hello.mode, LinkMode::lock_step);
  EXPECT_EQ(loopback.value("pwm:TIM1/1"), std::vector<double>(duty, duty + 3));
}

// A plant that raises interrupts in advance() and writes down everything it sees, in order.
class ScriptedPlant : public plant::Plant {
 public:
  void advance(double time_s, const plant::RaiseInterrupt& raise) override {
    log.push_back("advance " + std::to_string(time_s));
    sensor_ = time_s * 100;
    if (time_s > 0) {
      raise("EXTI0");
      log.emplace_back("EXTI0 done");
      raise("TIM2");
      log.emplace_back("TIM2 done");
    }
  }
  void write(std::string_view resource, std::span<const double> values) override {
    log.push_back("write " + std::string{resource} + " " + std::to_string(values[0]));
  }
  void read(std::string_view resource, std::span<double> values) override {
    log.push_back("read " + std::string{resource});
    for (double& value : values) value = sensor_;
  }
  std::vector<std::string> log;

 private:
  double sensor_ = 0;
};

TEST(RemotePlant, InterruptsRunTheFirmwaresTaskInTheMiddleOfTheTick) {
  ScriptedPlant scripted;
  Linked link = linked();
  PlantThread plant_side{scripted, std::move(link.plant)};
  auto connected = RemotePlant::connect(std::move(link.firmware), one_ms);
  ASSERT_TRUE(connected.ok()) << connected.error();
  RemotePlant& remote = *connected.value();
  std::vector<std::string> raised;
  // The interrupt task reads its sensor and writes what it read, over the link, while the plant waits in raise().
  const plant::RaiseInterrupt raise = [&](std::string_view name) {
    raised.emplace_back(name);
    double sample[2] = {};
    remote.read("adc:" + std::string{name}, sample);
    remote.write("gpio:" + std::string{name}, std::span<const double>{sample, 1});
  };
  remote.advance(0.0, raise);
  remote.advance(0.5, raise);
  EXPECT_TRUE(remote.ok()) << remote.error();
  EXPECT_EQ(remote.interrupts(), 2U);
  EXPECT_EQ(remote.ticks(), 2U);
  connected.value().reset();  // BYE
  auto summary = plant_side.finish();
  ASSERT_TRUE(summary.ok()) << summary.error();
  EXPECT_EQ(summary.value().interrupts, 2U);
  EXPECT_EQ(raised, (std::vector<std::string>{"EXTI0", "TIM2"}));
  EXPECT_EQ(scripted.log, (std::vector<std::string>{"advance 0.000000", "advance 0.500000", "read adc:EXTI0",
                                                    "write gpio:EXTI0 50.000000", "EXTI0 done", "read adc:TIM2",
                                                    "write gpio:TIM2 50.000000", "TIM2 done"}));
}

TEST(RemotePlant, APipePairWorksAsWell) {
  plant::Loopback loopback;
  auto pair = pipe_pair(2s);
  ASSERT_TRUE(pair.ok());
  PlantThread plant_side{loopback, std::move(pair.value().second)};
  auto connected = RemotePlant::connect(std::move(pair.value().first), one_ms);
  ASSERT_TRUE(connected.ok()) << connected.error();
  const double one = 1;
  connected.value()->write("gpio:LED0", {&one, 1});
  double back = 0;
  connected.value()->read("gpio:LED0", {&back, 1});
  EXPECT_EQ(back, 1.0);
  connected.value().reset();
  EXPECT_TRUE(plant_side.finish().ok());
}

TEST(RemotePlant, RealTimeSendsEachTickWhenItsTimeComes) {
  plant::Loopback loopback;
  Linked link = linked();
  PlantThread plant_side{loopback, std::move(link.plant)};
  auto connected = RemotePlant::connect(std::move(link.firmware), {LinkMode::real_time, 10'000'000});
  ASSERT_TRUE(connected.ok()) << connected.error();
  const auto start = std::chrono::steady_clock::now();
  for (int tick = 0; tick < 5; ++tick) connected.value()->advance(tick * 0.01, {});
  EXPECT_GE(std::chrono::steady_clock::now() - start, 40ms);
  connected.value().reset();
  auto summary = plant_side.finish();
  ASSERT_TRUE(summary.ok());
  EXPECT_EQ(summary.value().hello.mode, LinkMode::real_time);
  EXPECT_EQ(summary.value().ticks, 5U);
}

// The firmware's side against a scripted plant that answers HELLO and then misbehaves in `script`.
RemotePlant& connect_to(Peer& plant_peer, std::unique_ptr<Stream> firmware, std::unique_ptr<RemotePlant>& remote,
                        std::thread& script_thread, const std::function<void(Peer&)>& script) {
  script_thread = std::thread{[&plant_peer, script] {
    EXPECT_EQ(plant_peer.expect_frame(), FrameKind::hello);
    EXPECT_TRUE(plant_peer.channel().send_hello_ok({}).ok());
    EXPECT_TRUE(plant_peer.channel().flush().ok());
    script(plant_peer);
  }};
  auto connected = RemotePlant::connect(std::move(firmware), one_ms);
  EXPECT_TRUE(connected.ok()) << connected.error();
  remote = std::move(connected).value();
  return *remote;
}

TEST(RemotePlant, APlantThatClosesInTheMiddleOfAFrame) {
  Linked link = linked();
  Peer plant_peer{std::move(link.plant), "the firmware"};
  std::unique_ptr<RemotePlant> remote;
  std::thread script;
  RemotePlant& plant = connect_to(plant_peer, std::move(link.firmware), remote, script, [](Peer& peer) {
    EXPECT_EQ(peer.expect_frame(), FrameKind::read);
    std::array<std::uint8_t, max_frame> buffer{};
    const double values[2] = {1, 2};
    const auto frame = encode_values(buffer, std::span<const double>{values});
    EXPECT_TRUE(peer.stream().write_all(frame.first(7)).ok());
    peer.close();
  });
  double values[2] = {5, 5};
  plant.read("adc:ADC1/6", values);
  script.join();
  ASSERT_FALSE(plant.ok());
  EXPECT_EQ(plant.error(),
            "the plant closed the link in the middle of a VALUES frame (7 of 22 bytes) while awaiting VALUES");
  EXPECT_EQ(values[0], 0.0);
  plant.advance(1.0, {});  // does nothing now: the failure stays the first one
  EXPECT_EQ(plant.error(),
            "the plant closed the link in the middle of a VALUES frame (7 of 22 bytes) while awaiting VALUES");
}

TEST(RemotePlant, APlantThatReportsAnError) {
  Linked link = linked();
  Peer plant_peer{std::move(link.plant), "the firmware"};
  std::unique_ptr<RemotePlant> remote;
  std::thread script;
  RemotePlant& plant = connect_to(plant_peer, std::move(link.firmware), remote, script, [](Peer& peer) {
    EXPECT_EQ(peer.expect_frame(), FrameKind::tick);
    EXPECT_TRUE(peer.channel().fail("the robot fell over").message == "the robot fell over");
  });
  plant.advance(0.0, {});
  script.join();
  ASSERT_FALSE(plant.ok());
  EXPECT_EQ(plant.error(), "the plant reported an error: the robot fell over");
}

TEST(RemotePlant, APlantThatAnswersWithTheWrongFrame) {
  Linked link = linked();
  Peer plant_peer{std::move(link.plant), "the firmware"};
  std::unique_ptr<RemotePlant> remote;
  std::thread script;
  RemotePlant& plant = connect_to(plant_peer, std::move(link.firmware), remote, script, [](Peer& peer) {
    EXPECT_EQ(peer.expect_frame(), FrameKind::tick);
    EXPECT_TRUE(peer.channel().send_empty(FrameKind::interrupt_done).ok());
    EXPECT_EQ(peer.expect_frame(), FrameKind::error);  // the firmware says what was wrong
    ErrorText text;
    EXPECT_EQ(parse(peer.payload(), text), FrameError::none);
    EXPECT_EQ(text.text, "the plant sent INTERRUPT_DONE where the firmware awaited TICK_DONE or INTERRUPT");
  });
  plant.advance(0.0, {});
  script.join();
  ASSERT_FALSE(plant.ok());
  EXPECT_EQ(plant.error(), "the plant sent INTERRUPT_DONE where the firmware awaited TICK_DONE or INTERRUPT");
}

TEST(RemotePlant, APlantThatSendsGarbage) {
  Linked link = linked();
  Peer plant_peer{std::move(link.plant), "the firmware"};
  std::unique_ptr<RemotePlant> remote;
  std::thread script;
  RemotePlant& plant = connect_to(plant_peer, std::move(link.firmware), remote, script, [](Peer& peer) {
    EXPECT_EQ(peer.expect_frame(), FrameKind::read);
    const std::uint8_t garbage[] = {0x05, 0xFF, 0xFF, 1, 2, 3};
    EXPECT_TRUE(peer.stream().write_all(garbage).ok());
  });
  double value = 0;
  plant.read("adc:ADC1/6", {&value, 1});
  script.join();
  ASSERT_FALSE(plant.ok());
  EXPECT_EQ(plant.error(),
            "the plant sent a bad frame (payload too long: VALUES announcing 65535 bytes) while awaiting VALUES");
}

TEST(RemotePlant, ASilentPlantTimesOut) {
  Linked link = linked(50ms);
  Peer plant_peer{std::move(link.plant), "the firmware"};  // never answers
  auto connected = RemotePlant::connect(std::move(link.firmware), one_ms);
  ASSERT_FALSE(connected.ok());
  EXPECT_EQ(connected.error(), "link to the plant: nothing received for 50 ms while awaiting HELLO_OK");
}

TEST(RemotePlant, APlantThatWantsAnotherVersion) {
  Linked link = linked();
  Peer plant_peer{std::move(link.plant), "the firmware"};
  std::thread script{[&] {
    EXPECT_EQ(plant_peer.expect_frame(), FrameKind::hello);
    EXPECT_TRUE(plant_peer.channel().send_hello_ok({1}).ok());
    EXPECT_TRUE(plant_peer.channel().flush().ok());
  }};
  auto connected = RemotePlant::connect(std::move(link.firmware), one_ms);
  script.join();
  ASSERT_FALSE(connected.ok());
  EXPECT_EQ(connected.error(),
            "the plant answered HELLO with link protocol version 1; this firmware speaks version 2 only");
  EXPECT_EQ(plant_peer.expect_frame(), FrameKind::error);  // the firmware says why, and nothing more: no BYE
  auto end = plant_peer.channel().receive("the end");
  ASSERT_TRUE(end.ok()) << end.error();
  EXPECT_FALSE(end.value().has_value());
}

// The plant's side against firmware that misbehaves.
Result<ServeSummary> serve_against(plant::Plant& plant, const std::function<void(Peer&)>& firmware_script,
                                   Timeout timeout = 2s) {
  Linked link = linked(timeout);
  link.firmware->set_timeout(2s);  // the plant's side is the one to give up
  Peer firmware{std::move(link.firmware), "the plant"};
  std::thread script{[&] { firmware_script(firmware); }};
  auto result = serve(plant, *link.plant);
  script.join();
  return result;
}

TEST(Serve, FirmwareThatDoesNotSayHelloFirst) {
  plant::Loopback loopback;
  auto result = serve_against(loopback, [](Peer& firmware) {
    EXPECT_TRUE(firmware.channel().send_tick(0).ok());
    EXPECT_EQ(firmware.expect_frame(), FrameKind::error);
  });
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error(), "the firmware sent TICK where the plant awaited HELLO");
}

TEST(Serve, FirmwareOfAnotherVersion) {
  plant::Loopback loopback;
  for (const std::uint8_t version : std::initializer_list<std::uint8_t>{1, 9}) {
    const std::string said =
        "the firmware speaks link protocol version " + std::to_string(version) + "; this plant speaks version 2 only";
    auto result = serve_against(loopback, [&](Peer& firmware) {
      // Version 1's HELLO has version 2's layout, so that an old firmware hears why.
      const std::uint8_t hello[] = {0x01, 6, 0, version, 0, 0x40, 0x42, 0x0F, 0x00};
      EXPECT_TRUE(firmware.stream().write_all(hello).ok());
      EXPECT_EQ(firmware.expect_frame(), FrameKind::error);
      ErrorText text;
      EXPECT_EQ(parse(firmware.payload(), text), FrameError::none);
      EXPECT_EQ(text.text, said);
    });
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error(), said);
  }
}

TEST(Serve, AHelloWithoutABasePeriodIsRefused) {
  plant::Loopback loopback;
  auto result = serve_against(loopback, [](Peer& firmware) {
    EXPECT_TRUE(firmware.channel().send_hello({protocol_version, LinkMode::lock_step, 0}).ok());
    EXPECT_EQ(firmware.expect_frame(), FrameKind::error);
  });
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error(), "the firmware's HELLO gives a base period of 0 ns: the plant's time is tick x base period");
}

// The plant's time at each TICK.
class Clockwork : public plant::Plant {
 public:
  void advance(double time_s, const plant::RaiseInterrupt&) override { times.push_back(time_s); }
  void write(std::string_view, std::span<const double>) override {}
  void read(std::string_view, std::span<double>) override {}
  std::vector<double> times;
};

TEST(Serve, ATicksTimeIsItsNumberTimesTheBasePeriodInSeconds) {
  Clockwork clockwork;
  auto result = serve_against(clockwork, [](Peer& firmware) {
    EXPECT_TRUE(firmware.channel().send_hello(hello_one_ms).ok());
    EXPECT_EQ(firmware.expect_frame(), FrameKind::hello_ok);
    for (const std::uint64_t tick : {0ULL, 9ULL, 1ULL << 40}) {
      EXPECT_TRUE(firmware.channel().send_tick(tick).ok());
      EXPECT_EQ(firmware.expect_frame(), FrameKind::tick_done);
    }
    EXPECT_TRUE(firmware.channel().send_empty(FrameKind::bye).ok());
    EXPECT_TRUE(firmware.channel().flush().ok());
  });
  ASSERT_TRUE(result.ok()) << result.error();
  // As duet sim's robot computes it: static_cast<double>(tick) * (period_ns * 1e-9). Tick 9 at 1 ms is
  // 0.009000000000000001, not the 0.009 that 9,000,000 ns would give.
  ASSERT_EQ(clockwork.times.size(), 3U);
  EXPECT_EQ(clockwork.times[0], 0.0);
  EXPECT_EQ(clockwork.times[1], 9.0 * (1'000'000 * 1e-9));
  EXPECT_NE(clockwork.times[1], 0.009);
  EXPECT_EQ(clockwork.times[2], 1099511627776.0 * 0.001);
  EXPECT_EQ(result.value().last_tick_s, clockwork.times[2]);
}

// A plant that starts, or not, with the firmware's base period, and halts at a time it is given.
class Halting : public plant::Plant {
 public:
  Status start(double base_period_s) override {
    started_with = base_period_s;
    if (refuse_start) return Failure{"no FMU"};
    return done();
  }
  void advance(double time_s, const plant::RaiseInterrupt&) override {
    if (time_s >= halt_at) halt = Halt{.reason = "enough", .failed = failed};
  }
  void write(std::string_view, std::span<const double>) override {}
  void read(std::string_view, std::span<double>) override {}
  [[nodiscard]] std::optional<Halt> halted() const override { return halt; }
  bool refuse_start = false;
  double halt_at = 1e9;
  bool failed = false;
  double started_with = 0;
  std::optional<Halt> halt;
};

TEST(Serve, ThePlantStartsWithTheBasePeriodOfTheHelloOrTheSessionFails) {
  Halting plant;
  plant.refuse_start = true;
  auto result = serve_against(plant, [](Peer& firmware) {
    EXPECT_TRUE(firmware.channel().send_hello(hello_one_ms).ok());
    EXPECT_EQ(firmware.expect_frame(), FrameKind::error);
  });
  EXPECT_EQ(plant.started_with, 0.001);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error(), "the plant cannot start: no FMU");
}

// A plant that fails fails the session at that tick; one that asks to stop ends it, and the summary says why. The
// firmware learns of either by ERROR in place of TICK_DONE.
TEST(Serve, APlantThatHaltsEndsTheSessionAtThatTick) {
  for (const bool failed : {true, false}) {
    Halting plant;
    plant.halt_at = 0.002;
    plant.failed = failed;
    auto result = serve_against(plant, [](Peer& firmware) {
      EXPECT_TRUE(firmware.channel().send_hello(hello_one_ms).ok());
      EXPECT_EQ(firmware.expect_frame(), FrameKind::hello_ok);
      for (const std::uint64_t tick : {0ULL, 1ULL}) {
        EXPECT_TRUE(firmware.channel().send_tick(tick).ok());
        EXPECT_EQ(firmware.expect_frame(), FrameKind::tick_done);
      }
      EXPECT_TRUE(firmware.channel().send_tick(2).ok());
      EXPECT_EQ(firmware.expect_frame(), FrameKind::error);
    });
    if (failed) {
      ASSERT_FALSE(result.ok());
      EXPECT_EQ(result.error(), "the plant failed at t = 0.002 s: enough");
    } else {
      ASSERT_TRUE(result.ok()) << result.error();
      EXPECT_EQ(result.value().plant_stop, "the plant asked to stop at t = 0.002 s: enough");
      EXPECT_EQ(result.value().ticks, 3U);
    }
  }
}

// duet::blocks::convert's rules (convert.hpp): to bool u != 0, a NaN true; floating to integer NaN 0, truncated
// toward zero and saturated; double to float rounded to nearest, beyond float's range an infinity.
TEST(Serve, TypedElementsAreConvertedAsTheInterpreterConvertsThem) {
  plant::Loopback loopback;
  auto result = serve_against(loopback, [](Peer& firmware) {
    EXPECT_TRUE(firmware.channel().send_hello(hello_one_ms).ok());
    EXPECT_EQ(firmware.expect_frame(), FrameKind::hello_ok);
    // Typed writes, as the firmware on QEMU sends them (type bytes from docs/LINK.md's table).
    const std::uint8_t writes[] = {0x03, 0x09, 0, 3, 's', 'p', 'i', 0x02, 2, 0, 200,  7,                  // u8 [200, 7]
                                   0x03, 0x08, 0, 3, 'p', 'i', 'n', 0x01, 1, 0, 1,                        // bool [true]
                                   0x03, 0x0B, 0, 3, 'p', 'w', 'm', 0x05, 1, 0, 0xCD, 0xCC, 0xCC, 0x3E,   // f32 [0.4f]
                                   0x03, 0x09, 0, 3, 'a', 'd', 'c', 0x03, 1, 0, 0x64, 0x00,               // u16 [100]
                                   0x03, 0x0B, 0, 3, 'c', 'a', 'p', 0x04, 1, 0, 0x70, 0x11, 0x01, 0x00};  // u32 [70000]
    EXPECT_TRUE(firmware.stream().write_all(writes).ok());
    const double odd[] = {300.7, -2.5, std::nan(""), 1e300, 0.5};
    EXPECT_TRUE(firmware.channel().send_write("odd", odd).ok());
    // The same five doubles read back as u8, bool, u16, u32 and f32.
    const auto read_back = [&](ElementType type) {
      EXPECT_TRUE(firmware.channel().send_read("odd", type, 5).ok());
      EXPECT_EQ(firmware.expect_frame(), FrameKind::values);
      return firmware.payload();
    };
    EXPECT_EQ(read_back(ElementType::u8), (std::vector<std::uint8_t>{0x02, 5, 0, 255, 0, 0, 255, 0}));
    EXPECT_EQ(read_back(ElementType::boolean), (std::vector<std::uint8_t>{0x01, 5, 0, 1, 1, 1, 1, 1}));
    EXPECT_EQ(read_back(ElementType::u16),
              (std::vector<std::uint8_t>{0x03, 5, 0, 0x2C, 0x01, 0, 0, 0, 0, 0xFF, 0xFF, 0, 0}));
    EXPECT_EQ(read_back(ElementType::u32), (std::vector<std::uint8_t>{0x04, 5, 0, 0x2C, 0x01, 0,    0,    0, 0, 0, 0, 0,
                                                                      0,    0, 0, 0xFF, 0xFF, 0xFF, 0xFF, 0, 0, 0, 0}));
    // f32: 300.7 rounds to 0x4396599A, -2.5 is 0xC0200000, NaN stays a NaN, 1e300 is +inf, 0.5 0x3F000000.
    const std::vector<std::uint8_t> floats = read_back(ElementType::f32);
    ASSERT_EQ(floats.size(), 3U + 5 * 4);
    EXPECT_EQ(std::vector<std::uint8_t>(floats.begin() + 3, floats.begin() + 11),
              (std::vector<std::uint8_t>{0x9A, 0x59, 0x96, 0x43, 0x00, 0x00, 0x20, 0xC0}));
    EXPECT_EQ(floats[3 + 8 + 3] & 0x7F, 0x7F);  // NaN: exponent all ones
    EXPECT_EQ(std::vector<std::uint8_t>(floats.begin() + 15, floats.end()),
              (std::vector<std::uint8_t>{0x00, 0x00, 0x80, 0x7F, 0x00, 0x00, 0x00, 0x3F}));
    EXPECT_TRUE(firmware.channel().send_empty(FrameKind::bye).ok());
    EXPECT_TRUE(firmware.channel().flush().ok());
  });
  ASSERT_TRUE(result.ok()) << result.error();
  EXPECT_EQ(loopback.value("spi"), (std::vector<double>{200, 7}));
  EXPECT_EQ(loopback.value("pin"), std::vector<double>{1});
  EXPECT_EQ(loopback.value("pwm"), std::vector<double>{static_cast<double>(0.4F)});
  EXPECT_EQ(loopback.value("adc"), std::vector<double>{100});
  EXPECT_EQ(loopback.value("cap"), std::vector<double>{70'000});
}

TEST(Serve, AReadOfMoreThanAValuesHoldsIsRefused) {
  plant::Loopback loopback;
  auto result = serve_against(loopback, [](Peer& firmware) {
    EXPECT_TRUE(firmware.channel().send_hello(hello_one_ms).ok());
    EXPECT_EQ(firmware.expect_frame(), FrameKind::hello_ok);
    const std::uint8_t read[] = {0x04, 0x05, 0, 1, 'x', 0x06, 0x00, 0x02};  // 512 f64
    EXPECT_TRUE(firmware.stream().write_all(read).ok());
    EXPECT_EQ(firmware.expect_frame(), FrameKind::error);
  });
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error(), "the firmware asked for 512 f64 values of 'x'; a VALUES frame holds at most 511");
}

TEST(RemotePlant, ATimeThatIsNoTicksTimeFailsTheLink) {
  plant::Loopback loopback;
  Linked link = linked();
  PlantThread plant_side{loopback, std::move(link.plant)};
  auto connected = RemotePlant::connect(std::move(link.firmware), one_ms);
  ASSERT_TRUE(connected.ok()) << connected.error();
  connected.value()->advance(0.009000000000000001, {});  // tick 9
  EXPECT_TRUE(connected.value()->ok());
  connected.value()->advance(0.0009765625, {});  // 2^-10 s: between ticks 0 and 1
  ASSERT_FALSE(connected.value()->ok());
  EXPECT_EQ(
      connected.value()->error(),
      "advance(0.0009765625) is no tick's time at the base period of 1000000 ns (tick x 0.001 s): the link carries "
      "tick numbers, and the plant computes each tick's time so");
  EXPECT_FALSE(plant_side.finish().ok());
}

TEST(Serve, FirmwareThatGoesAwayInTheMiddleOfAnInterrupt) {
  ScriptedPlant scripted;
  auto result = serve_against(scripted, [](Peer& firmware) {
    EXPECT_TRUE(firmware.channel().send_hello(hello_one_ms).ok());
    EXPECT_EQ(firmware.expect_frame(), FrameKind::hello_ok);
    EXPECT_TRUE(firmware.channel().send_tick(1000).ok());
    EXPECT_EQ(firmware.expect_frame(), FrameKind::interrupt);
    firmware.close();
  });
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error(), "the firmware closed the link during interrupt 'EXTI0'");
  // The plant finished its advance() without the second interrupt reaching anyone.
  EXPECT_EQ(scripted.log, (std::vector<std::string>{"advance 1.000000", "EXTI0 done", "TIM2 done"}));
}

TEST(Serve, FirmwareThatSendsGarbageOrAnError) {
  plant::Loopback loopback;
  auto garbage = serve_against(loopback, [](Peer& firmware) {
    EXPECT_TRUE(firmware.channel().send_hello(hello_one_ms).ok());
    EXPECT_EQ(firmware.expect_frame(), FrameKind::hello_ok);
    const std::uint8_t bytes[] = {0xEE, 0, 0};
    EXPECT_TRUE(firmware.stream().write_all(bytes).ok());
    EXPECT_EQ(firmware.expect_frame(), FrameKind::error);
  });
  ASSERT_FALSE(garbage.ok());
  EXPECT_EQ(garbage.error(),
            "the firmware sent a bad frame (unknown frame kind 0xEE) while awaiting WRITE, READ, TICK or BYE");
  auto reported = serve_against(loopback, [](Peer& firmware) {
    EXPECT_TRUE(firmware.channel().send_hello(hello_one_ms).ok());
    EXPECT_EQ(firmware.expect_frame(), FrameKind::hello_ok);
    (void)firmware.channel().fail("the executive overran");
  });
  ASSERT_FALSE(reported.ok());
  EXPECT_EQ(reported.error(), "the firmware reported an error: the executive overran");
}

TEST(Serve, ASilentFirmwareTimesOut) {
  plant::Loopback loopback;
  auto result = serve_against(
      loopback,
      [](Peer& firmware) {
        EXPECT_TRUE(firmware.channel().send_hello(hello_one_ms).ok());
        EXPECT_EQ(firmware.expect_frame(), FrameKind::hello_ok);
        EXPECT_EQ(firmware.expect_frame(), FrameKind::error);  // the plant gives up and says so
      },
      50ms);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error(), "link to the firmware: nothing received for 50 ms while awaiting WRITE, READ, TICK or BYE");
}

TEST(Serve, TheEndOfTheStreamBetweenFramesEndsTheSessionWell) {
  plant::Loopback loopback;
  auto result = serve_against(loopback, [](Peer& firmware) {
    EXPECT_TRUE(firmware.channel().send_hello(hello_one_ms).ok());
    EXPECT_EQ(firmware.expect_frame(), FrameKind::hello_ok);
    const double value = 3;
    EXPECT_TRUE(firmware.channel().send_write("gpio:LED1", {&value, 1}).ok());
    EXPECT_TRUE(firmware.channel().flush().ok());
    firmware.close();
  });
  ASSERT_TRUE(result.ok()) << result.error();
  EXPECT_FALSE(result.value().said_bye);
  EXPECT_EQ(loopback.value("gpio:LED1"), std::vector<double>{3});
}

}  // namespace
}  // namespace duet::link
