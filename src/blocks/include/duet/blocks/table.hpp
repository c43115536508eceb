#pragma once
// Indexing into a constant table (Simulink's Direct Lookup Table, 1-D, and Selector with a run-time index).
// Pure and interrupt-safe.

#include <cstddef>
#include <cstdint>
#include <span>

#include "duet/blocks/convert.hpp"
#include "duet/blocks/element.hpp"

namespace duet::blocks {

// table[index], with index made an integer as convert<std::int64_t> does (floating point truncates toward zero, a NaN
// is 0, bool is 0 or 1) and then clamped to [0, size - 1], so no index reads outside the table: -3 and -0.9 read the
// first element, 2.7 the third, 1e30 the last.
// Precondition: the table is not empty; an empty one gives T{} (there is nothing sensible to return).
template <typename T, typename Index>
constexpr T element_at(std::span<const T> table, Index index) {
  static_assert(Element<T> && Element<Index>, "element_at: element types are floating point, integers and bool");
  if (table.empty()) return T{};
  if constexpr (Floating<Index>) {
    // The same clamping without converting to 64 bits, which costs library calls on the Cortex-M4: below 1 (or a NaN)
    // is the first element; from the size on, the last; in between the truncated position.
    if (!(index >= Index{1})) return table.front();
    if (index >= static_cast<Index>(table.size())) return table.back();
    const auto truncated = static_cast<std::size_t>(index);
    return truncated >= table.size() ? table.back() : table[truncated];  // a size that rounded down as Index
  } else {
    const auto position = convert<std::int64_t>(index);
    if (position <= 0) return table.front();
    // Compared in 64 bits: on the Cortex-M4 std::size_t has 32 and would cut large positions down into the table.
    if (static_cast<std::uint64_t>(position) >= static_cast<std::uint64_t>(table.size())) return table.back();
    return table[static_cast<std::size_t>(position)];
  }
}

}  // namespace duet::blocks
