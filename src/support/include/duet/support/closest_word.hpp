#pragma once
// "Did you mean ...?" for mistyped words: commands, block types, names.

#include <optional>
#include <span>
#include <string_view>

namespace duet {

// The candidate nearest to `word` by edit distance (insertions, deletions, substitutions, adjacent swaps), if one is
// close enough to be a plausible typo: at most two edits, and fewer edits than the word has letters.
std::optional<std::string_view> closest_word(std::string_view word, std::span<const std::string_view> candidates);

}  // namespace duet
