#pragma once
// A fixed-capacity text builder for freestanding code: console lines and messages without printf or the heap.

#include <concepts>
#include <cstddef>
#include <string_view>
#include <type_traits>

namespace duet {

// Appends text and integers into an inline buffer of `Capacity` characters. Text that does not fit is cut off and
// remembered in `truncated()`, never written past the end. Not interrupt-safe: one owner at a time.
template <std::size_t Capacity>
class TextBuffer {
 public:
  TextBuffer& append(std::string_view text) {
    for (char character : text) {
      push(character);
    }
    return *this;
  }

  // Decimal, with a leading '-' for negative values; every value of every integer type up to 64 bits fits.
  template <std::integral Integer>
  TextBuffer& append(Integer value) {
    if constexpr (std::same_as<Integer, bool>) {
      return append(value ? std::string_view{"true"} : std::string_view{"false"});
    } else {
      char digits[20];  // 2^64 has 20 decimal digits
      std::size_t count = 0;
      // Negate as unsigned, where the most negative value has a magnitude too.
      using Unsigned = std::make_unsigned_t<Integer>;
      const auto bits = static_cast<Unsigned>(value);
      unsigned long long magnitude = value < 0 ? static_cast<Unsigned>(Unsigned{0} - bits) : bits;
      if (value < 0) push('-');
      do {
        digits[count++] = static_cast<char>('0' + magnitude % 10U);
        magnitude /= 10U;
      } while (magnitude != 0U);
      while (count > 0) {
        push(digits[--count]);
      }
      return *this;
    }
  }

  TextBuffer& append(char character) {
    push(character);
    return *this;
  }

  // "0x" followed by exactly `digit_count` lower-case hexadecimal digits (at most 16), as in register dumps.
  TextBuffer& append_hex(unsigned long long value, std::size_t digit_count = 8) {
    append("0x");
    for (std::size_t digit = digit_count; digit > 0; --digit) {
      push("0123456789abcdef"[(value >> (4U * (digit - 1U))) & 0xFU]);
    }
    return *this;
  }

  [[nodiscard]] std::string_view view() const { return {characters_, size_}; }
  [[nodiscard]] bool truncated() const { return truncated_; }
  void clear() {
    size_ = 0;
    truncated_ = false;
  }

 private:
  void push(char character) {
    if (size_ < Capacity) {
      characters_[size_++] = character;
    } else {
      truncated_ = true;
    }
  }

  char characters_[Capacity]{};
  std::size_t size_ = 0;
  bool truncated_ = false;
};

}  // namespace duet
