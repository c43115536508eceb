#pragma once
// Reading and writing the fields of XCP packets. Multi-byte fields are little-endian (the slave announces Intel byte
// order in CONNECT). Reading past the end yields zeros and marks the reader, so handlers check lengths first.

#include <cstddef>
#include <cstdint>
#include <span>

namespace duet::xcp {

class PacketReader {
 public:
  constexpr explicit PacketReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  [[nodiscard]] constexpr std::size_t size() const { return bytes_.size(); }
  [[nodiscard]] constexpr std::size_t remaining() const { return bytes_.size() - position_; }
  constexpr void skip(std::size_t count) { position_ = count < remaining() ? position_ + count : bytes_.size(); }

  constexpr std::uint8_t u8() { return position_ < bytes_.size() ? bytes_[position_++] : 0; }
  constexpr std::uint16_t u16() {
    const std::uint8_t low = u8();
    return static_cast<std::uint16_t>(low | (u8() << 8U));
  }
  constexpr std::uint32_t u32() {
    const std::uint16_t low = u16();
    return low | (static_cast<std::uint32_t>(u16()) << 16U);
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
};

class PacketWriter {
 public:
  constexpr explicit PacketWriter(std::span<std::uint8_t> buffer) : buffer_(buffer) {}

  constexpr PacketWriter& u8(std::uint8_t value) {
    if (size_ < buffer_.size()) {
      buffer_[size_++] = value;
    } else {
      overflowed_ = true;
    }
    return *this;
  }
  constexpr PacketWriter& u16(std::uint16_t value) {
    return u8(static_cast<std::uint8_t>(value)).u8(static_cast<std::uint8_t>(value >> 8U));
  }
  constexpr PacketWriter& u32(std::uint32_t value) {
    return u16(static_cast<std::uint16_t>(value)).u16(static_cast<std::uint16_t>(value >> 16U));
  }
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
  std::size_t size_ = 0;
  bool overflowed_ = false;
};

}  // namespace duet::xcp
