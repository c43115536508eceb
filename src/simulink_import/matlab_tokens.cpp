#include "matlab_tokens.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <limits>

namespace duet::simulink_import {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_name_character(char c) { return is_letter(c) || is_digit(c) || c == '_'; }

class Tokenizer {
 public:
  explicit Tokenizer(std::string_view text) : text_(text) {}

  std::vector<Token> run() {
    std::vector<Token> tokens;
    bool space = false;
    while (offset_ < text_.size()) {
      const char c = text_[offset_];
      if (c == ' ' || c == '\t' || c == '\r') {
        advance(1);
        space = true;
      } else if (c == '%') {
        while (offset_ < text_.size() && text_[offset_] != '\n') advance(1);
      } else if (text_.substr(offset_, 3) == "...") {  // continuation: the rest of the line is a comment
        while (offset_ < text_.size() && text_[offset_] != '\n') advance(1);
        if (offset_ < text_.size()) newline();
        space = true;
      } else {
        Token token = next(c, tokens, space);
        token.space_before = space;
        space = false;
        tokens.push_back(token);
      }
    }
    Token end;
    end.position = here();
    tokens.push_back(end);
    return tokens;
  }

 private:
  Token next(char c, const std::vector<Token>& before, bool space_before) {
    Token token;
    token.position = here();
    const std::size_t start = offset_;
    if (c == '\n') {
      token.kind = Token::Kind::newline;
      newline();
    } else if (is_digit(c) || (c == '.' && offset_ + 1 < text_.size() && is_digit(text_[offset_ + 1]))) {
      token.kind = Token::Kind::number;
      token.number = number(token.position);
    } else if (is_letter(c)) {
      token.kind = Token::Kind::name;
      while (offset_ < text_.size() && is_name_character(text_[offset_])) advance(1);
    } else if (c == '\'') {
      if (space_before || !ends_operand(before)) {
        throw EvaluationError{token.position, "character strings ('...') are not supported"};
      }
      token.kind = Token::Kind::symbol;
      advance(1);
    } else {
      token.kind = Token::Kind::symbol;
      advance(symbol_length(token.position));
    }
    token.text = text_.substr(start, offset_ - start);
    return token;
  }

  // A quote right after (without space) a name, number, closing bracket or transpose is a transpose; elsewhere it
  // opens a string.
  static bool ends_operand(const std::vector<Token>& before) {
    if (before.empty()) return false;
    const Token& last = before.back();
    return last.kind == Token::Kind::number || last.kind == Token::Kind::name || last.text == ")" || last.text == "]" ||
           last.text == "'" || last.text == ".'";
  }

  std::size_t symbol_length(TextPosition where) const {
    static constexpr std::array<std::string_view, 4> two_characters{".*", "./", ".^", ".'"};
    static constexpr std::array<std::string_view, 7> refused{"==", "~=", "<=", ">=", "&&", "||", ".\\"};
    const std::string_view pair = text_.substr(offset_, 2);
    for (std::string_view op : refused) {
      if (pair == op) throw EvaluationError{where, "operator '" + std::string{op} + "' is not supported"};
    }
    for (std::string_view op : two_characters) {
      if (pair == op) return 2;
    }
    const char c = text_[offset_];
    if (std::string_view{"+-*/^()[],;:.="}.find(c) != std::string_view::npos) return 1;
    if (std::string_view{"<>&|~\\!"}.find(c) != std::string_view::npos) {
      throw EvaluationError{where, "operator '" + std::string(1, c) + "' is not supported"};
    }
    if (c == '"') throw EvaluationError{where, "character strings (\"...\") are not supported"};
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte >= 0x7f) throw EvaluationError{where, "unexpected byte " + std::to_string(byte)};
    throw EvaluationError{where, "unexpected character '" + std::string(1, c) + "'"};
  }

  // Digits with an optional fraction and exponent. `1.*x` is 1 .* x, as in MATLAB: the dot of an operator stays.
  double number(TextPosition where) {
    const std::size_t start = offset_;
    while (offset_ < text_.size() && is_digit(text_[offset_])) advance(1);
    if (offset_ < text_.size() && text_[offset_] == '.' &&
        !(offset_ + 1 < text_.size() &&
          std::string_view{"*/^'\\"}.find(text_[offset_ + 1]) != std::string_view::npos)) {
      advance(1);
      while (offset_ < text_.size() && is_digit(text_[offset_])) advance(1);
    }
    bool negative_exponent = false;
    if (offset_ < text_.size() && (text_[offset_] == 'e' || text_[offset_] == 'E')) {
      std::size_t look = offset_ + 1;
      if (look < text_.size() && (text_[look] == '+' || text_[look] == '-')) {
        negative_exponent = text_[look] == '-';
        ++look;
      }
      if (look < text_.size() && is_digit(text_[look])) {
        advance(look - offset_);
        while (offset_ < text_.size() && is_digit(text_[offset_])) advance(1);
      }
    }
    const std::string_view written = text_.substr(start, offset_ - start);
    if (offset_ < text_.size() && is_name_character(text_[offset_])) {
      std::size_t end = offset_;
      while (end < text_.size() && is_name_character(text_[end])) ++end;
      const std::string whole{text_.substr(start, end - start)};
      if (end == offset_ + 1 && (text_[offset_] == 'i' || text_[offset_] == 'j')) {
        throw EvaluationError{where, "complex numbers ('" + whole + "') are not supported"};
      }
      throw EvaluationError{where, "malformed number '" + whole + "'"};
    }
    double value = 0.0;
    const auto [rest, problem] = std::from_chars(written.data(), written.data() + written.size(), value);
    if (problem == std::errc::result_out_of_range) {  // MATLAB reads such numbers as Inf or 0
      return negative_exponent ? 0.0 : std::numeric_limits<double>::infinity();
    }
    if (problem != std::errc{} || rest != written.data() + written.size()) {
      throw EvaluationError{where, "malformed number '" + std::string{written} + "'"};
    }
    return value;
  }

  TextPosition here() const { return {line_, column_}; }
  void advance(std::size_t count) {
    offset_ += count;
    column_ += count;
  }
  void newline() {
    ++offset_;
    ++line_;
    column_ = 1;
  }

  std::string_view text_;
  std::size_t offset_ = 0;
  std::size_t line_ = 1;
  std::size_t column_ = 1;
};

}  // namespace

std::vector<Token> tokenize(std::string_view text) { return Tokenizer{text}.run(); }

}  // namespace duet::simulink_import
