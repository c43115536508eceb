#include "mdl_syntax.hpp"

#include <algorithm>
#include <optional>
#include <utility>

namespace duet::simulink_import {
namespace {

enum class TokenKind { word, string, array, open, close, end };

struct Token {
  TokenKind kind = TokenKind::end;
  std::string text;  // a word as written, a string chunk with its escapes resolved, an array with its brackets
  int line = 0;
};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }
bool ends_word(char c) { return is_space(c) || c == '{' || c == '}' || c == '"' || c == '[' || c == ']'; }

class Tokenizer {
 public:
  Tokenizer(std::string_view text, const std::string& file) : text_{text}, file_{file} {}

  Result<Token> peek() {
    if (!peeked_) {
      Result<Token> token = read();
      if (!token) return token;
      peeked_ = std::move(token).value();
    }
    return *peeked_;
  }
  Result<Token> next() {
    Result<Token> token = peek();
    peeked_.reset();
    return token;
  }
  [[nodiscard]] Failure failure(int line, const std::string& message) const {
    return mdl_failure(file_, line, message);
  }

 private:
  void skip_space_and_comments() {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '\n') {
        ++line_;
        ++at_;
      } else if (is_space(c)) {
        ++at_;
      } else if (c == '#') {  // a comment runs to the end of its line
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
      } else {
        return;
      }
    }
  }

  Result<Token> read() {
    skip_space_and_comments();
    Token token{.kind = TokenKind::end, .text = {}, .line = line_};
    if (at_ == text_.size()) return token;
    const char c = text_[at_];
    if (c == '{' || c == '}') {
      token.kind = c == '{' ? TokenKind::open : TokenKind::close;
      ++at_;
      return token;
    }
    if (c == '"') return read_string(token);
    if (c == '[') return read_array(token);
    if (c == ']') return failure(line_, "']' without an array it closes");
    token.kind = TokenKind::word;
    const std::size_t start = at_;
    while (at_ < text_.size() && !ends_word(text_[at_])) ++at_;
    token.text = text_.substr(start, at_ - start);
    return token;
  }

  // Strings never span lines in these files: a newline before the closing quote means the quote is missing.
  Result<Token> read_string(Token token) {
    token.kind = TokenKind::string;
    for (++at_; at_ < text_.size() && text_[at_] != '\n'; ++at_) {
      const char c = text_[at_];
      if (c == '"') {
        ++at_;
        return token;
      }
      if (c != '\\' || at_ + 1 == text_.size() || text_[at_ + 1] == '\n') {
        token.text += c;
        continue;
      }
      const char escaped = text_[++at_];
      switch (escaped) {
        case 'n': token.text += '\n'; break;
        case 't': token.text += '\t'; break;
        case '"': token.text += '"'; break;
        case '\\': token.text += '\\'; break;
        default:  // not an escape Simulink writes: kept as it stands, for the importer to judge
          token.text += '\\';
          token.text += escaped;
      }
    }
    return failure(token.line, "string not terminated: '\"' expected before the end of the line");
  }

  Result<Token> read_array(Token token) {
    token.kind = TokenKind::array;
    const std::size_t start = at_;
    while (at_ < text_.size() && text_[at_] != '\n' && text_[at_] != ']') ++at_;
    if (at_ == text_.size() || text_[at_] != ']')
      return failure(token.line, "array not closed: ']' expected before the end of the line");
    ++at_;
    token.text = text_.substr(start, at_ - start);
    return token;
  }

  std::string_view text_;
  const std::string& file_;
  std::size_t at_ = 0;
  int line_ = 1;
  std::optional<Token> peeked_;
};

class Parser {
 public:
  Parser(std::string_view text, const std::string& file) : tokens_{text, file} {}

  // Reads the children of `section` up to its '}' (or the end of the file for the top level).
  Status read_body(MdlNode& section, int depth) {
    if (depth > max_mdl_nesting)
      return tokens_.failure(section.line, "sections nested deeper than " + std::to_string(max_mdl_nesting));
    const bool top_level = depth == 0;
    for (;;) {
      Result<Token> token = tokens_.next();
      if (!token) return Failure{token.error()};
      switch (token.value().kind) {
        case TokenKind::end:
          if (top_level) return done();
          return tokens_.failure(token.value().line, "the file ends inside '" + section.name + "' (line " +
                                                         std::to_string(section.line) + "): '}' expected");
        case TokenKind::close:
          if (!top_level) return done();
          return tokens_.failure(token.value().line, "'}' without a section it closes");
        case TokenKind::open: {
          Status read = read_section(section, {}, token.value().line, depth);
          if (!read) return read;
          break;
        }
        case TokenKind::string:
        case TokenKind::array: {
          Status read = read_value(section, {}, std::move(token).value());
          if (!read) return read;
          break;
        }
        case TokenKind::word: {
          Status read = read_named(section, std::move(token).value(), depth);
          if (!read) return read;
          break;
        }
      }
    }
  }

 private:
  Status read_named(MdlNode& section, const Token& name, int depth) {
    Result<Token> after = tokens_.peek();
    if (!after) return Failure{after.error()};
    const Token& token = after.value();
    if (token.kind == TokenKind::open) {
      (void)tokens_.next();
      return read_section(section, name.text, name.line, depth);
    }
    const bool is_value =
        token.kind == TokenKind::word || token.kind == TokenKind::string || token.kind == TokenKind::array;
    if (!is_value || token.line != name.line)
      return tokens_.failure(name.line, "'" + name.text + "' has neither a value nor a '{' after it on its line");
    Result<Token> value = tokens_.next();
    return read_value(section, name.text, std::move(value).value(), name.line);
  }

  Status read_section(MdlNode& parent, std::string name, int line, int depth) {
    MdlNode section{.name = std::move(name), .is_section = true, .value = {}, .children = {}, .line = line};
    Status read = read_body(section, depth + 1);
    if (!read) return read;
    parent.children.push_back(std::move(section));
    return done();
  }

  // A string value continues with every string chunk that follows it.
  Status read_value(MdlNode& section, std::string name, Token first, int line = 0) {
    MdlNode pair{.name = std::move(name),
                 .is_section = false,
                 .value = std::move(first.text),
                 .children = {},
                 .line = line == 0 ? first.line : line};
    while (first.kind == TokenKind::string) {
      Result<Token> chunk = tokens_.peek();
      if (!chunk) return Failure{chunk.error()};
      if (chunk.value().kind != TokenKind::string) break;
      pair.value += tokens_.next().value().text;
    }
    section.children.push_back(std::move(pair));
    return done();
  }

  Tokenizer tokens_;
};

}  // namespace

const MdlNode* find_pair(const MdlNode& section, std::string_view name) {
  for (const MdlNode& child : section.children)
    if (!child.is_section && child.name == name) return &child;
  return nullptr;
}

std::string pair_value(const MdlNode& section, std::string_view name) {
  const MdlNode* pair = find_pair(section, name);
  return pair ? pair->value : std::string{};
}

Status add_mdl_pairs(const MdlNode& section, std::map<std::string, std::string>& into, const std::string& file,
                     std::initializer_list<std::string_view> skipped) {
  for (const MdlNode& child : section.children) {
    if (child.is_section || child.name.empty()) continue;
    if (std::find(skipped.begin(), skipped.end(), child.name) != skipped.end()) continue;
    if (!into.emplace(child.name, child.value).second)
      return mdl_failure(
          file, child.line,
          "'" + child.name + "' given twice in '" + section.name + "' (line " + std::to_string(section.line) + ")");
  }
  return done();
}

Failure mdl_failure(const std::string& file, int line, const std::string& message) {
  return Failure{file + ":" + std::to_string(line) + ": " + message};
}

Result<MdlNode> parse_mdl_syntax(std::string_view utf8_text, const std::string& file) {
  MdlNode top{.name = {}, .is_section = true, .value = {}, .children = {}, .line = 1};
  Parser parser{utf8_text, file};
  Status read = parser.read_body(top, 0);
  if (!read) return Failure{read.error()};
  return top;
}

}  // namespace duet::simulink_import
