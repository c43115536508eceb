#include "duet/support/content_hash.hpp"

#include <cstdint>
#include <cstdio>

namespace duet {

std::string content_hash(std::string_view bytes) {
  std::uint64_t hash = 14695981039346656037ULL;  // FNV-1a's offset basis and prime (64 bits)
  for (const char byte : bytes) {
    hash ^= static_cast<unsigned char>(byte);
    hash *= 1099511628211ULL;
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

}  // namespace duet
