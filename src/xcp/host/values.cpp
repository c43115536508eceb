#include "duet/xcp/host/values.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

namespace duet::xcp::host {
namespace {

std::uint64_t little_endian(std::span<const std::uint8_t> bytes) {
  std::uint64_t value = 0;
  for (std::size_t byte = 0; byte < bytes.size(); ++byte)
    value |= static_cast<std::uint64_t>(bytes[byte]) << (8U * byte);
  return value;
}

double raw_value(DataType type, std::span<const std::uint8_t> bytes) {
  const std::uint64_t bits = little_endian(bytes);
  switch (type) {
    case DataType::uint8: return static_cast<double>(static_cast<std::uint8_t>(bits));
    case DataType::int8: return static_cast<double>(static_cast<std::int8_t>(bits));
    case DataType::uint16: return static_cast<double>(static_cast<std::uint16_t>(bits));
    case DataType::int16: return static_cast<double>(static_cast<std::int16_t>(bits));
    case DataType::uint32: return static_cast<double>(static_cast<std::uint32_t>(bits));
    case DataType::int32: return static_cast<double>(static_cast<std::int32_t>(bits));
    case DataType::uint64: return static_cast<double>(bits);
    case DataType::int64: return static_cast<double>(static_cast<std::int64_t>(bits));
    case DataType::float32: return static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(bits)));
    case DataType::float64: return std::bit_cast<double>(bits);
  }
  return 0;
}

template <typename Integer>
Result<std::uint64_t> integer_bits(const Variable& variable, double raw) {
  const double rounded = std::round(raw);
  if (rounded < static_cast<double>(std::numeric_limits<Integer>::min()) ||
      rounded > static_cast<double>(std::numeric_limits<Integer>::max())) {
    return Failure{variable.name + ": the raw value " + std::to_string(rounded) + " does not fit " +
                   std::string{a2l_name(variable.type)}};
  }
  return static_cast<std::uint64_t>(static_cast<Integer>(rounded));
}

}  // namespace

std::vector<double> decode(const Variable& variable, std::span<const std::uint8_t> bytes) {
  const std::size_t size = size_of(variable.type);
  std::vector<double> values;
  for (std::size_t at = 0; at + size <= bytes.size(); at += size) {
    values.push_back(variable.conversion.factor * raw_value(variable.type, bytes.subspan(at, size)) +
                     variable.conversion.offset);
  }
  return values;
}

Result<std::vector<std::uint8_t>> encode(const Variable& variable, double value) {
  if (!std::isfinite(value) || value < variable.minimum || value > variable.maximum) {
    std::ostringstream message;
    message << variable.name << ": " << value << " is outside " << variable.minimum << " .. " << variable.maximum;
    if (!variable.unit.empty()) message << ' ' << variable.unit;
    return Failure{message.str()};
  }
  const double raw = (value - variable.conversion.offset) / variable.conversion.factor;
  Result<std::uint64_t> bits = std::uint64_t{0};
  switch (variable.type) {
    case DataType::uint8: bits = integer_bits<std::uint8_t>(variable, raw); break;
    case DataType::int8: bits = integer_bits<std::int8_t>(variable, raw); break;
    case DataType::uint16: bits = integer_bits<std::uint16_t>(variable, raw); break;
    case DataType::int16: bits = integer_bits<std::int16_t>(variable, raw); break;
    case DataType::uint32: bits = integer_bits<std::uint32_t>(variable, raw); break;
    case DataType::int32: bits = integer_bits<std::int32_t>(variable, raw); break;
    case DataType::uint64: bits = integer_bits<std::uint64_t>(variable, raw); break;
    case DataType::int64: bits = integer_bits<std::int64_t>(variable, raw); break;
    case DataType::float32: bits = std::bit_cast<std::uint32_t>(static_cast<float>(raw)); break;
    case DataType::float64: bits = std::bit_cast<std::uint64_t>(raw); break;
  }
  if (!bits) return Failure{bits.error()};
  std::vector<std::uint8_t> bytes(size_of(variable.type));
  for (std::size_t byte = 0; byte < bytes.size(); ++byte)
    bytes[byte] = static_cast<std::uint8_t>(bits.value() >> (8U * byte));
  return bytes;
}

}  // namespace duet::xcp::host
