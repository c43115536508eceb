// The few C library functions that firmware needs although it links no C library: the compiler emits calls to memcpy,
// memmove, memset and memcmp for copies and zeroing even in code that never names them, and std::string_view's
// constructor from a C string calls strlen. This file is compiled with -fno-tree-loop-distribute-patterns so
// that the compiler does not turn these loops back into calls to themselves.

#include <cstddef>
#include <cstdint>

extern "C" {

// A word that may alias any object, as memcpy's copies do.
using AliasingWord [[gnu::may_alias]] = std::uint32_t;

// Word by word while both ends are word-aligned (the usual case for DAQ entries and parameter groups), then bytes.
void* memcpy(void* destination, const void* source, std::size_t count) {
  auto* to = static_cast<unsigned char*>(destination);
  const auto* from = static_cast<const unsigned char*>(source);
  if (((reinterpret_cast<std::uintptr_t>(to) | reinterpret_cast<std::uintptr_t>(from)) & 3U) == 0) {
    for (; count >= 4; count -= 4, to += 4, from += 4) {
      *static_cast<AliasingWord*>(static_cast<void*>(to)) =
          *static_cast<const AliasingWord*>(static_cast<const void*>(from));
    }
  }
  while (count-- > 0) *to++ = *from++;
  return destination;
}

void* memmove(void* destination, const void* source, std::size_t count) {
  auto* to = static_cast<unsigned char*>(destination);
  const auto* from = static_cast<const unsigned char*>(source);
  if (to < from) {
    while (count-- > 0) *to++ = *from++;
  } else {
    while (count-- > 0) to[count] = from[count];
  }
  return destination;
}

void* memset(void* destination, int value, std::size_t count) {
  auto* to = static_cast<unsigned char*>(destination);
  while (count-- > 0) *to++ = static_cast<unsigned char>(value);
  return destination;
}

int memcmp(const void* left, const void* right, std::size_t count) {
  const auto* a = static_cast<const unsigned char*>(left);
  const auto* b = static_cast<const unsigned char*>(right);
  for (; count > 0; --count, ++a, ++b) {
    if (*a != *b) return *a < *b ? -1 : 1;
  }
  return 0;
}
std::size_t strlen(const char* text) {
  const char* end = text;
  while (*end != '\0') ++end;
  return static_cast<std::size_t>(end - text);
}
}
