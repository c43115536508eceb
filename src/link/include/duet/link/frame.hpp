#pragma once
// The frames of the virtual-hardware link (docs/LINK.md): firmware and a simulated plant in another process talk
// over a byte stream in frames of [kind: u8][payload length: u16 little-endian][payload]. Numbers are little-endian
// whatever the processor. WRITE and VALUES carry elements of one type each (ElementType: bool, u8, u16, u32, f32,
// f64), in that type's own bytes, so that firmware moves its u8 bytes and float duties as they are: no conversion to
// double on a processor whose FPU is single precision. Floating-point elements travel as their IEEE-754 bits, so a
// value arrives bit for bit.
//
// Freestanding and header-only (no heap, no exceptions, no RTTI): the firmware on the emulated Cortex-M4 encodes
// and parses with it as the host does. Nothing here blocks or keeps state; every function may run in any context.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>

namespace duet::link {

// Version 1 carried doubles and the time of a TICK; version 2 typed elements and the tick's number (docs/LINK.md).
inline constexpr std::uint8_t protocol_version = 2;
inline constexpr std::size_t header_size = 3;     // kind, payload length
inline constexpr std::size_t max_payload = 4096;  // the protocol's limit: a frame never needs a bigger buffer
inline constexpr std::size_t max_frame = header_size + max_payload;
inline constexpr std::size_t max_name = 255;  // resource and interrupt names: 1 to 255 bytes
static_assert(max_payload <= 0xFFFF, "the length field is a u16");

// The type of a WRITE's or a VALUES' elements: its byte in the frame, and how each element lies in the payload.
enum class ElementType : std::uint8_t {
  boolean = 0x01,  // 1 byte: 0x00 false, 0x01 true; any other byte is a bad frame
  u8 = 0x02,       // 1 byte
  u16 = 0x03,      // 2 bytes, little-endian
  u32 = 0x04,      // 4 bytes, little-endian
  f32 = 0x05,      // 4 bytes: the IEEE-754 binary32 bits, little-endian
  f64 = 0x06,      // 8 bytes: the IEEE-754 binary64 bits, little-endian
};
inline constexpr std::uint8_t first_element_type = 0x01;
inline constexpr std::uint8_t last_element_type = 0x06;

[[nodiscard]] constexpr bool is_element_type(std::uint8_t byte) {
  return byte >= first_element_type && byte <= last_element_type;
}
[[nodiscard]] constexpr std::size_t element_size(ElementType type) {
  switch (type) {
    case ElementType::boolean:
    case ElementType::u8: return 1;
    case ElementType::u16: return 2;
    case ElementType::u32:
    case ElementType::f32: return 4;
    case ElementType::f64: return 8;
  }
  return 1;
}
[[nodiscard]] constexpr std::string_view element_type_name(ElementType type) {
  switch (type) {
    case ElementType::boolean: return "bool";
    case ElementType::u8: return "u8";
    case ElementType::u16: return "u16";
    case ElementType::u32: return "u32";
    case ElementType::f32: return "f32";
    case ElementType::f64: return "f64";
  }
  return "an unknown type";
}

// The element type of a C++ type; other types do not compile.
template <typename T>
struct ElementTypeOf;
template <>
struct ElementTypeOf<bool> : std::integral_constant<ElementType, ElementType::boolean> {};
template <>
struct ElementTypeOf<std::uint8_t> : std::integral_constant<ElementType, ElementType::u8> {};
template <>
struct ElementTypeOf<std::uint16_t> : std::integral_constant<ElementType, ElementType::u16> {};
template <>
struct ElementTypeOf<std::uint32_t> : std::integral_constant<ElementType, ElementType::u32> {};
template <>
struct ElementTypeOf<float> : std::integral_constant<ElementType, ElementType::f32> {};
template <>
struct ElementTypeOf<double> : std::integral_constant<ElementType, ElementType::f64> {};
template <typename T>
inline constexpr ElementType element_type_of = ElementTypeOf<T>::value;

// The most elements of a type one frame carries: a VALUES (type, count, elements), and a WRITE whatever its name
// (name length, name of up to 255 bytes, type, count, elements). For f64: 511 and 479.
[[nodiscard]] constexpr std::size_t max_read_count(ElementType type) { return (max_payload - 3) / element_size(type); }
[[nodiscard]] constexpr std::size_t max_write_count(ElementType type) {
  return (max_payload - 1 - max_name - 3) / element_size(type);
}
static_assert(max_read_count(ElementType::f64) == 511 && max_write_count(ElementType::f64) == 479);

// Names and descriptions are string_views, their lengths known at compile time: the firmware puts them in its
// messages from the base tick's handler, where a strlen has no business (ports/cortex-m/interrupt_reach.py).
enum class FrameKind : std::uint8_t {
  hello = 0x01,           // firmware -> plant, first: version u8, mode u8, base period ns u32
  hello_ok = 0x02,        // plant -> firmware: version u8
  write = 0x03,           // firmware -> plant: name, element type u8, count u16, count elements
  read = 0x04,            // firmware -> plant: name, element type u8, count u16; answered by VALUES
  values = 0x05,          // plant -> firmware: element type u8, count u16, count elements
  tick = 0x06,            // firmware -> plant: tick number u64; answered by TICK_DONE
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
  bad_element_type,  // an element type byte outside 0x01..0x06
  bad_boolean,       // a bool element other than 0x00 or 0x01
};

[[nodiscard]] constexpr bool is_frame_kind(std::uint8_t byte) { return byte >= first_kind && byte <= last_kind; }

[[nodiscard]] constexpr std::string_view kind_name(FrameKind kind) {
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

[[nodiscard]] constexpr std::string_view describe(FrameError error) {
  switch (error) {
    case FrameError::none: return "no error";
    case FrameError::unknown_kind: return "unknown frame kind";
    case FrameError::payload_too_long: return "payload too long";
    case FrameError::wrong_length: return "payload length wrong for the frame's kind";
    case FrameError::bad_name: return "empty name";
    case FrameError::bad_count: return "value count does not match the payload length";
    case FrameError::bad_mode: return "unknown link mode";
    case FrameError::bad_element_type: return "unknown element type";
    case FrameError::bad_boolean: return "a bool element other than 0 or 1";
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
// The shortest payload a kind of varying length has: a name length and one byte of name, an element type, a count.
[[nodiscard]] constexpr std::size_t min_payload(FrameKind kind) {
  switch (kind) {
    case FrameKind::write:
    case FrameKind::read: return 5;
    case FrameKind::values: return 3;
    case FrameKind::interrupt: return 2;
    default: return fixed_payload(kind) < 0 ? 0 : static_cast<std::size_t>(fixed_payload(kind));
  }
}

namespace detail {
template <typename T>
constexpr T element_from_bits(std::uint64_t bits) {
  if constexpr (std::is_same_v<T, bool>) {
    return bits != 0;  // the parser let only 0 and 1 through
  } else if constexpr (std::is_same_v<T, float>) {
    return std::bit_cast<float>(static_cast<std::uint32_t>(bits));
  } else if constexpr (std::is_same_v<T, double>) {
    return std::bit_cast<double>(bits);
  } else {
    return static_cast<T>(bits);
  }
}
template <typename T>
constexpr std::uint64_t element_bits(T value) {
  if constexpr (std::is_same_v<T, bool>) {
    return value ? 1U : 0U;
  } else if constexpr (std::is_same_v<T, float>) {
    return std::bit_cast<std::uint32_t>(value);
  } else if constexpr (std::is_same_v<T, double>) {
    return std::bit_cast<std::uint64_t>(value);
  } else {
    return value;
  }
}
}  // namespace detail

// Elements of one type as they lie in a payload (little-endian, maybe unaligned).
class PackedElements {
 public:
  constexpr PackedElements() = default;
  // Precondition: bytes.size() is a multiple of element_size(type).
  constexpr PackedElements(ElementType type, std::span<const std::uint8_t> bytes) : type_(type), bytes_(bytes) {}

  [[nodiscard]] constexpr ElementType type() const { return type_; }
  [[nodiscard]] constexpr std::size_t size() const { return bytes_.size() / element_size(type_); }
  // The element's bits, zero-extended: a bool 0 or 1, a float's binary32 bits.
  [[nodiscard]] constexpr std::uint64_t bits(std::size_t index) const {
    const std::size_t size = element_size(type_);
    std::uint64_t bits = 0;
    for (std::size_t byte = size; byte-- > 0;) bits = (bits << 8U) | bytes_[index * size + byte];
    return bits;
  }
  // Precondition: type() == element_type_of<T>.
  template <typename T>
  [[nodiscard]] constexpr T at(std::size_t index) const {
    return detail::element_from_bits<T>(bits(index));
  }
  // Copies min(size(), values.size()) elements; the rest of `values` is left as it was. Precondition: as at().
  template <typename T>
  constexpr void copy_to(std::span<T> values) const {
    for (std::size_t k = 0; k < size() && k < values.size(); ++k) values[k] = at<T>(k);
  }

 private:
  ElementType type_ = ElementType::u8;
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
  PackedElements values;
};
struct Read {
  std::string_view resource;
  ElementType type = ElementType::f64;
  std::uint16_t count = 0;
};
struct Values {
  PackedElements values;
};
struct Tick {
  std::uint64_t tick = 0;  // the base tick's number: the plant's time is tick x base period (tick_time_s)
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
  void u64(std::uint64_t value) { little_endian(value, 8); }
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
  // The element type (u8), a count (u16), then the elements.
  template <typename T>
  void elements(std::span<const T> values) {
    constexpr ElementType type = element_type_of<T>;
    if (values.size() > 0xFFFF || !room(3 + values.size() * element_size(type))) {
      spoiled_ = true;
      return;
    }
    u8(static_cast<std::uint8_t>(type));
    u16(static_cast<std::uint16_t>(values.size()));
    for (const T value : values) little_endian(detail::element_bits(value), element_size(type));
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
template <typename T>
std::span<const std::uint8_t> encode_write(std::span<std::uint8_t> buffer, std::string_view resource,
                                           std::span<const T> values) {
  FrameWriter frame{buffer, FrameKind::write};
  frame.name(resource);
  frame.elements(values);
  return frame.finish();
}
inline std::span<const std::uint8_t> encode_read(std::span<std::uint8_t> buffer, std::string_view resource,
                                                 ElementType type, std::uint16_t count) {
  FrameWriter frame{buffer, FrameKind::read};
  frame.name(resource);
  frame.u8(static_cast<std::uint8_t>(type));
  frame.u16(count);
  return frame.finish();
}
template <typename T>
std::span<const std::uint8_t> encode_values(std::span<std::uint8_t> buffer, std::span<const T> values) {
  FrameWriter frame{buffer, FrameKind::values};
  frame.elements(values);
  return frame.finish();
}
inline std::span<const std::uint8_t> encode_tick(std::span<std::uint8_t> buffer, std::uint64_t tick) {
  FrameWriter frame{buffer, FrameKind::tick};
  frame.u64(tick);
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
  constexpr std::uint64_t u64() { return little_endian(8); }
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
inline FrameError parse_element_type(PayloadReader& reader, ElementType& type) {
  const std::uint8_t byte = reader.u8();
  if (reader.spoiled()) return FrameError::wrong_length;
  if (!is_element_type(byte)) return FrameError::bad_element_type;
  type = static_cast<ElementType>(byte);
  return FrameError::none;
}
inline FrameError parse_elements(PayloadReader& reader, PackedElements& values) {
  ElementType type{};
  if (const FrameError error = parse_element_type(reader, type); error != FrameError::none) return error;
  const std::uint16_t count = reader.u16();
  if (reader.spoiled()) return FrameError::wrong_length;
  if (reader.left() != std::size_t{count} * element_size(type)) return FrameError::bad_count;
  values = PackedElements{type, reader.rest()};
  if (type == ElementType::boolean) {
    for (std::size_t k = 0; k < values.size(); ++k) {
      if (values.bits(k) > 1) return FrameError::bad_boolean;
    }
  }
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
  return detail::parse_elements(reader, out.values);
}
inline FrameError parse(std::span<const std::uint8_t> payload, Read& out) {
  PayloadReader reader{payload};
  if (const FrameError error = detail::parse_name(reader, out.resource); error != FrameError::none) return error;
  if (const FrameError error = detail::parse_element_type(reader, out.type); error != FrameError::none) return error;
  out.count = reader.u16();
  return reader.spoiled() || reader.left() != 0 ? FrameError::wrong_length : FrameError::none;
}
inline FrameError parse(std::span<const std::uint8_t> payload, Values& out) {
  PayloadReader reader{payload};
  return detail::parse_elements(reader, out.values);
}
inline FrameError parse(std::span<const std::uint8_t> payload, Tick& out) {
  if (payload.size() != 8) return FrameError::wrong_length;
  PayloadReader reader{payload};
  out.tick = reader.u64();
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
