#pragma once
// Little-endian integers and doubles into and out of byte buffers: MDF 4's byte order, also the PC's.

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
  std::uint64_t size() const { return bytes_.size(); }
  std::vector<std::uint8_t>& bytes() { return bytes_; }
  void append_text(std::string_view text) { bytes_.insert(bytes_.end(), text.begin(), text.end()); }
  void append_zeros(std::uint64_t count) { bytes_.resize(bytes_.size() + count, 0); }
  template <typename T>
  void append(T value) {
    const std::size_t at = bytes_.size();
    bytes_.resize(at + sizeof value);
    store(bytes_.data() + at, value);
  }
  template <typename T>
  void put(std::uint64_t at, T value) {
    store(bytes_.data() + at, value);
  }
  void align(std::uint64_t alignment) { append_zeros((alignment - size() % alignment) % alignment); }

 private:
  std::vector<std::uint8_t> bytes_;
};

}  // namespace duet::mdf4
