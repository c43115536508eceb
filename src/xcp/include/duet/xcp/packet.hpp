#pragma once
// Reading and writing the fields of XCP packets. Multi-byte fields are in the slave's byte order (CONNECT's
// COMM_MODE_BASIC bit 0): Intel (little-endian, the default) or Motorola (big-endian). Reading past the end yields
// zeros, so handlers check lengths first.

#include <cstddef>
#include <cstdint>
#include <span>

namespace duet::xcp {

enum class ByteOrder : std::uint8_t { intel = 0, motorola = 1 };

class PacketReader {
 public:
  constexpr explicit PacketReader(std::span<const std::uint8_t> bytes, ByteOrder order = ByteOrder::intel)
      : bytes_(bytes), order_(order) {}

  [[nodiscard]] constexpr std::size_t size() const { return bytes_.size(); }
  [[nodiscard]] constexpr std::size_t remaining() const { return bytes_.size() - position_; }
  constexpr void skip(std::size_t count) { position_ = count < remaining() ? position_ + count : bytes_.size(); }

  constexpr std::uint8_t u8() { return position_ < bytes_.size() ? bytes_[position_++] : 0; }
  constexpr std::uint16_t u16() {
    const std::uint8_t first = u8();
    const std::uint8_t second = u8();
    return order_ == ByteOrder::intel ? static_cast<std::uint16_t>(first | (second << 8U))
                                      : static_cast<std::uint16_t>((first << 8U) | second);
  }
  constexpr std::uint32_t u32() {
    const std::uint16_t first = u16();
    const std::uint16_t second = u16();
    return order_ == ByteOrder::intel ? first | (static_cast<std::uint32_t>(second) << 16U)
                                      : (static_cast<std::uint32_t>(first) << 16U) | second;
  }
  // The next `count` bytes, or fewer if the packet ends first.
  constexpr std::span<const std::uint8_t> bytes(std::size_t count) {
    const std::size_t available = count < remaining() ? count : remaining();
    const std::span<const std::uint8_t> taken = bytes_.subspan(position_, available);
    position_ += available;
    return taken;
  }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t position_ = 0;
  ByteOrder order_;
};

// Multi-byte fields in a byte order, written through the derived writer's u8() and order(): the slave's responses
// (PacketWriter) and the master's commands (duet::xcp::host::CommandPacket) order their fields here.
template <typename Writer>
class OrderedFieldWriter {
 public:
  constexpr Writer& u16(std::uint16_t value) {
    const auto low = static_cast<std::uint8_t>(value);
    const auto high = static_cast<std::uint8_t>(value >> 8U);
    return self().order() == ByteOrder::intel ? self().u8(low).u8(high) : self().u8(high).u8(low);
  }
  constexpr Writer& u32(std::uint32_t value) {
    const auto low = static_cast<std::uint16_t>(value);
    const auto high = static_cast<std::uint16_t>(value >> 16U);
    return self().order() == ByteOrder::intel ? u16(low).u16(high) : u16(high).u16(low);
  }

 private:
  constexpr Writer& self() { return static_cast<Writer&>(*this); }
};

class PacketWriter : public OrderedFieldWriter<PacketWriter> {
 public:
  constexpr explicit PacketWriter(std::span<std::uint8_t> buffer, ByteOrder order = ByteOrder::intel)
      : buffer_(buffer), order_(order) {}

  constexpr PacketWriter& u8(std::uint8_t value) {
    if (size_ < buffer_.size()) {
      buffer_[size_++] = value;
    } else {
      overflowed_ = true;
    }
    return *this;
  }
  [[nodiscard]] constexpr ByteOrder order() const { return order_; }
  constexpr PacketWriter& bytes(std::span<const std::uint8_t> values) {
    for (std::uint8_t value : values) u8(value);
    return *this;
  }

  [[nodiscard]] constexpr std::span<const std::uint8_t> written() const { return buffer_.first(size_); }
  [[nodiscard]] constexpr std::size_t size() const { return size_; }
  [[nodiscard]] constexpr bool overflowed() const { return overflowed_; }
  constexpr void clear() {
    size_ = 0;
    overflowed_ = false;
  }

 private:
  std::span<std::uint8_t> buffer_;
  ByteOrder order_;
  std::size_t size_ = 0;
  bool overflowed_ = false;
};

}  // namespace duet::xcp
