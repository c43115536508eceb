#include "duet/app_channel/endpoint.hpp"

#include <cstring>

namespace duet::app_channel {
namespace {

// An answer's record: message, index, status and the widest value.
constexpr std::size_t answer_record = xcp::TransmitQueue::record_header + 3 + 8;

// Writes the little-endian fields of a packet into a buffer; past its end, writes nothing and remembers it overflowed.
class PacketWriter {
 public:
  explicit PacketWriter(std::span<std::uint8_t> packet) : packet_(packet) {}
  PacketWriter& u8(std::uint8_t value) { return bytes(&value, 1); }
  PacketWriter& u32(std::uint32_t value) {
    const std::uint8_t little[4] = {static_cast<std::uint8_t>(value), static_cast<std::uint8_t>(value >> 8U),
                                    static_cast<std::uint8_t>(value >> 16U), static_cast<std::uint8_t>(value >> 24U)};
    return bytes(little, sizeof(little));
  }
  PacketWriter& f64(double value) {  // both the Cortex-M4 and the PC keep doubles little-endian
    std::uint8_t raw[8];
    std::memcpy(raw, &value, sizeof(raw));
    return bytes(raw, sizeof(raw));
  }
  PacketWriter& text(const char* value, std::size_t longest) {
    std::size_t length = 0;
    while (value[length] != '\0' && length < longest) ++length;
    u8(static_cast<std::uint8_t>(length));
    return bytes(reinterpret_cast<const std::uint8_t*>(value), length);
  }
  PacketWriter& bytes(const std::uint8_t* values, std::size_t count) {
    if (written_ + count > packet_.size()) {
      overflowed_ = true;
      return *this;
    }
    std::memcpy(packet_.data() + written_, values, count);
    written_ += count;
    return *this;
  }
  // The packet's size, 0 if it did not fit.
  [[nodiscard]] std::size_t size() const { return overflowed_ ? 0 : written_; }

 private:
  std::span<std::uint8_t> packet_;
  std::size_t written_ = 0;
  bool overflowed_ = false;
};

template <typename T>
bool clamp_as(std::uint8_t* bytes, const TypedLimit& lowest, const TypedLimit& highest) {
  T value;
  T low;
  T high;
  std::memcpy(&value, bytes, sizeof(T));
  std::memcpy(&low, lowest.bytes, sizeof(T));
  std::memcpy(&high, highest.bytes, sizeof(T));
  if (value >= low && value <= high) return false;  // NaN is neither
  const T limit = value > high ? high : low;
  std::memcpy(bytes, &limit, sizeof(T));
  return true;
}

// A double's place in the order of doubles, as an unsigned integer: the Cortex-M4 compares doubles only in software
// (libgcc), which an interrupt handler must not reach; the bits of two doubles that are not NaN compare as their
// values once negative ones are reversed. -0 is +0.
std::uint64_t order_of(std::uint64_t bits) {
  constexpr std::uint64_t sign = std::uint64_t{1} << 63;
  if ((bits & ~sign) == 0) return sign;  // either zero
  return (bits & sign) != 0 ? ~bits : bits | sign;
}
bool is_nan(std::uint64_t bits) {
  constexpr std::uint64_t exponent = 0x7FF0'0000'0000'0000U;
  return (bits & exponent) == exponent && (bits & ~(exponent | std::uint64_t{1} << 63)) != 0;
}

template <>
bool clamp_as<double>(std::uint8_t* bytes, const TypedLimit& lowest, const TypedLimit& highest) {
  std::uint64_t value;
  std::uint64_t low;
  std::uint64_t high;
  std::memcpy(&value, bytes, sizeof value);
  std::memcpy(&low, lowest.bytes, sizeof low);
  std::memcpy(&high, highest.bytes, sizeof high);
  if (!is_nan(value) && order_of(value) >= order_of(low) && order_of(value) <= order_of(high)) return false;
  const std::uint64_t limit = !is_nan(value) && order_of(value) > order_of(high) ? high : low;
  std::memcpy(bytes, &limit, sizeof limit);
  return true;
}

// Brings `bytes`, a value of `type`, within the limits (a NaN to the lower one); true if it had to.
bool clamp(ValueType type, std::uint8_t* bytes, const TypedLimit& lowest, const TypedLimit& highest) {
  switch (type) {
    case ValueType::u8: return clamp_as<std::uint8_t>(bytes, lowest, highest);
    case ValueType::i8: return clamp_as<std::int8_t>(bytes, lowest, highest);
    case ValueType::u16: return clamp_as<std::uint16_t>(bytes, lowest, highest);
    case ValueType::i16: return clamp_as<std::int16_t>(bytes, lowest, highest);
    case ValueType::u32: return clamp_as<std::uint32_t>(bytes, lowest, highest);
    case ValueType::i32: return clamp_as<std::int32_t>(bytes, lowest, highest);
    case ValueType::f32: return clamp_as<float>(bytes, lowest, highest);
    case ValueType::f64: return clamp_as<double>(bytes, lowest, highest);
  }
  return false;
}

}  // namespace

Endpoint::Endpoint(const Application& application, xcp::TransmitQueue& queue, xcp::QueueLock lock,
                   std::span<std::uint8_t> decoder_buffer, std::span<std::uint8_t> packet_buffer)
    : application_(application),
      queue_(queue),
      lock_(lock),
      decoder_(framing, decoder_buffer, max_packet),
      framer_(framing, packet_buffer) {
  telemetry_size_ = 1 + 4;
  for (const Item& item : application_.telemetry) telemetry_size_ += size_of(item.type);
}

bool Endpoint::publish(std::uint32_t sample) {
  const bool queued =
      queue_.push(telemetry_size_ + xcp::TransmitQueue::record_header, 2 * answer_record, [&](auto& out) {
        out.packet(telemetry_size_).u8(static_cast<std::uint8_t>(Message::telemetry));
        out.u32(sample);
        for (const Item& item : application_.telemetry) {
          out.bytes(static_cast<const std::uint8_t*>(item.address), size_of(item.type));
        }
      });
  if (!queued) samples_dropped_.fetch_add(1, std::memory_order_relaxed);
  return queued;
}

bool Endpoint::publish_executive(const ExecutiveReport& report) {
  constexpr std::size_t executive_size = 1 + 6 * 4 + 1;
  bool queued = queue_.push(executive_size + xcp::TransmitQueue::record_header, 2 * answer_record, [&](auto& out) {
    out.packet(executive_size).u8(static_cast<std::uint8_t>(Message::executive));
    out.u32(static_cast<std::uint32_t>(report.ticks)).u32(static_cast<std::uint32_t>(report.ticks >> 32U));
    out.u32(report.base_period_ns).u32(report.busy_ppm).u32(report.overruns).u32(report.cycle_hz);
    out.u8(static_cast<std::uint8_t>(report.tasks.size()));
  });
  for (std::size_t index = 0; index < report.tasks.size() && queued; ++index) {
    const TaskReport& task = report.tasks[index];
    const std::size_t name_length = task.name.size() < max_name_length ? task.name.size() : max_name_length;
    const std::size_t size = 1 + 1 + 5 * 4 + 1 + name_length;
    queued = queue_.push(size + xcp::TransmitQueue::record_header, 2 * answer_record, [&](auto& out) {
      out.packet(size).u8(static_cast<std::uint8_t>(Message::task)).u8(static_cast<std::uint8_t>(index));
      out.u32(task.activations).u32(task.overruns).u32(task.min_cycles).u32(task.mean_cycles).u32(task.max_cycles);
      out.u8(static_cast<std::uint8_t>(name_length));
      out.bytes(reinterpret_cast<const std::uint8_t*>(task.name.data()), name_length);
    });
  }
  if (!queued) reports_dropped_.fetch_add(1, std::memory_order_relaxed);
  return queued;
}

void Endpoint::receive(std::span<const std::uint8_t> bytes) {
  decoder_.feed(bytes, [this](std::uint16_t, std::span<const std::uint8_t> command) { handle(command); });
}

void Endpoint::handle(std::span<const std::uint8_t> command) {
  switch (static_cast<Message>(command[0])) {
    case Message::describe: announce(); break;
    case Message::set: set(command.subspan(1)); break;
    default: break;  // not ours to answer: the other side sends only these two
  }
}

void Endpoint::set(std::span<const std::uint8_t> request) {
  if (request.empty() || request[0] >= application_.parameters.size()) {
    answer(request.empty() ? 0xFF : request[0], ParameterStatus::unknown_parameter);
    return;
  }
  const std::uint8_t index = request[0];
  const Item& parameter = application_.parameters[index];
  const std::span<const std::uint8_t> value = request.subspan(1);
  if (value.size() != size_of(parameter.type)) {
    answer(index, ParameterStatus::malformed);
    return;
  }
  std::uint8_t applied[8];
  std::memcpy(applied, value.data(), value.size());
  const ParameterStatus status = clamp(parameter.type, applied, parameter.lowest, parameter.highest)
                                     ? ParameterStatus::clamped
                                     : ParameterStatus::applied;
  // Under the lock, so that a task reading a multi-word parameter never sees half of the old and half of the new.
  const std::uint32_t saved = lock_.lock();
  std::memcpy(parameter.address, applied, value.size());
  lock_.unlock(saved);
  answer(index, status);
}

bool Endpoint::report(std::size_t parameter) {
  if (parameter >= application_.parameters.size()) return false;
  const std::uint32_t dropped = answers_dropped_.load(std::memory_order_relaxed);
  answer(static_cast<std::uint8_t>(parameter), ParameterStatus::reported);
  return answers_dropped_.load(std::memory_order_relaxed) == dropped;
}

void Endpoint::answer(std::uint8_t index, ParameterStatus status) {
  const std::size_t value_size =
      index < application_.parameters.size() ? size_of(application_.parameters[index].type) : 0;
  const std::size_t size = 3 + value_size;
  const bool queued = queue_.push(size + xcp::TransmitQueue::record_header, 0, [&](auto& out) {
    out.packet(size).u8(static_cast<std::uint8_t>(Message::parameter)).u8(index).u8(static_cast<std::uint8_t>(status));
    if (value_size != 0) {
      out.bytes(static_cast<const std::uint8_t*>(application_.parameters[index].address), value_size);
    }
  });
  if (!queued) answers_dropped_.fetch_add(1, std::memory_order_relaxed);
}

std::size_t Endpoint::transmit(std::span<std::uint8_t> out) {
  return framer_.transmit(out, [this](std::span<std::uint8_t> packet) {
    if (describe_requested_.exchange(false, std::memory_order_acq_rel)) description_step_ = 1;
    if (description_step_ != 0) return next_description_packet(packet);
    return queue_.pop(packet);
  });
}

// The description, one packet per step: hello, each item, described, then each parameter's value.
std::size_t Endpoint::next_description_packet(std::span<std::uint8_t> packet) {
  const std::size_t telemetry = application_.telemetry.size();
  const std::size_t parameters = application_.parameters.size();
  const std::size_t step = description_step_;
  description_step_ = step == 1 + telemetry + parameters + 1 + parameters ? 0 : step + 1;
  PacketWriter writer{packet};
  if (step == 1) {
    writer.u8(static_cast<std::uint8_t>(Message::hello)).u8(protocol_version).text(application_.name, max_name_length);
    writer.u32(application_.telemetry_period_us)
        .u8(static_cast<std::uint8_t>(telemetry))
        .u8(static_cast<std::uint8_t>(parameters));
  } else if (step <= 1 + telemetry + parameters) {
    const bool is_telemetry = step - 2 < telemetry;
    const std::size_t index = is_telemetry ? step - 2 : step - 2 - telemetry;
    const Item& item = is_telemetry ? application_.telemetry[index] : application_.parameters[index];
    writer.u8(static_cast<std::uint8_t>(Message::item))
        .u8(static_cast<std::uint8_t>(is_telemetry ? ItemKind::telemetry : ItemKind::parameter))
        .u8(static_cast<std::uint8_t>(index))
        .u8(static_cast<std::uint8_t>(item.type))
        .f64(item.minimum)
        .f64(item.maximum)
        .text(item.name, max_name_length)
        .text(item.unit, max_unit_length);
    if (!item.labels.empty()) {
      const std::size_t count = item.labels.size() < max_labels ? item.labels.size() : max_labels;
      writer.u8(static_cast<std::uint8_t>(count));
      for (std::size_t label = 0; label < count; ++label) writer.text(item.labels[label], max_label_length);
    }
  } else if (step == 2 + telemetry + parameters) {
    writer.u8(static_cast<std::uint8_t>(Message::described));
  } else {
    const std::size_t index = step - 3 - telemetry - parameters;
    const Item& parameter = application_.parameters[index];
    writer.u8(static_cast<std::uint8_t>(Message::parameter))
        .u8(static_cast<std::uint8_t>(index))
        .u8(static_cast<std::uint8_t>(ParameterStatus::reported))
        .bytes(static_cast<const std::uint8_t*>(parameter.address), size_of(parameter.type));
  }
  return writer.size();
}

}  // namespace duet::app_channel
