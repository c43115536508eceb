#pragma once
// The frames of the virtual-hardware link (docs/LINK.md): firmware and a simulated plant in another process talk
// over a byte stream in frames of [kind: u8][payload length: u16 little-endian][payload]. Numbers are little-endian
// whatever the processor; doubles travel as their IEEE-754 binary64 bits, so a value arrives bit for bit.
//
// Freestanding and header-only (no heap, no exceptions, no RTTI): the firmware on the emulated Cortex-M4 encodes
// and parses with it as the host does. Nothing here blocks or keeps state; every function may run in any context.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace duet::link {

inline constexpr std::uint8_t protocol_version = 1;
inline constexpr std::size_t header_size = 3;     // kind, payload length
inline constexpr std::size_t max_payload = 4096;  // the protocol's limit: a frame never needs a bigger buffer
inline constexpr std::size_t max_frame = header_size + max_payload;
inline constexpr std::size_t max_name = 255;         // resource and interrupt names: 1 to 255 bytes
inline constexpr std::size_t max_values = 479;       // doubles a WRITE carries whatever its name: (4096 - 258) / 8
inline constexpr std::size_t max_read_values = 511;  // doubles a READ may ask for: a VALUES of (4096 - 2) / 8
static_assert(max_values == (max_payload - 1 - max_name - 2) / 8 && max_read_values == (max_payload - 2) / 8);
static_assert(max_payload <= 0xFFFF, "the length field is a u16");

enum class FrameKind : std::uint8_t {
  hello = 0x01,           // firmware -> plant, first: version u8, mode u8, base period ns u32
  hello_ok = 0x02,        // plant -> firmware: version u8
  write = 0x03,           // firmware -> plant: name, count u16, count doubles
  read = 0x04,            // firmware -> plant: name, count u16; answered by VALUES
  values = 0x05,          // plant -> firmware: count u16, count doubles
  tick = 0x06,            // firmware -> plant: time in seconds, binary64; answered by TICK_DONE
  interrupt = 0x07,       // plant -> firmware, during a TICK: name; answered by INTERRUPT_DONE
  interrupt_done = 0x08,  // firmware -> plant
  tick_done = 0x09,       // plant -> firmware
  error = 0x0A,           // either way: UTF-8 text; the sender gives up on the link
  bye = 0x0B,             // firmware -> plant: the run is over
};
inline constexpr std::uint8_t first_kind = 0x01;
inline constexpr std::uint8_t last_kind = 0x0B;

enum class LinkMode : std::uint8_t {
  lock_step = 0,  // the firmware ticks as fast as the plant answers: every run the same, bit for bit
  real_time = 1,  // the firmware sends each TICK when the wall clock reaches its time
};

// What is wrong with a frame. The decoder finds the first three; the parse functions the others.
enum class FrameError : std::uint8_t {
  none = 0,
  unknown_kind,      // a kind byte outside 0x01..0x0B
  payload_too_long,  // a length over max_payload, or over the decoder's buffer
  wrong_length,      // a length this kind never has, or a payload that ends inside a field
  bad_name,          // an empty name
  bad_count,         // a count that does not match the payload's length
  bad_mode,          // a HELLO mode other than 0 or 1
};

[[nodiscard]] constexpr bool is_frame_kind(std::uint8_t byte) { return byte >= first_kind && byte <= last_kind; }

[[nodiscard]] constexpr const char* kind_name(FrameKind kind) {
  switch (kind) {
    case FrameKind::hello: return "HELLO";
    case FrameKind::hello_ok: return "HELLO_OK";
    case FrameKind::write: return "WRITE";
    case FrameKind::read: return "READ";
    case FrameKind::values: return "VALUES";
    case FrameKind::tick: return "TICK";
    case FrameKind::interrupt: return "INTERRUPT";
    case FrameKind::interrupt_done: return "INTERRUPT_DONE";
    case FrameKind::tick_done: return "TICK_DONE";
    case FrameKind::error: return "ERROR";
    case FrameKind::bye: return "BYE";
  }
  return "an unknown kind";
}

[[nodiscard]] constexpr const char* describe(FrameError error) {
  switch (error) {
    case FrameError::none: return "no error";
    case FrameError::unknown_kind: return "unknown frame kind";
    case FrameError::payload_too_long: return "payload too long";
    case FrameError::wrong_length: return "payload length wrong for the frame's kind";
    case FrameError::bad_name: return "empty name";
    case FrameError::bad_count: return "value count does not match the payload length";
    case FrameError::bad_mode: return "unknown link mode";
  }
  return "unknown error";
}

// The payload length every frame of this kind has, or -1 where it varies.
[[nodiscard]] constexpr int fixed_payload(FrameKind kind) {
  switch (kind) {
    case FrameKind::hello: return 6;
    case FrameKind::hello_ok: return 1;
    case FrameKind::tick: return 8;
    case FrameKind::interrupt_done:
    case FrameKind::tick_done:
    case FrameKind::bye: return 0;
    default: return -1;
  }
}
// The shortest payload a kind of varying length has: a name length and one byte of name, a count.
[[nodiscard]] constexpr std::size_t min_payload(FrameKind kind) {
  switch (kind) {
    case FrameKind::write:
    case FrameKind::read: return 4;
    case FrameKind::values:
    case FrameKind::interrupt: return 2;
    default: return fixed_payload(kind) < 0 ? 0 : static_cast<std::size_t>(fixed_payload(kind));
  }
}

// Doubles as they lie in a payload (8 bytes each, little-endian, maybe unaligned).
class PackedDoubles {
 public:
  constexpr PackedDoubles() = default;
  // Precondition: bytes.size() is a multiple of 8.
  constexpr explicit PackedDoubles(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  [[nodiscard]] constexpr std::size_t size() const { return bytes_.size() / 8; }
  [[nodiscard]] constexpr double operator[](std::size_t index) const {
    std::uint64_t bits = 0;
    for (std::size_t byte = 8; byte-- > 0;) bits = (bits << 8U) | bytes_[index * 8 + byte];
    return std::bit_cast<double>(bits);
  }
  // Copies min(size(), values.size()) values; the rest of `values` is left as it was.
  constexpr void copy_to(std::span<double> values) const {
    for (std::size_t k = 0; k < size() && k < values.size(); ++k) values[k] = (*this)[k];
  }

 private:
  std::span<const std::uint8_t> bytes_;
};

// The payloads, parsed. Names and texts point into the payload they were parsed from.
struct Hello {
  std::uint8_t version = protocol_version;
  LinkMode mode = LinkMode::lock_step;
  std::uint32_t base_period_ns = 0;  // the firmware's base period, for the plant's information
};
struct HelloOk {
  std::uint8_t version = protocol_version;
};
struct Write {
  std::string_view resource;
  PackedDoubles values;
};
struct Read {
  std::string_view resource;
  std::uint16_t count = 0;
};
struct Values {
  PackedDoubles values;
};
struct Tick {
  double time_s = 0;  // exactly the double the firmware passed to Plant::advance
};
struct Interrupt {
  std::string_view name;
};
struct ErrorText {
  std::string_view text;
};

// Builds one frame in a caller's buffer: the header first, then the payload's fields. A field that does not fit in
// the buffer or in max_payload spoils the frame, and finish() then returns an empty span.
class FrameWriter {
 public:
  FrameWriter(std::span<std::uint8_t> buffer, FrameKind kind) : buffer_(buffer) {
    if (buffer_.size() < header_size) {
      spoiled_ = true;
      return;
    }
    buffer_[0] = static_cast<std::uint8_t>(kind);
    size_ = header_size;
  }

  void u8(std::uint8_t value) {
    if (room(1)) buffer_[size_++] = value;
  }
  void u16(std::uint16_t value) { little_endian(value, 2); }
  void u32(std::uint32_t value) { little_endian(value, 4); }
  void f64(double value) { little_endian(std::bit_cast<std::uint64_t>(value), 8); }
  void bytes(std::string_view text) {
    if (!room(text.size())) return;
    for (const char c : text) buffer_[size_++] = static_cast<std::uint8_t>(c);
  }
  // A name: its length (u8), then its bytes; 1 to max_name bytes.
  void name(std::string_view text) {
    if (text.empty() || text.size() > max_name) {
      spoiled_ = true;
      return;
    }
    u8(static_cast<std::uint8_t>(text.size()));
    bytes(text);
  }
  // A count (u16), then the values.
  void doubles(std::span<const double> values) {
    if (values.size() > 0xFFFF || !room(2 + values.size() * 8)) {
      spoiled_ = true;
      return;
    }
    u16(static_cast<std::uint16_t>(values.size()));
    for (const double value : values) f64(value);
  }

  // The frame, header filled in; empty if anything did not fit.
  [[nodiscard]] std::span<const std::uint8_t> finish() {
    if (spoiled_) return {};
    const std::size_t payload = size_ - header_size;
    buffer_[1] = static_cast<std::uint8_t>(payload & 0xFFU);
    buffer_[2] = static_cast<std::uint8_t>(payload >> 8U);
    return buffer_.first(size_);
  }

 private:
  bool room(std::size_t count) {
    if (!spoiled_ && size_ + count <= buffer_.size() && size_ + count - header_size <= max_payload) return true;
    spoiled_ = true;
    return false;
  }
  void little_endian(std::uint64_t value, std::size_t count) {
    if (!room(count)) return;
    for (std::size_t byte = 0; byte < count; ++byte) buffer_[size_++] = static_cast<std::uint8_t>(value >> (8 * byte));
  }

  std::span<std::uint8_t> buffer_;
  std::size_t size_ = 0;
  bool spoiled_ = false;
};

// Encoders: the whole frame in `buffer`, or an empty span if it does not fit (the buffer is too small, a name is
// empty or longer than max_name, or the payload would exceed max_payload).
inline std::span<const std::uint8_t> encode_hello(std::span<std::uint8_t> buffer, const Hello& hello) {
  FrameWriter frame{buffer, FrameKind::hello};
  frame.u8(hello.version);
  frame.u8(static_cast<std::uint8_t>(hello.mode));
  frame.u32(hello.base_period_ns);
  return frame.finish();
}
inline std::span<const std::uint8_t> encode_hello_ok(std::span<std::uint8_t> buffer, const HelloOk& hello_ok) {
  FrameWriter frame{buffer, FrameKind::hello_ok};
  frame.u8(hello_ok.version);
  return frame.finish();
}
inline std::span<const std::uint8_t> encode_write(std::span<std::uint8_t> buffer, std::string_view resource,
                                                  std::span<const double> values) {
  FrameWriter frame{buffer, FrameKind::write};
  frame.name(resource);
  frame.doubles(values);
  return frame.finish();
}
inline std::span<const std::uint8_t> encode_read(std::span<std::uint8_t> buffer, std::string_view resource,
                                                 std::uint16_t count) {
  FrameWriter frame{buffer, FrameKind::read};
  frame.name(resource);
  frame.u16(count);
  return frame.finish();
}
inline std::span<const std::uint8_t> encode_values(std::span<std::uint8_t> buffer, std::span<const double> values) {
  FrameWriter frame{buffer, FrameKind::values};
  frame.doubles(values);
  return frame.finish();
}
inline std::span<const std::uint8_t> encode_tick(std::span<std::uint8_t> buffer, double time_s) {
  FrameWriter frame{buffer, FrameKind::tick};
  frame.f64(time_s);
  return frame.finish();
}
inline std::span<const std::uint8_t> encode_interrupt(std::span<std::uint8_t> buffer, std::string_view name) {
  FrameWriter frame{buffer, FrameKind::interrupt};
  frame.name(name);
  return frame.finish();
}
// INTERRUPT_DONE, TICK_DONE and BYE, whose payload is empty. Precondition: fixed_payload(kind) == 0.
inline std::span<const std::uint8_t> encode_empty(std::span<std::uint8_t> buffer, FrameKind kind) {
  FrameWriter frame{buffer, kind};
  return frame.finish();
}
// An error's text, cut at a character boundary where it would not fit in the buffer or in max_payload.
inline std::span<const std::uint8_t> encode_error(std::span<std::uint8_t> buffer, std::string_view text) {
  if (buffer.size() < header_size) return {};
  std::size_t room = buffer.size() - header_size < max_payload ? buffer.size() - header_size : max_payload;
  if (text.size() > room) {
    while (room > 0 && (static_cast<std::uint8_t>(text[room]) & 0xC0U) == 0x80U) --room;  // a continuation byte
    text = text.substr(0, room);
  }
  FrameWriter frame{buffer, FrameKind::error};
  frame.bytes(text);
  return frame.finish();
}

// Reads a payload's fields in order; a field past its end spoils the reading.
class PayloadReader {
 public:
  explicit constexpr PayloadReader(std::span<const std::uint8_t> payload) : payload_(payload) {}

  constexpr std::uint8_t u8() { return static_cast<std::uint8_t>(little_endian(1)); }
  constexpr std::uint16_t u16() { return static_cast<std::uint16_t>(little_endian(2)); }
  constexpr std::uint32_t u32() { return static_cast<std::uint32_t>(little_endian(4)); }
  constexpr double f64() { return std::bit_cast<double>(little_endian(8)); }
  std::string_view text(std::size_t count) {
    if (!room(count)) return {};
    const std::string_view text{reinterpret_cast<const char*>(payload_.data() + at_), count};
    at_ += count;
    return text;
  }
  constexpr std::span<const std::uint8_t> rest() {
    const std::span<const std::uint8_t> rest = payload_.subspan(at_);
    at_ = payload_.size();
    return rest;
  }
  [[nodiscard]] constexpr bool spoiled() const { return spoiled_; }
  [[nodiscard]] constexpr std::size_t left() const { return payload_.size() - at_; }

 private:
  constexpr bool room(std::size_t count) {
    if (!spoiled_ && count <= payload_.size() - at_) return true;
    spoiled_ = true;
    return false;
  }
  constexpr std::uint64_t little_endian(std::size_t count) {
    if (!room(count)) return 0;
    std::uint64_t value = 0;
    for (std::size_t byte = count; byte-- > 0;) value = (value << 8U) | payload_[at_ + byte];
    at_ += count;
    return value;
  }

  std::span<const std::uint8_t> payload_;
  std::size_t at_ = 0;
  bool spoiled_ = false;
};

// Parsers: fill `out` from a payload of that kind and say what is wrong with it, if anything. The payload must
// stay alive while `out`'s names and values are used.
namespace detail {
inline FrameError parse_name(PayloadReader& reader, std::string_view& name) {
  const std::uint8_t length = reader.u8();
  if (reader.spoiled()) return FrameError::wrong_length;
  if (length == 0) return FrameError::bad_name;
  name = reader.text(length);
  return reader.spoiled() ? FrameError::wrong_length : FrameError::none;
}
inline FrameError parse_doubles(PayloadReader& reader, PackedDoubles& values) {
  const std::uint16_t count = reader.u16();
  if (reader.spoiled()) return FrameError::wrong_length;
  if (reader.left() != std::size_t{count} * 8) return FrameError::bad_count;
  values = PackedDoubles{reader.rest()};
  return FrameError::none;
}
}  // namespace detail

inline FrameError parse(std::span<const std::uint8_t> payload, Hello& out) {
  if (payload.size() != 6) return FrameError::wrong_length;
  PayloadReader reader{payload};
  out.version = reader.u8();
  const std::uint8_t mode = reader.u8();
  out.base_period_ns = reader.u32();
  if (mode > static_cast<std::uint8_t>(LinkMode::real_time)) return FrameError::bad_mode;
  out.mode = static_cast<LinkMode>(mode);
  return FrameError::none;
}
inline FrameError parse(std::span<const std::uint8_t> payload, HelloOk& out) {
  if (payload.size() != 1) return FrameError::wrong_length;
  out.version = payload[0];
  return FrameError::none;
}
inline FrameError parse(std::span<const std::uint8_t> payload, Write& out) {
  PayloadReader reader{payload};
  if (const FrameError error = detail::parse_name(reader, out.resource); error != FrameError::none) return error;
  return detail::parse_doubles(reader, out.values);
}
inline FrameError parse(std::span<const std::uint8_t> payload, Read& out) {
  PayloadReader reader{payload};
  if (const FrameError error = detail::parse_name(reader, out.resource); error != FrameError::none) return error;
  out.count = reader.u16();
  return reader.spoiled() || reader.left() != 0 ? FrameError::wrong_length : FrameError::none;
}
inline FrameError parse(std::span<const std::uint8_t> payload, Values& out) {
  PayloadReader reader{payload};
  return detail::parse_doubles(reader, out.values);
}
inline FrameError parse(std::span<const std::uint8_t> payload, Tick& out) {
  if (payload.size() != 8) return FrameError::wrong_length;
  PayloadReader reader{payload};
  out.time_s = reader.f64();
  return FrameError::none;
}
inline FrameError parse(std::span<const std::uint8_t> payload, Interrupt& out) {
  PayloadReader reader{payload};
  if (const FrameError error = detail::parse_name(reader, out.name); error != FrameError::none) return error;
  return reader.left() != 0 ? FrameError::wrong_length : FrameError::none;
}
inline FrameError parse(std::span<const std::uint8_t> payload, ErrorText& out) {
  PayloadReader reader{payload};
  out.text = reader.text(payload.size());
  return FrameError::none;
}

}  // namespace duet::link
