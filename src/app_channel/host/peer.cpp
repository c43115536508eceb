#include "duet/app_channel/host/peer.hpp"

#include <cmath>
#include <cstring>

namespace duet::app_channel::host {
namespace {

// Reads the little-endian fields of a packet; any read past its end marks it malformed.
class PacketReader {
 public:
  explicit PacketReader(std::span<const std::uint8_t> packet) : packet_(packet) {}
  std::uint8_t u8() {
    if (!has(1)) return 0;
    return packet_[at_++];
  }
  std::uint32_t u32() {
    std::uint32_t value = 0;
    for (unsigned byte = 0; byte < 4; ++byte) value |= static_cast<std::uint32_t>(u8()) << (8U * byte);
    return value;
  }
  double f64() {
    std::uint8_t raw[8] = {};
    for (std::uint8_t& byte : raw) byte = u8();
    double value = 0;
    std::memcpy(&value, raw, sizeof(value));
    return value;
  }
  std::string text() {
    const std::size_t length = u8();
    if (!has(length)) return {};
    std::string value{reinterpret_cast<const char*>(packet_.data() + at_), length};
    at_ += length;
    return value;
  }
  double value(ValueType type) {
    const std::size_t size = size_of(type);
    if (!has(size)) return 0;
    const std::uint8_t* bytes = packet_.data() + at_;
    at_ += size;
    switch (type) {
      case ValueType::u8: return read<std::uint8_t>(bytes);
      case ValueType::i8: return read<std::int8_t>(bytes);
      case ValueType::u16: return read<std::uint16_t>(bytes);
      case ValueType::i16: return read<std::int16_t>(bytes);
      case ValueType::u32: return read<std::uint32_t>(bytes);
      case ValueType::i32: return read<std::int32_t>(bytes);
      case ValueType::f32: return read<float>(bytes);
      case ValueType::f64: return read<double>(bytes);
    }
    return 0;
  }
  // Every byte read and none missing.
  [[nodiscard]] bool complete() const { return !short_ && at_ == packet_.size(); }
  [[nodiscard]] bool at_end() const { return at_ >= packet_.size(); }

 private:
  template <typename T>
  static double read(const std::uint8_t* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return static_cast<double>(value);
  }
  bool has(std::size_t count) {
    if (at_ + count <= packet_.size()) return true;
    short_ = true;
    at_ = packet_.size();
    return false;
  }
  std::span<const std::uint8_t> packet_;
  std::size_t at_ = 0;
  bool short_ = false;
};

template <typename T>
void append(std::vector<std::uint8_t>& bytes, double value) {
  const T converted = static_cast<T>(value);
  const auto* raw = reinterpret_cast<const std::uint8_t*>(&converted);
  bytes.insert(bytes.end(), raw, raw + sizeof(T));
}

void append_value(std::vector<std::uint8_t>& bytes, ValueType type, double value) {
  switch (type) {
    case ValueType::u8: append<std::uint8_t>(bytes, value); break;
    case ValueType::i8: append<std::int8_t>(bytes, value); break;
    case ValueType::u16: append<std::uint16_t>(bytes, value); break;
    case ValueType::i16: append<std::int16_t>(bytes, value); break;
    case ValueType::u32: append<std::uint32_t>(bytes, value); break;
    case ValueType::i32: append<std::int32_t>(bytes, value); break;
    case ValueType::f32: append<float>(bytes, value); break;
    case ValueType::f64: append<double>(bytes, value); break;
  }
}

bool is_integer(ValueType type) { return type != ValueType::f32 && type != ValueType::f64; }

}  // namespace

Peer::Peer(Handlers handlers)
    : handlers_(std::move(handlers)),
      decoder_buffer_(decoder_buffer_size),
      decoder_(framing, decoder_buffer_, max_packet) {}

void Peer::receive(std::span<const std::uint8_t> bytes) {
  decoder_.feed(bytes, [this](std::uint16_t counter, std::span<const std::uint8_t> packet) {
    if (last_counter_ && counter != static_cast<std::uint16_t>(*last_counter_ + 1)) {
      counters_.frames_lost += static_cast<std::uint16_t>(counter - *last_counter_ - 1);
    }
    last_counter_ = counter;
    handle(packet);
  });
}

void Peer::reset() {
  decoder_.reset();
  description_.reset();
  incoming_.reset();
  parameter_values_.clear();
  last_counter_.reset();
}

PeerCounters Peer::counters() const {
  PeerCounters counters = counters_;
  counters.garbage_bytes = decoder_.dropped_bytes();
  return counters;
}

void Peer::problem(const std::string& what) {
  ++counters_.malformed_packets;
  if (handlers_.problem) handlers_.problem(what);
}

void Peer::handle(std::span<const std::uint8_t> packet) {
  PacketReader in{packet};
  const auto message = static_cast<Message>(in.u8());
  switch (message) {
    case Message::hello: {
      const std::uint8_t version = in.u8();
      Description description;
      description.application = in.text();
      description.telemetry_period_us = in.u32();
      description.telemetry.resize(in.u8());
      description.parameters.resize(in.u8());
      if (!in.complete()) return problem("a hello message of " + std::to_string(packet.size()) + " bytes is malformed");
      if (version != protocol_version) {
        return problem("the firmware speaks version " + std::to_string(version) + " of the application channel; " +
                       "this program speaks version " + std::to_string(protocol_version));
      }
      incoming_ = std::move(description);
      return;
    }
    case Message::item: {
      const std::uint8_t kind = in.u8();
      const std::uint8_t index = in.u8();
      const std::uint8_t type = in.u8();
      ItemDescription item;
      item.minimum = in.f64();
      item.maximum = in.f64();
      item.name = in.text();
      item.unit = in.text();
      if (!in.at_end()) {
        item.labels.resize(in.u8());
        for (std::string& label : item.labels) label = in.text();
      }
      if (!in.complete() || !is_value_type(type) || kind > 1) return problem("an item description is malformed");
      if (!incoming_) return;  // joined in the middle of a description: wait for the next hello
      auto& items = kind == 0 ? incoming_->telemetry : incoming_->parameters;
      if (index >= items.size()) return problem("item " + std::to_string(index) + " is beyond the announced count");
      item.type = static_cast<ValueType>(type);
      items[index] = std::move(item);
      return;
    }
    case Message::described: {
      if (!incoming_) return;
      for (const auto* items : {&incoming_->telemetry, &incoming_->parameters}) {
        for (const ItemDescription& item : *items) {
          if (item.name.empty()) {
            incoming_.reset();
            return problem("a description ended with items missing (lost frames?); asking again helps");
          }
        }
      }
      description_ = std::move(incoming_);
      incoming_.reset();
      parameter_values_.assign(description_->parameters.size(), std::nullopt);
      if (handlers_.description) handlers_.description(*description_);
      return;
    }
    case Message::telemetry: {
      if (!description_) return;  // not understood before the description
      Sample sample;
      sample.sample = in.u32();
      sample.values.reserve(description_->telemetry.size());
      for (const ItemDescription& item : description_->telemetry) sample.values.push_back(in.value(item.type));
      if (!in.complete()) {
        return problem("a telemetry sample of " + std::to_string(packet.size()) +
                       " bytes does not match the description");
      }
      ++counters_.samples;
      if (handlers_.telemetry) handlers_.telemetry(sample);
      return;
    }
    case Message::parameter: {
      if (!description_) return;
      ParameterReport report;
      report.index = in.u8();
      const std::uint8_t status = in.u8();
      if (status > static_cast<std::uint8_t>(ParameterStatus::reported)) return problem("unknown parameter status");
      report.status = static_cast<ParameterStatus>(status);
      if (report.index < description_->parameters.size()) {
        report.value = in.value(description_->parameters[report.index].type);
        parameter_values_[report.index] = report.value;
      }
      if (!in.complete()) return problem("a parameter report is malformed");
      if (handlers_.parameter) handlers_.parameter(report);
      return;
    }
    case Message::executive: {
      ExecutiveReport report;
      report.ticks = in.u32();
      report.ticks |= static_cast<std::uint64_t>(in.u32()) << 32U;
      report.base_period_ns = in.u32();
      report.busy_ppm = in.u32();
      report.overruns = in.u32();
      report.cycle_hz = in.u32();
      report.tasks.resize(in.u8());
      if (!in.complete()) return problem("an executive report is malformed");
      executive_tasks_ = 0;
      executive_ = std::move(report);
      return finish_executive();
    }
    case Message::task: {
      TaskTiming task;
      const std::size_t index = in.u8();
      task.activations = in.u32();
      task.overruns = in.u32();
      task.min_cycles = in.u32();
      task.mean_cycles = in.u32();
      task.max_cycles = in.u32();
      task.name = in.text();
      if (!in.complete()) return problem("a task report is malformed");
      // Tasks come in order after their executive packet; anything else means a lost frame: wait for the next.
      if (!executive_ || index != executive_tasks_ || index >= executive_->tasks.size()) {
        executive_.reset();
        return;
      }
      executive_->tasks[executive_tasks_++] = std::move(task);
      return finish_executive();
    }
    default: return problem("unknown message " + std::to_string(packet.empty() ? 0 : packet[0]));
  }
}

void Peer::finish_executive() {
  if (!executive_ || executive_tasks_ != executive_->tasks.size()) return;
  if (handlers_.executive) handlers_.executive(*executive_);
  executive_.reset();
}

std::vector<std::uint8_t> Peer::describe_request() {
  const std::uint8_t packet[] = {static_cast<std::uint8_t>(Message::describe)};
  std::vector<std::uint8_t> frame(framing.frame_size(sizeof(packet)));
  frame.resize(xcp::write_frame(framing, frame, request_counter_++, packet));
  return frame;
}

Result<std::vector<std::uint8_t>> Peer::set_request(std::string_view name, double value) {
  if (!description_) return Failure{"the firmware has not described its parameters yet"};
  for (std::size_t index = 0; index < description_->parameters.size(); ++index) {
    const ItemDescription& parameter = description_->parameters[index];
    if (parameter.name != name) continue;
    if (!std::isfinite(value)) return Failure{"parameter " + parameter.name + ": the value is not a number"};
    if (value < parameter.minimum || value > parameter.maximum) {
      return Failure{"parameter " + parameter.name + ": " + std::to_string(value) + " is outside its limits [" +
                     std::to_string(parameter.minimum) + ", " + std::to_string(parameter.maximum) + "]"};
    }
    if (is_integer(parameter.type) && value != std::trunc(value)) {
      return Failure{"parameter " + parameter.name + " is an integer (" + std::string{name_of(parameter.type)} +
                     "): " + std::to_string(value) + " is not"};
    }
    std::vector<std::uint8_t> packet{static_cast<std::uint8_t>(Message::set), static_cast<std::uint8_t>(index)};
    append_value(packet, parameter.type, value);
    std::vector<std::uint8_t> frame(framing.frame_size(packet.size()));
    frame.resize(xcp::write_frame(framing, frame, request_counter_++, packet));
    return frame;
  }
  return Failure{"the firmware has no parameter named '" + std::string{name} + "'"};
}

std::string_view name_of(ValueType type) {
  switch (type) {
    case ValueType::u8: return "uint8";
    case ValueType::i8: return "int8";
    case ValueType::u16: return "uint16";
    case ValueType::i16: return "int16";
    case ValueType::u32: return "uint32";
    case ValueType::i32: return "int32";
    case ValueType::f32: return "float32";
    case ValueType::f64: return "float64";
  }
  return "unknown";
}

std::string_view name_of(ParameterStatus status) {
  switch (status) {
    case ParameterStatus::applied: return "applied";
    case ParameterStatus::clamped: return "clamped";
    case ParameterStatus::unknown_parameter: return "unknown parameter";
    case ParameterStatus::malformed: return "malformed";
    case ParameterStatus::reported: return "reported";
  }
  return "unknown";
}

}  // namespace duet::app_channel::host
