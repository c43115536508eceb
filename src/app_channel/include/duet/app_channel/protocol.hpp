#pragma once
// The application channel's wire format (docs/APP_CHANNEL.md): the firmware describes what it sends (telemetry) and
// accepts (parameters) by name, type, unit and limits, so that the bridge and the dashboard need no code per
// application. Packets travel in XCP-on-SxI frames with a word checksum (LEN, CTR, packet, CS), which finds its way
// back after bytes lost on a tty without flow control. All numbers are little-endian. Freestanding.

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "duet/xcp/framing.hpp"

namespace duet::app_channel {

inline constexpr std::uint8_t protocol_version = 1;
inline constexpr xcp::Framing framing{xcp::FrameHeader::len_ctr_word, xcp::FrameChecksum::word};
// The largest packet either side sends: bounds the receivers' buffers.
inline constexpr std::size_t max_packet = 256;
// The space a receiver's frame decoder needs for the largest frame.
inline constexpr std::size_t decoder_buffer_size = framing.frame_size(max_packet);
inline constexpr std::size_t max_name_length = 63;
inline constexpr std::size_t max_unit_length = 15;
// An item's value names: with the longest name and unit they keep an item packet within max_packet.
inline constexpr std::size_t max_labels = 8;
inline constexpr std::size_t max_label_length = 15;

// A packet's first byte.
enum class Message : std::uint8_t {
  // From the firmware.
  hello = 0x01,  // version u8, application name str, telemetry period us u32, telemetry count u8, parameter count u8
  // kind u8, index u8, type u8, minimum f64, maximum f64, name str, unit str, then optionally label count u8 and
  // that many str: the names of the values 0, 1, ...
  item = 0x02,
  described = 0x03,  // (the description is complete)
  telemetry = 0x04,  // sample u32, then every telemetry item's value in order, each as its type
  parameter = 0x05,  // index u8, status u8, the parameter's value now, as its type
  // The executive's account, then a `task` packet per task: ticks u32 low, u32 high, base period ns u32,
  // busy ppm u32, overruns u32, the frequency the cycle counts count in Hz u32, task count u8.
  executive = 0x06,
  task = 0x07,  // index u8, activations u32, overruns u32, min, mean, max cycles u32, name str
  // To the firmware.
  describe = 0x81,  // (send the description and every parameter's value)
  set = 0x82,       // index u8, value as the parameter's type
};

enum class ItemKind : std::uint8_t { telemetry = 0, parameter = 1 };

enum class ValueType : std::uint8_t { u8 = 1, i8 = 2, u16 = 3, i16 = 4, u32 = 5, i32 = 6, f32 = 7, f64 = 8 };

// What became of a set (or `reported`: a value sent with the description).
enum class ParameterStatus : std::uint8_t {
  applied = 0,
  clamped = 1,  // out of the limits: the nearest limit was applied
  unknown_parameter = 2,
  malformed = 3,  // the value's size does not match the parameter's type
  reported = 4,
};

[[nodiscard]] constexpr std::size_t size_of(ValueType type) {
  switch (type) {
    case ValueType::u8:
    case ValueType::i8: return 1;
    case ValueType::u16:
    case ValueType::i16: return 2;
    case ValueType::u32:
    case ValueType::i32:
    case ValueType::f32: return 4;
    case ValueType::f64: return 8;
  }
  return 0;
}

[[nodiscard]] constexpr bool is_value_type(std::uint8_t code) { return code >= 1 && code <= 8; }

template <typename T>
constexpr ValueType value_type_of() {
  if constexpr (std::is_same_v<T, std::uint8_t>)
    return ValueType::u8;
  else if constexpr (std::is_same_v<T, std::int8_t>)
    return ValueType::i8;
  else if constexpr (std::is_same_v<T, std::uint16_t>)
    return ValueType::u16;
  else if constexpr (std::is_same_v<T, std::int16_t>)
    return ValueType::i16;
  else if constexpr (std::is_same_v<T, std::uint32_t>)
    return ValueType::u32;
  else if constexpr (std::is_same_v<T, std::int32_t>)
    return ValueType::i32;
  else if constexpr (std::is_same_v<T, float>)
    return ValueType::f32;
  else {
    static_assert(std::is_same_v<T, double>, "the application channel carries 8 to 32-bit integers, float and double");
    return ValueType::f64;
  }
}

}  // namespace duet::app_channel
