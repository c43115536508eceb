// A record's values decoded as the channel's block describes them, and converted to physical values.
#include <cmath>
#include <cstring>
#include <limits>

#include "bytes.hpp"
#include "duet/mdf4/reader.hpp"
#include "format.hpp"

namespace duet::mdf4 {
namespace {

std::uint64_t big_endian(const std::uint8_t* bytes, std::uint32_t count) {
  std::uint64_t value = 0;
  for (std::uint32_t index = 0; index < count; ++index) value = value << 8 | bytes[index];
  return value;
}

std::uint64_t little_endian(const std::uint8_t* bytes, std::uint32_t count) {
  std::uint64_t value = 0;
  std::memcpy(&value, bytes, count);
  return value;
}

}  // namespace

double to_double(const Number& number) {
  return std::visit([](auto value) { return static_cast<double>(value); }, number);
}

Number Record::value(std::size_t index) const {
  const ChannelInfo& channel = group_->channels[index];
  if (!channel.decoded) return std::uint64_t{0};
  if (channel.role == ChannelInfo::Role::virtual_master || channel.bit_count == 0) return index_;
  const std::uint8_t* at = bytes_.data() + channel.byte_offset;
  const std::uint32_t bytes = (channel.bit_offset + channel.bit_count + 7) / 8;
  using namespace format::data_type;
  const bool big = channel.data_type == unsigned_be || channel.data_type == signed_be || channel.data_type == float_be;
  std::uint64_t raw = big ? big_endian(at, bytes) : little_endian(at, bytes);
  if (channel.data_type == float_le || channel.data_type == float_be) {
    if (channel.bit_count == 32) {
      float value = 0;
      const auto bits = static_cast<std::uint32_t>(raw);
      std::memcpy(&value, &bits, sizeof value);
      return value;
    }
    double value = 0;
    std::memcpy(&value, &raw, sizeof value);
    return value;
  }
  raw >>= channel.bit_offset;
  if (channel.bit_count < 64) raw &= (std::uint64_t{1} << channel.bit_count) - 1;
  if (channel.data_type == signed_le || channel.data_type == signed_be) {
    if (channel.bit_count < 64 && (raw >> (channel.bit_count - 1) & 1) != 0)
      raw |= ~std::uint64_t{0} << channel.bit_count;
    return static_cast<std::int64_t>(raw);
  }
  return raw;
}

bool Record::valid(std::size_t index) const {
  const std::optional<std::uint32_t>& bit = group_->channels[index].invalidation_bit;
  if (!bit) return true;
  if (*bit == std::numeric_limits<std::uint32_t>::max()) return false;  // the channel says all are invalid
  return (bytes_[group_->data_bytes + *bit / 8] >> (*bit % 8) & 1) == 0;
}

Physical Record::physical(std::size_t index) const {
  const Number stored = value(index);
  const Conversion& conversion = group_->channels[index].conversion;
  switch (conversion.kind) {
    case Conversion::Kind::linear: return conversion.factor * to_double(stored) + conversion.offset;
    case Conversion::Kind::value_to_text: {
      const double key = to_double(stored);
      for (const auto& [value, text] : conversion.texts) {
        if (value == key) return text;
      }
      return conversion.default_text;
    }
    case Conversion::Kind::identity:
    case Conversion::Kind::unsupported: break;
  }
  return stored;
}

double Record::time() const {
  if (!group_->master || !group_->channels[*group_->master].decoded) return std::numeric_limits<double>::quiet_NaN();
  const Physical time = physical(*group_->master);
  if (const double* converted = std::get_if<double>(&time)) return *converted;
  if (const Number* number = std::get_if<Number>(&time)) return to_double(*number);
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace duet::mdf4
