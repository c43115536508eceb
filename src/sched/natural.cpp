#include "natural.hpp"

#include <algorithm>

namespace duet::sched {
namespace {

constexpr int word_bits = 32;
constexpr std::uint64_t word_mask = 0xffff'ffffU;

}  // namespace

Natural::Natural(std::uint64_t value) {
  for (; value != 0; value >>= word_bits) words_.push_back(static_cast<std::uint32_t>(value & word_mask));
}

void Natural::multiply_by_word(std::uint32_t factor) {
  std::uint64_t carry = 0;
  for (std::uint32_t& word : words_) {
    const std::uint64_t product = std::uint64_t{word} * factor + carry;  // < 2^64: (2^32 - 1)^2 + 2^32 - 1
    word = static_cast<std::uint32_t>(product & word_mask);
    carry = product >> word_bits;
  }
  if (carry != 0) words_.push_back(static_cast<std::uint32_t>(carry));
  drop_leading_zeros();
}

Natural& Natural::operator*=(std::uint64_t factor) {
  // this * (high * 2^32 + low) = (this * high) shifted up a word, plus this * low
  Natural high_part = *this;
  high_part.multiply_by_word(static_cast<std::uint32_t>(factor >> word_bits));
  if (!high_part.words_.empty()) {  // shifted up a word (push and rotate: GCC 12 -O3 warns falsely on insert at front)
    high_part.words_.push_back(0U);
    std::rotate(high_part.words_.begin(), high_part.words_.end() - 1, high_part.words_.end());
  }
  multiply_by_word(static_cast<std::uint32_t>(factor & word_mask));
  return *this += high_part;
}

Natural& Natural::operator+=(const Natural& other) {
  words_.resize(std::max(words_.size(), other.words_.size()), 0U);
  std::uint64_t carry = 0;
  for (std::size_t i = 0; i < words_.size(); ++i) {
    const std::uint64_t sum = std::uint64_t{words_[i]} + (i < other.words_.size() ? other.words_[i] : 0U) + carry;
    words_[i] = static_cast<std::uint32_t>(sum & word_mask);
    carry = sum >> word_bits;
  }
  if (carry != 0) words_.push_back(static_cast<std::uint32_t>(carry));
  return *this;
}

void Natural::drop_leading_zeros() {
  while (!words_.empty() && words_.back() == 0) words_.pop_back();
}

std::strong_ordering operator<=>(const Natural& a, const Natural& b) {
  if (a.words_.size() != b.words_.size()) return a.words_.size() <=> b.words_.size();
  return std::lexicographical_compare_three_way(a.words_.rbegin(), a.words_.rend(), b.words_.rbegin(), b.words_.rend());
}

}  // namespace duet::sched
