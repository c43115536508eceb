#include "duet/support/closest_word.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace duet {
namespace {

// Optimal string alignment distance: Levenshtein plus transposition of two adjacent letters ("smi" for "sim").
std::size_t edit_distance(std::string_view from, std::string_view to) {
  const std::size_t columns = to.size() + 1;
  std::vector<std::size_t> table((from.size() + 1) * columns);
  auto cell = [&](std::size_t row, std::size_t column) -> std::size_t& { return table[row * columns + column]; };
  for (std::size_t row = 0; row <= from.size(); ++row) cell(row, 0) = row;
  for (std::size_t column = 0; column <= to.size(); ++column) cell(0, column) = column;
  for (std::size_t row = 1; row <= from.size(); ++row) {
    for (std::size_t column = 1; column <= to.size(); ++column) {
      const std::size_t substitution = from[row - 1] == to[column - 1] ? 0 : 1;
      std::size_t best =
          std::min({cell(row - 1, column) + 1, cell(row, column - 1) + 1, cell(row - 1, column - 1) + substitution});
      if (row > 1 && column > 1 && from[row - 1] == to[column - 2] && from[row - 2] == to[column - 1]) {
        best = std::min(best, cell(row - 2, column - 2) + 1);
      }
      cell(row, column) = best;
    }
  }
  return cell(from.size(), to.size());
}

}  // namespace

std::optional<std::string_view> closest_word(std::string_view word, std::span<const std::string_view> candidates) {
  constexpr std::size_t most_edits = 2;
  std::optional<std::string_view> closest;
  std::size_t closest_distance = most_edits + 1;
  for (std::string_view candidate : candidates) {
    const std::size_t distance = edit_distance(word, candidate);
    if (distance < closest_distance && distance < word.size()) {
      closest = candidate;
      closest_distance = distance;
    }
  }
  return closest;
}

}  // namespace duet
