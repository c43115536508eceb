#pragma once
// Little-endian integers and doubles into and out of byte buffers: MDF 4's byte order, also the PC's.

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <vector>

namespace duet::mdf4 {

static_assert(std::endian::native == std::endian::little, "the MDF 4 writer and reader assume a little-endian host");

template <typename T>
T load(const std::uint8_t* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof value);
  return value;
}

template <typename T>
void store(std::uint8_t* bytes, T value) {
  std::memcpy(bytes, &value, sizeof value);
}

// Bytes appended at the end, or put at a place already written.
class ByteBuffer {
 public:
  [[nodiscard]] std::size_t size() const { return bytes_.size(); }
  std::vector<std::uint8_t>& bytes() { return bytes_; }
  void append_text(std::string_view text) {
    if (!text.empty()) std::memcpy(grow(text.size()), text.data(), text.size());
  }
  void append_zeros(std::size_t count) {
    if (count > 0) std::memset(grow(count), 0, count);
  }
  template <typename T>
  void append(T value) {
    store(grow(sizeof value), value);
  }
  template <typename T>
  void put(std::uint64_t at, T value) {
    store(bytes_.data() + at, value);
  }
  void align(std::size_t alignment) { append_zeros((alignment - bytes_.size() % alignment) % alignment); }

 private:
  // Room for `count` more bytes at the end, uninitialised as far as callers are concerned.
  std::uint8_t* grow(std::size_t count) {
    const std::size_t at = bytes_.size();
    if (bytes_.capacity() < at + count) bytes_.reserve(std::max<std::size_t>(2 * bytes_.capacity(), at + count));
    bytes_.resize(at + count);
    return bytes_.data() + at;
  }
  std::vector<std::uint8_t> bytes_;
};

}  // namespace duet::mdf4
