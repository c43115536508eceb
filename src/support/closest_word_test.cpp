#include "duet/support/closest_word.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string_view>

namespace duet {
namespace {

constexpr std::array<std::string_view, 6> commands{"xcp", "sim", "gen", "sched", "monitor", "model"};

TEST(ClosestWord, SuggestsTheCommandOneTypoAway) {
  EXPECT_EQ(closest_word("shced", commands), "sched");  // adjacent letters swapped
  EXPECT_EQ(closest_word("monitr", commands), "monitor");
  EXPECT_EQ(closest_word("xcpp", commands), "xcp");
  EXPECT_EQ(closest_word("modle", commands), "model");
}

TEST(ClosestWord, SuggestsNothingForUnrelatedWords) {
  EXPECT_EQ(closest_word("nonsense", commands), std::nullopt);
  EXPECT_EQ(closest_word("deploy", commands), std::nullopt);
  // One letter is only two edits from "xcp", but that is too little to go on.
  EXPECT_EQ(closest_word("x", commands), std::nullopt);
}

}  // namespace
}  // namespace duet
