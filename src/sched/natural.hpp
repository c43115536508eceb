#pragma once
// Natural numbers of any size: just enough to compare a sum of fractions with 1 exactly. (Internal to duet_sched.)

#include <compare>
#include <cstdint>
#include <vector>

namespace duet::sched {

class Natural {
 public:
  explicit Natural(std::uint64_t value);

  Natural& operator*=(std::uint64_t factor);
  Natural& operator+=(const Natural& other);
  friend std::strong_ordering operator<=>(const Natural& a, const Natural& b);

 private:
  void multiply_by_word(std::uint32_t factor);
  void drop_leading_zeros();

  std::vector<std::uint32_t> words_;  // least significant first; no zero word at the top, so 0 has none
};

}  // namespace duet::sched
