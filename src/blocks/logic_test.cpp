#include "duet/blocks/logic.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <limits>
#include <span>

namespace duet::blocks {
namespace {

static_assert(logic<LogicOperator::logical_xor>(true, true, true));
static_assert(!logic(LogicOperator::logical_nor, std::array{false, true}));
static_assert(compare(CompareOperator::less_equal, 2, 2));

// The truth table of three inputs, from the definitions rather than from the code under test.
bool expected(LogicOperator op, bool a, bool b, bool c) {
  const int count = (a ? 1 : 0) + (b ? 1 : 0) + (c ? 1 : 0);
  switch (op) {
    case LogicOperator::logical_and: return count == 3;
    case LogicOperator::logical_or: return count > 0;
    case LogicOperator::logical_xor: return count == 1 || count == 3;
    case LogicOperator::logical_nand: return count < 3;
    case LogicOperator::logical_nor: return count == 0;
  }
  return false;
}

// The interpreter's form and generated code's form agree with the truth table on every input combination.
template <LogicOperator op>
void expect_truth_table() {
  for (int pattern = 0; pattern < 8; ++pattern) {
    const bool a = (pattern & 1) != 0;
    const bool b = (pattern & 2) != 0;
    const bool c = (pattern & 4) != 0;
    const std::array inputs{a, b, c};
    EXPECT_EQ(logic(op, inputs), expected(op, a, b, c)) << "pattern " << pattern;
    EXPECT_EQ((logic<op>(a, b, c)), expected(op, a, b, c)) << "pattern " << pattern;
  }
}

TEST(BlocksLogic, AndOverEveryCombination) { expect_truth_table<LogicOperator::logical_and>(); }
TEST(BlocksLogic, OrOverEveryCombination) { expect_truth_table<LogicOperator::logical_or>(); }
TEST(BlocksLogic, XorIsTrueForAnOddNumberOfTrueInputs) { expect_truth_table<LogicOperator::logical_xor>(); }
TEST(BlocksLogic, NandOverEveryCombination) { expect_truth_table<LogicOperator::logical_nand>(); }
TEST(BlocksLogic, NorOverEveryCombination) { expect_truth_table<LogicOperator::logical_nor>(); }

TEST(BlocksLogic, XorOfFourInputs) {
  EXPECT_FALSE((logic<LogicOperator::logical_xor>(true, true, true, true)));
  EXPECT_TRUE((logic<LogicOperator::logical_xor>(true, false, true, true)));
  EXPECT_FALSE(logic(LogicOperator::logical_xor, std::array{true, false, true, false}));
}

TEST(BlocksLogic, OneInputNandAndNorAreNot) {
  for (const bool input : {false, true}) {
    EXPECT_EQ(logic<LogicOperator::logical_nand>(input), !input);
    EXPECT_EQ(logic<LogicOperator::logical_nor>(input), !input);
    EXPECT_EQ(logic(LogicOperator::logical_nand, std::span<const bool>(&input, 1)), !input);
    EXPECT_EQ(logic<LogicOperator::logical_and>(input), input);
    EXPECT_EQ(logic<LogicOperator::logical_xor>(input), input);
  }
}

TEST(BlocksLogic, NoInputsGiveTheEmptyAndAndOr) {
  const std::span<const bool> none;
  EXPECT_TRUE(logic(LogicOperator::logical_and, none));
  EXPECT_FALSE(logic(LogicOperator::logical_or, none));
  EXPECT_FALSE(logic(LogicOperator::logical_xor, none));
  EXPECT_FALSE(logic(LogicOperator::logical_nand, none));
  EXPECT_TRUE(logic(LogicOperator::logical_nor, none));
  EXPECT_TRUE(logic<LogicOperator::logical_and>());
  EXPECT_FALSE(logic<LogicOperator::logical_or>());
  EXPECT_FALSE(logic<LogicOperator::logical_xor>());
  EXPECT_FALSE(logic<LogicOperator::logical_nand>());
  EXPECT_TRUE(logic<LogicOperator::logical_nor>());
}

// Only bool inputs: an int would otherwise be taken as "nonzero" without anyone deciding so.
template <typename T>
concept LogicAccepts = requires(T input) {
  logic<LogicOperator::logical_and>(input, input);
};
static_assert(LogicAccepts<bool> && !LogicAccepts<int> && !LogicAccepts<double>);

struct CompareCase {
  CompareOperator op;
  bool below;  // u < value
  bool equal;  // u == value
  bool above;  // u > value
};

constexpr std::array<CompareCase, 6> compare_cases{{
    {CompareOperator::less, true, false, false},
    {CompareOperator::less_equal, true, true, false},
    {CompareOperator::equal, false, true, false},
    {CompareOperator::not_equal, true, false, true},
    {CompareOperator::greater_equal, false, true, true},
    {CompareOperator::greater, false, false, true},
}};

TEST(BlocksCompare, EveryOperatorOnEveryKindOfElement) {
  for (const CompareCase& c : compare_cases) {
    const auto op = static_cast<int>(c.op);
    EXPECT_EQ(compare(c.op, 1.0, 2.0), c.below) << op;
    EXPECT_EQ(compare(c.op, 2.0, 2.0), c.equal) << op;
    EXPECT_EQ(compare(c.op, 3.0, 2.0), c.above) << op;
    EXPECT_EQ(compare(c.op, -0.0F, 0.0F), c.equal) << op;  // -0 == +0
    EXPECT_EQ(compare<std::int8_t>(c.op, -128, 127), c.below) << op;
    EXPECT_EQ(compare<std::int8_t>(c.op, 127, -128), c.above) << op;
    EXPECT_EQ(compare<std::uint32_t>(c.op, 4000000000U, 1U), c.above) << op;  // no wrap to negative
    EXPECT_EQ(compare<std::int32_t>(c.op, -7, -7), c.equal) << op;
    EXPECT_EQ(compare(c.op, false, true), c.below) << op;
    EXPECT_EQ(compare(c.op, true, true), c.equal) << op;
  }
}

TEST(BlocksCompare, WithNanOnlyNotEqualHolds) {
  const double nan_value = std::numeric_limits<double>::quiet_NaN();
  for (const CompareCase& c : compare_cases) {
    const bool holds = c.op == CompareOperator::not_equal;
    EXPECT_EQ(compare(c.op, nan_value, 1.0), holds) << static_cast<int>(c.op);
    EXPECT_EQ(compare(c.op, 1.0, nan_value), holds) << static_cast<int>(c.op);
    EXPECT_EQ(compare(c.op, nan_value, nan_value), holds) << static_cast<int>(c.op);
  }
}

// Relational compares two signals with these same operators: infinities are ordinary values.
TEST(BlocksCompare, InfinitiesCompareAsValues) {
  const float infinity = std::numeric_limits<float>::infinity();
  EXPECT_TRUE(compare(CompareOperator::less, -infinity, std::numeric_limits<float>::lowest()));
  EXPECT_TRUE(compare(CompareOperator::equal, infinity, infinity));
  EXPECT_FALSE(compare(CompareOperator::greater, infinity, infinity));
  EXPECT_TRUE(compare(CompareOperator::greater_equal, infinity, -infinity));
}

}  // namespace
}  // namespace duet::blocks
