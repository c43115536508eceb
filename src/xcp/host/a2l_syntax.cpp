// Tokens, /include and the block tree of an A2L file.

#include "a2l_syntax.hpp"

#include <filesystem>
#include <optional>

#include "duet/support/text_file.hpp"

namespace duet::xcp::host::a2l_syntax {
namespace {

// An /include inside an /include ...: deeper than this is a loop, or a mistake.
constexpr std::size_t max_include_depth = 16;
// ASAP2 nests a handful of blocks (PROJECT, MODULE, CHARACTERISTIC, AXIS_DESCR, ...); far deeper is no A2L, and the
// tree's users recurse.
constexpr std::size_t max_block_depth = 64;

bool is_space(char character) {
  return character == ' ' || character == '\t' || character == '\r' || character == '\n' || character == '\f';
}

// Splits each file into words, "texts", /begin and /end, dropping comments (/* */ and //), and splices included
// files' tokens in where their /include stood.
class Lexer {
 public:
  std::vector<std::string> files;
  std::vector<Token> tokens;

  std::optional<SyntaxError> read(std::string_view text, const std::string& name, std::size_t depth) {
    const auto file = static_cast<std::uint32_t>(files.size());
    files.push_back(name);
    Place place{file, 1, 1};
    std::size_t at = 0;
    auto advance = [&](std::size_t count) {
      for (std::size_t step = 0; step < count && at < text.size(); ++step, ++at) {
        if (text[at] == '\n') {
          ++place.line;
          place.column = 1;
        } else {
          ++place.column;
        }
      }
    };
    bool include_next = false;
    Place include_place;
    while (at < text.size()) {
      const char character = text[at];
      if (is_space(character)) {
        advance(1);
        continue;
      }
      if (text.substr(at, 2) == "/*") {
        const std::size_t close = text.find("*/", at + 2);
        if (close == std::string_view::npos) return error(place, "a comment that never ends");
        advance(close + 2 - at);
        continue;
      }
      if (text.substr(at, 2) == "//") {
        const std::size_t newline = text.find('\n', at);
        advance((newline == std::string_view::npos ? text.size() : newline) - at);
        continue;
      }
      Token token{Token::Kind::word, "", place};
      if (character == '"') {
        token.kind = Token::Kind::text;
        advance(1);
        for (;;) {
          if (at >= text.size()) return error(token.place, "a text that never ends");
          if (text[at] == '\\' && at + 1 < text.size()) {
            token.value += text[at + 1];
            advance(2);
          } else if (text[at] == '"' && at + 1 < text.size() && text[at + 1] == '"') {  // "" inside a text
            token.value += '"';
            advance(2);
          } else if (text[at] == '"') {
            advance(1);
            break;
          } else {
            token.value += text[at];
            advance(1);
          }
        }
      } else {
        while (at < text.size() && !is_space(text[at]) && text[at] != '"') {
          token.value += text[at];
          advance(1);
        }
        if (token.value == "/begin") token.kind = Token::Kind::begin;
        if (token.value == "/end") token.kind = Token::Kind::end;
      }
      if (include_next) {
        include_next = false;
        if (auto failed = include(token.value, include_place, name, depth)) return failed;
      } else if (token.kind == Token::Kind::word && token.value == "/include") {
        include_next = true;
        include_place = token.place;
      } else {
        tokens.push_back(std::move(token));
      }
    }
    if (include_next) return error(include_place, "/include without a file name after it");
    return std::nullopt;
  }

 private:
  [[nodiscard]] SyntaxError error(const Place& place, std::string problem) const {
    return SyntaxError{files[place.file], place, std::move(problem)};
  }

  std::optional<SyntaxError> include(const std::string& target, const Place& place, const std::string& including,
                                     std::size_t depth) {
    if (depth >= max_include_depth) {
      return error(place, "/include \"" + target + "\": includes nest deeper than " +
                              std::to_string(max_include_depth) + " (does a file include itself?)");
    }
    std::filesystem::path path{target};
    if (path.is_relative()) path = std::filesystem::path{including}.parent_path() / path;
    auto text = read_text_file(path.string());
    if (!text) return error(place, "/include \"" + target + "\": cannot open " + path.string());
    return read(text.value(), path.string(), depth + 1);
  }
};

std::variant<Block, SyntaxError> build_tree(const std::vector<Token>& tokens, const std::vector<std::string>& files) {
  Block root{"", {}, {}, {}};
  std::vector<Block*> open{&root};
  auto error = [&files](const Place& place, std::string problem) {
    return SyntaxError{files[place.file], place, std::move(problem)};
  };
  for (std::size_t index = 0; index < tokens.size(); ++index) {
    const Token& token = tokens[index];
    if (token.kind != Token::Kind::begin && token.kind != Token::Kind::end) {
      open.back()->values.push_back(token);
      continue;
    }
    if (index + 1 >= tokens.size() || tokens[index + 1].kind != Token::Kind::word) {
      return error(token.place, token.value + " without a keyword after it");
    }
    const Token& keyword = tokens[++index];
    if (token.kind == Token::Kind::begin) {
      if (open.size() > max_block_depth) {
        return error(token.place,
                     "/begin " + keyword.value + ": blocks nest deeper than " + std::to_string(max_block_depth));
      }
      open.back()->children.push_back(Block{keyword.value, {}, {}, token.place});
      open.push_back(&open.back()->children.back());
      continue;
    }
    if (open.size() == 1) return error(token.place, "/end " + keyword.value + " without /begin");
    if (open.back()->keyword != keyword.value) {
      const Place& opened = open.back()->place;
      const std::string line = opened.file == token.place.file ? "line " + std::to_string(opened.line)
                                                               : files[opened.file] + ":" + std::to_string(opened.line);
      return error(token.place, "/end " + keyword.value + " closes /begin " + open.back()->keyword + " (" + line + ")");
    }
    open.pop_back();
  }
  if (open.size() > 1) return error(open.back()->place, "/begin " + open.back()->keyword + " is never closed");
  return root;
}

}  // namespace

std::string SyntaxError::message() const {
  return file + ":" + std::to_string(place.line) + ":" + std::to_string(place.column) + ": " + problem;
}

std::string Tree::where(const Place& place) const {
  return files[place.file] + ":" + std::to_string(place.line) + ":" + std::to_string(place.column);
}

std::variant<Tree, SyntaxError> parse(std::string_view text, std::string_view source) {
  Lexer lexer;
  if (auto failed = lexer.read(text, std::string{source}, 0)) return *failed;
  auto root = build_tree(lexer.tokens, lexer.files);
  if (auto* failed = std::get_if<SyntaxError>(&root)) return *failed;
  return Tree{std::move(lexer.files), std::move(std::get<Block>(root))};
}

const Token* after(const Block& block, std::string_view keyword) {
  for (std::size_t index = 0; index + 1 < block.values.size(); ++index) {
    if (block.values[index].kind == Token::Kind::word && block.values[index].value == keyword)
      return &block.values[index + 1];
  }
  return nullptr;
}

const Block* child(const Block& block, std::string_view keyword) {
  for (const Block& inner : block.children) {
    if (inner.keyword == keyword) return &inner;
  }
  return nullptr;
}

}  // namespace duet::xcp::host::a2l_syntax
