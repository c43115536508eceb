// What a tick costs over the link: a RemotePlant and serve() on a plant that echoes what was written, over a socket
// pair, the plant in a thread; each tick is TICK/TICK_DONE plus the firmware's writes and reads, as a controller's step
// would do.
//   link_round_trip [TICKS [WRITES [READS]]]      (default 60000 ticks, 2 writes, 1 read)
// Meaningful in the host-release build; the figure is in docs/LINK.md.
#include <charconv>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string_view>
#include <thread>

#include "duet/link/remote_plant.hpp"
#include "duet/link/serve.hpp"
#include "duet/plant/plant.hpp"

namespace {

// Reads give back the last value written anywhere: the least a plant can do.
class Echo : public duet::plant::Plant {
 public:
  void advance(double, const duet::plant::RaiseInterrupt&) override {}
  void write(std::string_view, std::span<const double> values) override {
    if (!values.empty()) last_ = values[0];
  }
  void read(std::string_view, std::span<double> values) override {
    for (double& value : values) value = last_;
  }

 private:
  double last_ = 0;
};

std::optional<long> number(const char* text) {
  long value = 0;
  const std::string_view view{text};
  const auto [end, error] = std::from_chars(view.data(), view.data() + view.size(), value);
  if (error != std::errc{} || end != view.data() + view.size() || value < 0) return std::nullopt;
  return value;
}

}  // namespace

int main(int argc, char** argv) {
  long counts[3] = {60'000, 2, 1};
  for (int k = 1; k < argc && k <= 3; ++k) {
    const auto value = number(argv[k]);
    if (!value) {
      std::fprintf(stderr, "link_round_trip: '%s' is not a count; usage: link_round_trip [TICKS [WRITES [READS]]]\n",
                   argv[k]);
      return 2;
    }
    counts[k - 1] = *value;
  }
  const auto [ticks, writes, reads] = counts;
  auto pair = duet::link::socket_pair();
  if (!pair) {
    std::fprintf(stderr, "link_round_trip: %s\n", pair.error().c_str());
    return 1;
  }
  Echo echo;
  std::unique_ptr<duet::link::Stream> plant_end = std::move(pair.value().second);
  std::optional<duet::Result<duet::link::ServeSummary>> served;
  std::thread plant_side{[&] { served.emplace(duet::link::serve(echo, *plant_end)); }};

  auto connected =
      duet::link::RemotePlant::connect(std::move(pair.value().first), {duet::link::LinkMode::lock_step, 1'000'000});
  if (!connected) {
    std::fprintf(stderr, "link_round_trip: %s\n", connected.error().c_str());
    plant_side.join();
    return 1;
  }
  duet::link::RemotePlant& remote = *connected.value();
  const char* const resources[] = {"pwm:TIM1/1", "pwm:TIM1/2", "gpio:LED0", "gpio:LED1"};
  const auto start = std::chrono::steady_clock::now();
  double sensor = 0;
  for (long tick = 0; tick < ticks && remote.ok(); ++tick) {
    remote.advance(static_cast<double>(tick) * 0.001, {});
    for (long k = 0; k < reads; ++k) remote.read("adc:ADC1/6", {&sensor, 1});
    const double value = static_cast<double>(tick) + sensor;
    for (long k = 0; k < writes; ++k) remote.write(resources[k % 4], {&value, 1});
  }
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  const duet::Status closed = remote.ok() ? remote.close() : remote.status();
  connected.value().reset();
  plant_side.join();
  if (!closed || !served->ok()) {
    std::fprintf(stderr, "link_round_trip: %s\n", !closed ? closed.error().c_str() : served->error().c_str());
    return 1;
  }
  std::printf("%ld ticks, %ld writes and %ld reads each, in %.3f s: %.2f us per tick, %.0f ticks per second\n", ticks,
              writes, reads, elapsed.count(), elapsed.count() * 1e6 / static_cast<double>(ticks),
              static_cast<double>(ticks) / elapsed.count());
  return 0;
}
