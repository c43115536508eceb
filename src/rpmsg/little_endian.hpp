#pragma once
// Little-endian words in byte memory, for the vrings and the RPMsg headers that both cores read and write: byte by
// byte, so that an unaligned field or another core's view of the bytes never matters. `Byte` is std::uint8_t for a
// buffer the device owns for now, volatile std::uint8_t for ring fields the other core may change meanwhile.

#include <cstdint>

namespace duet::rpmsg::little_endian {

template <typename Byte>
std::uint16_t get16(const Byte* at) {
  return static_cast<std::uint16_t>(at[0] | at[1] << 8U);
}
template <typename Byte>
std::uint32_t get32(const Byte* at) {
  return static_cast<std::uint32_t>(at[0]) | static_cast<std::uint32_t>(at[1]) << 8U |
         static_cast<std::uint32_t>(at[2]) << 16U | static_cast<std::uint32_t>(at[3]) << 24U;
}
template <typename Byte>
void put16(Byte* at, std::uint16_t value) {
  at[0] = static_cast<std::uint8_t>(value);
  at[1] = static_cast<std::uint8_t>(value >> 8U);
}
template <typename Byte>
void put32(Byte* at, std::uint32_t value) {
  for (unsigned byte = 0; byte < 4; ++byte) at[byte] = static_cast<std::uint8_t>(value >> (8U * byte));
}

}  // namespace duet::rpmsg::little_endian
