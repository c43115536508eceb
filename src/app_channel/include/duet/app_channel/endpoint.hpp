#pragma once
// The firmware's end of the application channel: it describes the application's telemetry and parameters, sends
// telemetry samples, and applies parameter sets within their limits. Freestanding: fixed buffers the application
// owns, no heap; publish() may be called from an interrupt, receive() from the receive interrupt or the background
// loop, transmit() from whoever feeds the line.

#include <array>
#include <atomic>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <type_traits>

#include "duet/app_channel/protocol.hpp"
#include "duet/xcp/framing.hpp"
#include "duet/xcp/packet_framer.hpp"
#include "duet/xcp/transmit_queue.hpp"

namespace duet::app_channel {

// A limit in the item's own type, as its bytes: set() compares in that type, so that the Cortex-M4 checks a float
// parameter with its FPU rather than with libgcc's software doubles. An integer's lower limit rounds up and its upper
// limit down (its values within them are those within the doubles); both saturate at the type's range.
struct TypedLimit {
  std::uint8_t bytes[8]{};
};

namespace detail {
template <typename T>
constexpr TypedLimit typed_limit(double limit, bool upper) {
  T value{};
  if constexpr (std::is_floating_point_v<T>) {
    value = static_cast<T>(limit);
  } else if (!(limit > static_cast<double>(std::numeric_limits<T>::lowest()))) {  // NaN: the lowest too
    value = std::numeric_limits<T>::lowest();
  } else if (!(limit < static_cast<double>(std::numeric_limits<T>::max()))) {
    value = std::numeric_limits<T>::max();
  } else {
    value = static_cast<T>(limit);  // toward zero
    if (!upper && static_cast<double>(value) < limit) ++value;
    if (upper && static_cast<double>(value) > limit) --value;
  }
  TypedLimit typed;
  const auto bytes = std::bit_cast<std::array<std::uint8_t, sizeof(T)>>(value);
  for (std::size_t k = 0; k < sizeof(T); ++k) typed.bytes[k] = bytes[k];
  return typed;
}
}  // namespace detail

// One value the application sends or accepts, and where it lives.
struct Item {
  const char* name;
  const char* unit;
  ValueType type;
  double minimum;  // as the description tells Linux
  double maximum;
  void* address;
  // Value k's name (a state, a choice), at most max_labels of at most max_label_length bytes; none: a number.
  std::span<const char* const> labels{};
  TypedLimit lowest{};  // minimum and maximum in the item's type, for set()
  TypedLimit highest{};
};

template <typename T>
constexpr Item item(const char* name, const char* unit, T& variable, double minimum, double maximum) {
  return {name,
          unit,
          value_type_of<T>(),
          minimum,
          maximum,
          &variable,
          {},
          detail::typed_limit<T>(minimum, false),
          detail::typed_limit<T>(maximum, true)};
}

// An integer item whose values 0, 1, ... are named: its limits are the first and the last name.
template <typename T>
constexpr Item named_item(const char* name, T& variable, std::span<const char* const> labels) {
  const double last = static_cast<double>(labels.size()) - 1;
  return {name,
          "",
          value_type_of<T>(),
          0,
          last,
          &variable,
          labels,
          detail::typed_limit<T>(0, false),
          detail::typed_limit<T>(last, true)};
}

struct Application {
  const char* name;
  std::uint32_t telemetry_period_us;
  std::span<const Item> telemetry;
  std::span<const Item> parameters;
};

// The executive's account of itself, for the dashboard's Status page.
struct TaskReport {
  std::string_view name;
  std::uint32_t activations;
  std::uint32_t overruns;
  std::uint32_t min_cycles;
  std::uint32_t mean_cycles;
  std::uint32_t max_cycles;
};

struct ExecutiveReport {
  std::uint64_t ticks;
  std::uint32_t base_period_ns;
  std::uint32_t busy_ppm;
  std::uint32_t overruns;
  std::uint32_t cycle_hz;  // what the tasks' cycle counts count
  std::span<const TaskReport> tasks;
};

class Endpoint {
 public:
  // `queue` carries telemetry and answers (its lock also guards parameter writes against the tasks that read them);
  // `decoder_buffer` holds decoder_buffer_size bytes, `packet_buffer` max_packet bytes.
  Endpoint(const Application& application, xcp::TransmitQueue& queue, xcp::QueueLock lock,
           std::span<std::uint8_t> decoder_buffer, std::span<std::uint8_t> packet_buffer);

  // Sends the description (and every parameter's value) before anything else that is queued; done at start and when
  // the other side asks.
  void announce() { describe_requested_.store(true, std::memory_order_release); }

  // Queues one telemetry sample; false, and counted, if the queue is full (answers keep their room).
  bool publish(std::uint32_t sample);

  // Queues the executive's account: a packet, then one per task. Like publish(), it leaves room for answers; false
  // if any packet did not fit (the other side then waits for the next whole account). Not from an interrupt: once
  // a second from the background loop is plenty.
  bool publish_executive(const ExecutiveReport& report);

  // Bytes from the line, in any pieces.
  void receive(std::span<const std::uint8_t> bytes);

  // Queues a parameter's value as it is now (status `reported`): for a value that changed by other means than a
  // set, so that the other side shows what is in effect. False, and counted with the answers, if it did not fit.
  bool report(std::size_t parameter);

  // Frames what is to be sent into `out`; returns the bytes written.
  std::size_t transmit(std::span<std::uint8_t> out);

  [[nodiscard]] std::uint32_t samples_dropped() const { return samples_dropped_.load(std::memory_order_relaxed); }
  // Executive accounts that did not fit whole, and answers to parameter writes that did not fit at all (the other
  // side then sees no confirmation of its write).
  [[nodiscard]] std::uint32_t reports_dropped() const { return reports_dropped_.load(std::memory_order_relaxed); }
  [[nodiscard]] std::uint32_t answers_dropped() const { return answers_dropped_.load(std::memory_order_relaxed); }
  [[nodiscard]] std::size_t garbage_bytes() const { return decoder_.dropped_bytes(); }

 private:
  void handle(std::span<const std::uint8_t> command);
  void set(std::span<const std::uint8_t> request);
  void answer(std::uint8_t index, ParameterStatus status);
  std::size_t next_description_packet(std::span<std::uint8_t> packet);

  Application application_;
  xcp::TransmitQueue& queue_;
  xcp::QueueLock lock_;
  xcp::FrameDecoder decoder_;
  xcp::PacketFramer framer_;
  std::atomic<bool> describe_requested_{true};
  std::size_t description_step_ = 0;  // 0: not describing; else the next step, counted from 1
  std::atomic<std::uint32_t> samples_dropped_{0};
  std::atomic<std::uint32_t> reports_dropped_{0};
  std::atomic<std::uint32_t> answers_dropped_{0};
  std::size_t telemetry_size_ = 0;  // of a telemetry packet
};

}  // namespace duet::app_channel
