#include "duet/support/number_text.hpp"

#include <array>
#include <charconv>

namespace duet {

std::string shortest_text(double value) {
  std::array<char, 32> text{};  // the longest double, -2.2250738585072014e-308, has 24 characters
  char* const end = std::to_chars(text.data(), text.data() + text.size(), value).ptr;
  return std::string(text.data(), end);
}

}  // namespace duet
