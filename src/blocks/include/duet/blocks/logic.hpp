#pragma once
// Logical and relational operators (Simulink's Logical Operator and Relational Operator). Pure and interrupt-safe.
//
// The interpreter picks the operator at run time and passes the inputs as a span; generated code knows both at compile
// time and calls the variadic template. Both give the same result for the same inputs, including no inputs at all:
// and/nor give true, or/xor/nand give false (the empty and is true, the empty or false). There is no logical_not:
// nand or nor with one input is not.

#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

#include "duet/blocks/element.hpp"

namespace duet::blocks {

enum class LogicOperator : std::uint8_t { logical_and, logical_or, logical_xor, logical_nand, logical_nor };

namespace detail {

// Every operator depends only on how many of the inputs are true, so both forms share this.
constexpr bool logic_of_counts(LogicOperator op, std::size_t true_count, std::size_t input_count) {
  switch (op) {
    case LogicOperator::logical_and: return true_count == input_count;
    case LogicOperator::logical_or: return true_count != 0;
    case LogicOperator::logical_xor: return true_count % 2 != 0;
    case LogicOperator::logical_nand: return true_count != input_count;
    case LogicOperator::logical_nor: return true_count == 0;
  }
  return false;  // not an enumerator: unreachable for a valid LogicOperator
}

}  // namespace detail

constexpr bool logic(LogicOperator op, std::span<const bool> inputs) {
  std::size_t true_count = 0;
  for (const bool input : inputs) true_count += input ? 1U : 0U;
  return detail::logic_of_counts(op, true_count, inputs.size());
}

template <LogicOperator op, typename... B>
requires(std::is_same_v<B, bool>&&...) constexpr bool logic(B... inputs) {
  const auto true_count = (std::size_t{0} + ... + (inputs ? std::size_t{1} : std::size_t{0}));
  return detail::logic_of_counts(op, true_count, sizeof...(inputs));
}

enum class CompareOperator : std::uint8_t { less, less_equal, equal, not_equal, greater_equal, greater };

// u <op> value. With a NaN every comparison is false except not_equal, as in IEEE 754.
template <Element T>
constexpr bool compare(CompareOperator op, T u, T value) {
  switch (op) {
    case CompareOperator::less: return u < value;
    case CompareOperator::less_equal: return u <= value;
    case CompareOperator::equal: return u == value;
    case CompareOperator::not_equal: return u != value;
    case CompareOperator::greater_equal: return u >= value;
    case CompareOperator::greater: return u > value;
  }
  return false;  // not an enumerator: unreachable for a valid CompareOperator
}

}  // namespace duet::blocks
