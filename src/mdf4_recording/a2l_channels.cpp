#include "duet/mdf4_recording/a2l_channels.hpp"

#include <array>
#include <bit>
#include <charconv>

namespace duet::mdf4_recording {

using xcp::host::DataType;

mdf4::ValueType value_type(DataType type) {
  switch (type) {
    case DataType::uint8: return mdf4::ValueType::u8;
    case DataType::int8: return mdf4::ValueType::i8;
    case DataType::uint16: return mdf4::ValueType::u16;
    case DataType::int16: return mdf4::ValueType::i16;
    case DataType::uint32: return mdf4::ValueType::u32;
    case DataType::int32: return mdf4::ValueType::i32;
    case DataType::uint64: return mdf4::ValueType::u64;
    case DataType::int64: return mdf4::ValueType::i64;
    case DataType::float32: return mdf4::ValueType::f32;
    case DataType::float64: return mdf4::ValueType::f64;
  }
  return mdf4::ValueType::f64;
}

namespace {

// The shortest text that reads back as `number` ("0", "2.5").
std::string shortest(double number) {
  std::array<char, 32> text{};
  const auto end = std::to_chars(text.data(), text.data() + text.size(), number).ptr;
  return {text.data(), end};
}

// What a reader of the file must know of a conversion it does not find in the channel.
std::string raw_note(const xcp::host::Variable& variable) {
  if (!variable.labels.empty()) {
    std::string note = "raw values, named by the A2L: ";
    for (std::size_t k = 0; k < variable.labels.size(); ++k) {
      note += (k == 0 ? "" : ", ") + shortest(variable.labels[k].raw) + " " + variable.labels[k].text;
    }
    return note;
  }
  if (!variable.unapplied_conversion.empty())
    return "raw values: the A2L's " + variable.unapplied_conversion + " conversion is not written";
  return {};
}

template <typename Stored>
Stored stored(std::span<const std::uint8_t> bytes) {
  std::uint64_t bits = 0;
  for (std::size_t byte = 0; byte < sizeof(Stored); ++byte)
    bits |= static_cast<std::uint64_t>(bytes[byte]) << (8U * byte);
  if constexpr (sizeof(Stored) == 8) {
    return std::bit_cast<Stored>(bits);
  } else if constexpr (sizeof(Stored) == 4) {
    return std::bit_cast<Stored>(static_cast<std::uint32_t>(bits));
  } else if constexpr (sizeof(Stored) == 2) {
    return std::bit_cast<Stored>(static_cast<std::uint16_t>(bits));
  } else {
    return std::bit_cast<Stored>(static_cast<std::uint8_t>(bits));
  }
}

mdf4::Value raw_value(DataType type, std::span<const std::uint8_t> bytes) {
  switch (type) {
    case DataType::uint8: return stored<std::uint8_t>(bytes);
    case DataType::int8: return stored<std::int8_t>(bytes);
    case DataType::uint16: return stored<std::uint16_t>(bytes);
    case DataType::int16: return stored<std::int16_t>(bytes);
    case DataType::uint32: return stored<std::uint32_t>(bytes);
    case DataType::int32: return stored<std::int32_t>(bytes);
    case DataType::uint64: return stored<std::uint64_t>(bytes);
    case DataType::int64: return stored<std::int64_t>(bytes);
    case DataType::float32: return stored<float>(bytes);
    case DataType::float64: return stored<double>(bytes);
  }
  return std::monostate{};
}

}  // namespace

mdf4::ChannelSpec channel(const xcp::host::Variable& variable) {
  mdf4::ChannelSpec spec{.name = variable.name,
                         .type = value_type(variable.type),
                         .unit = variable.unit,
                         .comment = variable.description,
                         .conversion = std::nullopt,
                         .elements = variable.count};
  if (variable.conversion != xcp::host::Conversion{})
    spec.conversion = mdf4::Linear{variable.conversion.factor, variable.conversion.offset};
  if (const std::string note = raw_note(variable); !note.empty())
    spec.comment += (spec.comment.empty() ? "" : " (") + note + (spec.comment.empty() ? "" : ")");
  return spec;
}

void append_raw_values(const xcp::host::Variable& variable, std::span<const std::uint8_t> bytes,
                       std::vector<mdf4::Value>& values) {
  const std::size_t size = xcp::host::size_of(variable.type);
  for (std::size_t at = 0; at + size <= bytes.size(); at += size)
    values.push_back(raw_value(variable.type, bytes.subspan(at, size)));
}

}  // namespace duet::mdf4_recording
