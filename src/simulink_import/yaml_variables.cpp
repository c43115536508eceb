#include "duet/simulink_import/yaml_variables.hpp"

#include <yaml-cpp/yaml.h>

#include <cctype>
#include <set>

#include "duet/support/text_file.hpp"

namespace duet::simulink_import {
namespace {

struct Problem {
  YAML::Mark mark;
  std::string what;
};

[[noreturn]] void fail(const YAML::Node& node, const std::string& what) { throw Problem{node.Mark(), what}; }

bool is_name(const std::string& text) {
  if (text.empty() || std::isalpha(static_cast<unsigned char>(text[0])) == 0) return false;
  for (char c : text) {
    if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '_') return false;
  }
  return true;
}

double number(const YAML::Node& node, const std::string& name) {
  double value = 0.0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, value)) {
    fail(node,
         "'" + name + "' holds '" + (node.IsScalar() ? node.Scalar() : std::string{"a list"}) + "', not a number");
  }
  return value;
}

Value value_of(const YAML::Node& node, const std::string& name, int depth);

Value structure(const YAML::Node& node, const std::string& name, int depth) {
  Value result = Value::structure();
  std::set<std::string> seen;
  for (const auto& entry : node) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : std::string{};
    if (!is_name(key)) fail(entry.first, "'" + key + "' is not a MATLAB name (letters, digits and _, first a letter)");
    if (!seen.insert(key).second) fail(entry.first, "'" + key + "' is given twice");
    const std::string path = name.empty() ? key : name + "." + key;
    result.set_field(key, value_of(entry.second, path, depth + 1));
  }
  return result;
}

// A list of numbers is a row vector, a list of lists a matrix, row by row.
Value matrix(const YAML::Node& node, const std::string& name) {
  if (node.size() == 0) return Value::matrix(0, 0, {});
  if (!node[0].IsSequence()) {
    std::vector<double> row;
    for (const YAML::Node& element : node) row.push_back(number(element, name));
    const std::size_t columns = row.size();
    return Value::matrix(1, columns, std::move(row));
  }
  const std::size_t columns = node[0].size();
  std::vector<double> elements;
  for (const YAML::Node& row : node) {
    if (!row.IsSequence()) fail(row, "'" + name + "' mixes numbers and lists of numbers");
    if (row.size() != columns) {
      fail(row, "the rows of '" + name + "' have different lengths (" + std::to_string(columns) + " and " +
                    std::to_string(row.size()) + ")");
    }
    for (const YAML::Node& element : row) elements.push_back(number(element, name));
  }
  return Value::matrix(node.size(), columns, std::move(elements));
}

Value value_of(const YAML::Node& node, const std::string& name, int depth) {
  if (depth > 100) fail(node, "'" + name + "' nests structs deeper than 100 levels");
  if (node.IsMap()) return structure(node, name, depth);
  if (node.IsSequence()) return matrix(node, name);
  if (node.IsNull()) fail(node, "'" + name + "' has no value");
  return Value::scalar(number(node, name));
}

}  // namespace

Result<Workspace> read_variables_yaml(const std::string& file) {
  const Result<std::string> text = read_text_file(file);
  if (!text) return Failure{text.error()};
  try {
    const YAML::Node root = YAML::Load(text.value());
    Workspace workspace;
    if (root.IsNull()) return workspace;
    if (!root.IsMap()) fail(root, "expected a mapping of variable names to values");
    for (Field& variable : structure(root, "", 0).fields) workspace[variable.name] = std::move(variable.value);
    return workspace;
  } catch (const Problem& problem) {
    return Failure{file + ":" + std::to_string(problem.mark.line + 1) + ": " + problem.what};
  } catch (const YAML::Exception& error) {
    return Failure{file + ":" + std::to_string(error.mark.line + 1) + ": " + error.msg};
  }
}

}  // namespace duet::simulink_import
