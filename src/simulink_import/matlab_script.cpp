#include "duet/simulink_import/matlab_script.hpp"

#include <array>
#include <cctype>
#include <vector>

#include "matlab_evaluation.hpp"

namespace duet::simulink_import {
namespace {

struct ScriptError {
  std::size_t line;
  std::string problem;
  std::size_t column = 0;  // 0: the whole statement
};

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// `%{` and `%}` alone on their lines enclose a block comment (they nest): its lines become empty, so that the line
// numbers of what follows stay right.
std::string without_block_comments(std::string_view text) {
  std::string result;
  std::vector<std::size_t> open_lines;
  std::size_t line = 1;
  for (std::size_t start = 0; start <= text.size(); ++line) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view content = text.substr(start, end - start);
    if (trimmed(content) == "%{") {
      open_lines.push_back(line);
    } else if (trimmed(content) == "%}" && !open_lines.empty()) {
      open_lines.pop_back();
    } else if (open_lines.empty()) {
      result += content;
    }
    if (end < text.size()) result += '\n';
    start = end + 1;
  }
  if (!open_lines.empty()) throw ScriptError{open_lines.back(), "block comment '%{' is not closed by '%}'"};
  return result;
}

struct Statement {
  std::string_view text;
  std::size_t line;
  std::size_t column;
};

// Statements end at `;`, `,` or a line's end outside brackets and parentheses; comments and continuations stay in
// the text, where the expression's tokenizer skips them.
std::vector<Statement> statements(std::string_view text) {
  std::vector<Statement> result;
  std::size_t line = 1;
  std::size_t column = 1;
  std::size_t start = 0;
  Statement current{{}, 1, 1};
  int depth = 0;
  bool meaningful = false;  // the statement has more than spaces and comments
  const auto finish = [&](std::size_t end) {
    current.text = text.substr(start, end - start);
    if (meaningful) result.push_back(current);
    meaningful = false;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '%' || text.substr(i, 3) == "...") {
      const bool continuation = c == '.';
      while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
      if (continuation && i + 1 < text.size()) {
        ++i;
        ++line;
        column = 0;
      }
    } else if (c == '[' || c == '(' || c == '{') {
      ++depth;
      meaningful = true;
    } else if ((c == ']' || c == ')' || c == '}') && depth > 0) {
      --depth;
    } else if (depth == 0 && (c == ';' || c == ',' || c == '\n')) {
      finish(i);
      start = i + 1;
      current = {{}, c == '\n' ? line + 1 : line, c == '\n' ? 1 : column + 1};
    } else if (c != ' ' && c != '\t' && c != '\r') {
      meaningful = true;
    }
    if (c == '\n' && i < text.size()) {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  finish(text.size());
  return result;
}

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_name_character(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

std::string shortened(std::string_view text) {
  text = trimmed(text);
  const std::size_t end = text.find('\n');
  std::string result{text.substr(0, end)};
  if (result.size() > 40 || end != std::string_view::npos) result = result.substr(0, 40) + "...";
  return result;
}

// The words that open MATLAB's control statements and other statements that are not assignments.
bool is_keyword(std::string_view word) {
  static constexpr std::array<std::string_view, 20> keywords{
      "if",  "elseif", "else",   "end",      "for",   "parfor",   "while",  "switch",     "case", "otherwise",
      "try", "catch",  "return", "function", "break", "continue", "global", "persistent", "spmd", "classdef"};
  for (std::string_view keyword : keywords) {
    if (word == keyword) return true;
  }
  return false;
}

void assign(Workspace& workspace, const std::vector<std::string>& path, Value value, std::size_t line) {
  if (path.size() == 1) {
    workspace[path[0]] = std::move(value);
    return;
  }
  Value& root = workspace.try_emplace(path[0], Value::structure()).first->second;
  Value* target = &root;
  std::string name = path[0];
  for (std::size_t k = 1; k < path.size(); ++k) {
    if (!target->is_struct) {
      throw ScriptError{line, "'" + name + "' is not a struct, so '" + name + "." + path[k] + "' cannot be assigned"};
    }
    if (k + 1 == path.size()) {
      target->set_field(path[k], std::move(value));
      return;
    }
    if (target->field(path[k]) == nullptr) target->set_field(path[k], Value::structure());
    target = target->field(path[k]);
    name += "." + path[k];
  }
}

void run(const Statement& statement, Workspace& workspace) {
  const std::string_view text = statement.text;
  std::size_t i = text.find_first_not_of(" \t\r");
  std::vector<std::string> path;
  while (i < text.size() && is_name_start(text[i])) {
    const std::size_t start = i;
    while (i < text.size() && is_name_character(text[i])) ++i;
    path.emplace_back(text.substr(start, i - start));
    if (path.size() == 1 && is_keyword(path[0])) {
      throw ScriptError{statement.line, "'" + path[0] + "' is not supported: only assignments 'name = value'"};
    }
    if (i < text.size() && text[i] == '.' && i + 1 < text.size() && is_name_start(text[i + 1])) {
      ++i;
    } else {
      break;
    }
  }
  while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
  const bool assignment = !path.empty() && i < text.size() && text[i] == '=' && text.substr(i, 2) != "==";
  if (!assignment) {
    if (!path.empty() && i < text.size() && text[i] == '(' && text.find('=') != std::string_view::npos) {
      throw ScriptError{statement.line, "indexed assignment '" + shortened(text) + "' is not supported"};
    }
    throw ScriptError{statement.line,
                      "'" + shortened(text) + "' is not an assignment; only assignments 'name = value' are supported"};
  }
  const std::string_view expression = text.substr(i + 1);
  const std::size_t expression_column = statement.column + i + 1;
  try {
    assign(workspace, path, evaluate_or_throw(expression, workspace), statement.line);
  } catch (const EvaluationError& error) {
    const bool first_line = error.position.line == 1;
    throw ScriptError{statement.line + error.position.line - 1, error.problem,
                      first_line ? expression_column + error.position.column - 1 : error.position.column};
  }
}

}  // namespace

Result<Workspace> read_m_script(std::string_view text, const std::string& file, Workspace start) {
  try {
    const std::string prepared = without_block_comments(text);
    for (const Statement& statement : statements(prepared)) run(statement, start);
    return start;
  } catch (const ScriptError& error) {
    const std::string column = error.column == 0 ? "" : ":" + std::to_string(error.column);
    return Failure{file + ":" + std::to_string(error.line) + column + ": " + error.problem};
  }
}

}  // namespace duet::simulink_import
