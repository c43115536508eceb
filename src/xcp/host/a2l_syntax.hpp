#pragma once
// The A2L file's syntax, shared by the reader and the checker: words, "texts", /begin KEYWORD ... /end KEYWORD blocks
// and /include FILE, resolved relative to the including file's folder. Private to duet_xcp_host.

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace duet::xcp::host::a2l_syntax {

// Where a token or a block starts: the index of its file in Tree::files, its line and column (from 1).
struct Place {
  std::uint32_t file = 0;
  std::size_t line = 1;
  std::size_t column = 1;
};

struct Token {
  enum class Kind : std::uint8_t { word, text, begin, end };
  Kind kind = Kind::word;
  std::string value;
  Place place;
};

struct Block {
  std::string keyword;
  std::vector<Token> values;  // the words and texts directly inside, in order
  std::vector<Block> children;
  Place place;  // of its /begin
};

// A problem with a place, as "FILE:LINE:COLUMN: problem".
struct SyntaxError {
  std::string file;
  Place place;
  std::string problem;
  [[nodiscard]] std::string message() const;
};

// The root holds the top-level words (ASAP2_VERSION ...) and blocks (PROJECT); `files` names the file of every place:
// the first is `source`, then each file an /include brought in.
struct Tree {
  std::vector<std::string> files;
  Block root;
  [[nodiscard]] std::string where(const Place& place) const;  // "FILE:LINE:COLUMN"
};

// Parses A2L text; `source` names it in messages and its folder is where /include looks first.
std::variant<Tree, SyntaxError> parse(std::string_view text, std::string_view source);

// What follows `keyword` among a block's values ("ECU_ADDRESS 0x1000"), if it is there.
const Token* after(const Block& block, std::string_view keyword);
const Block* child(const Block& block, std::string_view keyword);

}  // namespace duet::xcp::host::a2l_syntax
