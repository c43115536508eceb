// The A2L checker: the keyword table (a2l_rules.hpp) checks each block's shape; then, per MODULE, the rules that span
// blocks: unique names, references, addresses in memory segments, the EPK, and the XCP IF_DATA's numbers.

#include "duet/xcp/host/a2l_check.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "a2l_rules.hpp"
#include "a2l_syntax.hpp"
#include "duet/support/text_file.hpp"

namespace duet::xcp::host {
namespace {

using a2l_rules::BlockRule;
using a2l_rules::Field;
using a2l_rules::Type;
using a2l_syntax::after;
using a2l_syntax::Block;
using a2l_syntax::child;
using a2l_syntax::Place;
using a2l_syntax::Token;

constexpr std::size_t max_identifier_length = 1024;

std::optional<std::int64_t> parse_whole(std::string_view text) {
  bool negative = false;
  if (text.starts_with('-') || text.starts_with('+')) {
    negative = text.front() == '-';
    text.remove_prefix(1);
  }
  int base = 10;
  if (text.starts_with("0x") || text.starts_with("0X")) {
    text.remove_prefix(2);
    base = 16;
  }
  std::uint64_t value = 0;
  const auto [end, problem] = std::from_chars(text.data(), text.data() + text.size(), value, base);
  if (text.empty() || problem != std::errc{} || end != text.data() + text.size() || value > 0x7FFF'FFFF'FFFF'FFFFULL)
    return std::nullopt;
  return negative ? -static_cast<std::int64_t>(value) : static_cast<std::int64_t>(value);
}

std::optional<double> parse_number(const std::string& text) {
  if (const auto whole = parse_whole(text)) return static_cast<double>(*whole);
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) return std::nullopt;
  return value;
}

bool is_identifier(std::string_view text) {
  if (text.empty() || text.size() > max_identifier_length) return false;
  auto letter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; };
  if (!letter(text.front())) return false;
  return std::all_of(text.begin(), text.end(), [&letter](char c) {
    return letter(c) || (c >= '0' && c <= '9') || c == '.' || c == '[' || c == ']';
  });
}

// "%Length.Layout": the width of the whole number and the digits after the point.
bool is_format(std::string_view text) {
  if (!text.starts_with('%')) return false;
  text.remove_prefix(1);
  const std::size_t point = text.find('.');
  if (point == 0 || point == std::string_view::npos || point + 1 == text.size()) return false;
  return std::all_of(text.begin(), text.end(), [](char c) { return c == '.' || (c >= '0' && c <= '9'); }) &&
         text.find('.', point + 1) == std::string_view::npos;
}

// The values a data type holds (the largest finite ones for floats).
std::pair<double, double> range_of_datatype(std::string_view type) {
  static const std::map<std::string_view, std::pair<double, double>> ranges{
      {"UBYTE", {0, 255}},
      {"SBYTE", {-128, 127}},
      {"UWORD", {0, 65535}},
      {"SWORD", {-32768, 32767}},
      {"ULONG", {0, 4294967295.0}},
      {"SLONG", {-2147483648.0, 2147483647.0}},
      {"A_UINT64", {0, 18446744073709551615.0}},
      {"A_INT64", {-9223372036854775808.0, 9223372036854775807.0}},
      {"FLOAT16_IEEE", {-65504, 65504}},
      {"FLOAT32_IEEE", {-3.4028234663852886e38, 3.4028234663852886e38}}};
  const auto found = ranges.find(type);
  return found != ranges.end() ? found->second : std::pair{-1.7976931348623157e308, 1.7976931348623157e308};
}

std::size_t size_of_datatype(std::string_view type) {
  if (type == "UBYTE" || type == "SBYTE") return 1;
  if (type == "UWORD" || type == "SWORD" || type == "FLOAT16_IEEE") return 2;
  if (type == "A_UINT64" || type == "A_INT64" || type == "FLOAT64_IEEE") return 8;
  return 4;
}

// The names one MODULE defines, per namespace: MEASUREMENT, CHARACTERISTIC, AXIS_PTS and INSTANCE share one.
struct Definition {
  std::string kind;  // the keyword that defined it
  const Block* block = nullptr;
};

std::string namespace_of(std::string_view keyword) {
  if (keyword == "MEASUREMENT" || keyword == "CHARACTERISTIC" || keyword == "AXIS_PTS" || keyword == "INSTANCE")
    return "object";
  if (keyword == "COMPU_TAB" || keyword == "COMPU_VTAB" || keyword == "COMPU_VTAB_RANGE") return "table";
  if (keyword.starts_with("TYPEDEF_")) return "typedef";
  return std::string{keyword};
}

struct Problem {
  A2lProblem::Severity severity;
  Place place;
  std::string message;
};

class Checker {
 public:
  explicit Checker(const a2l_syntax::Tree& tree) : tree_(tree) {}

  std::vector<A2lProblem> check() {
    check_values(tree_.root, a2l_rules::file_rule());
    const Token* version = after(tree_.root, "ASAP2_VERSION");
    if (version == nullptr) {
      error(tree_.root.values.empty() ? Place{} : tree_.root.values.front().place, "ASAP2_VERSION is missing");
    }
    check_children(tree_.root, "");
    const Block* project = child(tree_.root, "PROJECT");
    if (project == nullptr) {
      error(Place{}, "no /begin PROJECT");
    } else {
      if (child(*project, "MODULE") == nullptr) error(project->place, "PROJECT has no MODULE");
      for (const Block& module : project->children) {
        if (module.keyword == "MODULE") check_module(module);
      }
    }
    std::stable_sort(problems_.begin(), problems_.end(), [](const Problem& left, const Problem& right) {
      return std::tie(left.place.file, left.place.line, left.place.column) <
             std::tie(right.place.file, right.place.line, right.place.column);
    });
    std::vector<A2lProblem> result;
    for (const Problem& problem : problems_)
      result.push_back({problem.severity, tree_.where(problem.place), problem.message});
    return result;
  }

 private:
  void error(const Place& place, std::string message) {
    problems_.push_back({A2lProblem::Severity::error, place, std::move(message)});
  }
  void warning(const Place& place, std::string message) {
    problems_.push_back({A2lProblem::Severity::warning, place, std::move(message)});
  }

  // ---- The shape of each block, from the keyword table.

  // The blocks inside `owner`, whose keyword (IF_DATA: with the interface's name) is `key`.
  void check_children(const Block& owner, const std::string& key) {
    const std::string where = key.empty() ? "the file's top" : key;
    for (const Block& block : owner.children) {
      bool known = false;
      const BlockRule* rule = a2l_rules::rule_for(block.keyword, key, known);
      if (rule == nullptr) {
        if (known) {
          error(block.place, block.keyword + " is not allowed in " + where);
        } else {
          warning(block.place, "unknown keyword " + block.keyword + " in " + where + " (not checked)");
        }
        continue;
      }
      if (rule->once) {
        const auto first = std::find_if(owner.children.begin(), owner.children.end(),
                                        [&block](const Block& other) { return other.keyword == block.keyword; });
        if (&*first != &block) {
          error(block.place, block.keyword + " appears twice in " + where + " (first at line " +
                                 std::to_string(first->place.line) + ")");
        }
      }
      if (rule->unchecked) continue;
      if (block.keyword == "IF_DATA") {
        check_if_data(block);
        continue;
      }
      check_values(block, *rule);
      check_children(block, block.keyword);
    }
  }

  // IF_DATA XCP (and XCPplus, with its version) is checked; another tool's IF_DATA is its own business.
  void check_if_data(const Block& block) {
    const std::string& name = block.values.empty() ? std::string{} : block.values[0].value;
    if (name != "XCP" && name != "XCPplus") {
      if (block.values.empty()) {
        error(block.place, "IF_DATA: the name of the interface is missing");
      } else if (unchecked_interfaces_.insert(name).second) {
        warning(block.values[0].place, "IF_DATA " + name + " is not checked");
      }
      return;
    }
    const std::size_t expected = name == "XCPplus" ? 2 : 1;
    if (block.values.size() > expected) {
      error(block.values[expected].place, "IF_DATA " + name + ": unexpected '" + block.values[expected].value + "'");
    }
    if (name == "XCPplus" && block.values.size() < 2) error(block.place, "IF_DATA XCPplus: its version is missing");
    check_children(block, "IF_DATA " + name);
  }

  // Whether a token could be the first value of a group of this type (to know where repetitions end).
  static bool looks_like(const Token& token, const Type& type) {
    switch (type.kind) {
      case Type::Kind::identifier: return token.kind == Token::Kind::word && !parse_number(token.value);
      case Type::Kind::text: return token.kind == Token::Kind::text;
      case Type::Kind::number:
      case Type::Kind::whole: return token.kind == Token::Kind::word && parse_number(token.value).has_value();
      case Type::Kind::keyword:
        return token.kind == Token::Kind::word &&
               std::find(type.keywords->begin(), type.keywords->end(), token.value) != type.keywords->end();
    }
    return false;
  }

  void check_value(const Token& token, const Type& type, const std::string& owner, const std::string& label) {
    const std::string what = owner + ": " + label + ": '" + token.value + "'";
    switch (type.kind) {
      case Type::Kind::identifier:
        if (token.kind != Token::Kind::word || !is_identifier(token.value)) {
          error(token.place,
                what + " is not an identifier (a letter or _, then letters, digits, _ . [ ], at most 1024)");
        }
        return;
      case Type::Kind::text:
        if (token.kind != Token::Kind::text) {
          error(token.place, what + " is not a \"text\"");
        } else if (type.max_length != 0 && token.value.size() > type.max_length) {
          error(token.place, what + " is longer than " + std::to_string(type.max_length) + " characters");
        }
        return;
      case Type::Kind::number:
        if (token.kind != Token::Kind::word || !parse_number(token.value))
          error(token.place, what + " is not a number");
        return;
      case Type::Kind::whole: {
        const auto value = token.kind == Token::Kind::word ? parse_whole(token.value) : std::nullopt;
        if (!value) {
          error(token.place, what + " is not a whole number");
        } else if (*value < type.minimum || *value > type.maximum) {
          error(token.place, what + " is outside " + type.name + " (" + std::to_string(type.minimum) + " to " +
                                 std::to_string(type.maximum) + ")");
        }
        return;
      }
      case Type::Kind::keyword:
        if (!looks_like(token, type)) {
          std::string choices;
          for (const std::string& keyword : *type.keywords) choices += (choices.empty() ? "" : ", ") + keyword;
          error(token.place, what + " is not one of " + choices);
        }
        return;
    }
  }

  // Checks fields from `at` on; returns where they end, or nothing when a value is missing (reported).
  std::optional<std::size_t> check_fields(const Block& block, const std::vector<Field>& fields, std::size_t at,
                                          const std::string& owner, const BlockRule& rule,
                                          std::vector<std::size_t>* repetitions) {
    const std::vector<Token>& values = block.values;
    for (const Field& field : fields) {
      if (field.repeated) {
        std::size_t count = 0;
        while (at < values.size() && looks_like(values[at], field.group.front()) &&
               !(values[at].kind == Token::Kind::word && rule.items.contains(values[at].value))) {
          for (std::size_t member = 0; member < field.group.size(); ++member, ++at) {
            if (at >= values.size()) {
              error(block.place, owner + ": " + field.label + " is missing its last values");
              return std::nullopt;
            }
            check_value(values[at], field.group[member], owner, field.label);
          }
          ++count;
        }
        if (field.at_least_one && count == 0) {
          error(at < values.size() ? values[at].place : block.place, owner + ": " + field.label + " is missing");
        }
        if (repetitions != nullptr) repetitions->push_back(count);
        continue;
      }
      for (const Type& type : field.group) {
        if (at >= values.size()) {
          error(block.place, owner + ": " + field.label + " (" + type.name + ") is missing");
          return std::nullopt;
        }
        check_value(values[at++], type, owner, field.label);
      }
    }
    return at;
  }

  void check_values(const Block& block, const BlockRule& rule) {
    const std::string owner = block.keyword.empty() ? "the file" : block.keyword;
    std::vector<std::size_t> repetitions;
    auto at = check_fields(block, rule.fields, 0, owner, rule, &repetitions);
    if (!at) return;
    check_table_size(block, rule, repetitions);
    std::map<std::string, const Token*, std::less<>> seen;
    const std::vector<Token>& values = block.values;
    while (*at < values.size()) {
      const Token& token = values[*at];
      const auto item = token.kind == Token::Kind::word ? rule.items.find(token.value) : rule.items.end();
      if (item == rule.items.end()) {
        if (token.kind == Token::Kind::word && !parse_number(token.value) && is_identifier(token.value)) {
          warning(token.place, "unknown keyword " + token.value + " in " + owner + " (not checked)");
          ++*at;
          while (*at < values.size() &&
                 !(values[*at].kind == Token::Kind::word && rule.items.contains(values[*at].value))) {
            ++*at;
          }
        } else {
          error(token.place, owner + ": unexpected '" + token.value + "'");
          ++*at;
        }
        continue;
      }
      if (const auto [first, inserted] = seen.emplace(token.value, &token); !inserted && !item->second.repeatable) {
        error(token.place, owner + ": " + token.value + " appears twice (first at line " +
                               std::to_string(first->second->place.line) + ")");
      }
      at = check_fields(block, item->second.fields, *at + 1, owner + " " + token.value, rule, nullptr);
      if (!at) return;
    }
  }

  // COMPU_TAB, COMPU_VTAB and COMPU_VTAB_RANGE say how many pairs (triples) follow.
  void check_table_size(const Block& block, const BlockRule& rule, const std::vector<std::size_t>& repetitions) {
    for (std::size_t index = 0; index < rule.fields.size(); ++index) {
      if (!rule.fields[index].label.starts_with("NumberValue") || repetitions.empty()) continue;
      const auto declared = parse_whole(block.values[index].value);
      if (declared && static_cast<std::size_t>(*declared) != repetitions.front()) {
        error(block.values[index].place, block.keyword + ": " + rule.fields[index].label + " is " +
                                             block.values[index].value + " but " + std::to_string(repetitions.front()) +
                                             " follow");
      }
    }
  }

  // ---- The rules that span blocks, per MODULE.

  void check_module(const Block& module) {
    definitions_.clear();
    for (const Block& block : module.children) define(block);
    if (const Block* parameters = child(module, "MOD_PAR")) {
      for (const Block& segment : parameters->children) {
        if (segment.keyword == "MEMORY_SEGMENT") define(segment);
      }
    }
    for (const Block& block : module.children) check_references(block);
    check_memory(module);
    for (const Block& block : module.children) {
      if (block.keyword == "IF_DATA" && !block.values.empty() &&
          (block.values[0].value == "XCP" || block.values[0].value == "XCPplus")) {
        check_xcp(module, block);
      }
    }
  }

  void define(const Block& block) {
    static const std::set<std::string, std::less<>> named{"MEASUREMENT",
                                                          "CHARACTERISTIC",
                                                          "AXIS_PTS",
                                                          "INSTANCE",
                                                          "COMPU_METHOD",
                                                          "COMPU_TAB",
                                                          "COMPU_VTAB",
                                                          "COMPU_VTAB_RANGE",
                                                          "RECORD_LAYOUT",
                                                          "UNIT",
                                                          "GROUP",
                                                          "FUNCTION",
                                                          "TYPEDEF_STRUCTURE",
                                                          "TYPEDEF_MEASUREMENT",
                                                          "TYPEDEF_CHARACTERISTIC",
                                                          "TYPEDEF_AXIS",
                                                          "TYPEDEF_BLOB",
                                                          "MEMORY_SEGMENT"};
    if (!named.contains(block.keyword) || block.values.empty()) return;
    const Token& name = block.values[0];
    auto& names = definitions_[namespace_of(block.keyword)];
    const auto [first, inserted] = names.emplace(name.value, Definition{block.keyword, &block});
    if (!inserted) {
      error(name.place, block.keyword + " '" + name.value + "': the name is taken by the " + first->second.kind +
                            " at line " + std::to_string(first->second.block->place.line));
    }
  }

  const Definition* find(const std::string& space, const std::string& name) {
    const auto names = definitions_.find(space);
    if (names == definitions_.end()) return nullptr;
    const auto found = names->second.find(name);
    return found == names->second.end() ? nullptr : &found->second;
  }

  // `token` names a definition of one of `kinds` (the first kind's namespace), or one of `also` (NO_COMPU_METHOD ...).
  void expect(const Block& block, const Token* token, const std::vector<std::string_view>& kinds,
              std::string_view also = {}) {
    if (token == nullptr || (!also.empty() && token->value == also)) return;
    const Definition* found = find(namespace_of(kinds.front()), token->value);
    // A member of an INSTANCE of a structure ("instance.component") stands for the object it expands to.
    if (found == nullptr && namespace_of(kinds.front()) == "object") {
      const std::size_t dot = token->value.find('.');
      const Definition* instance = dot == std::string::npos ? nullptr : find("object", token->value.substr(0, dot));
      if (instance != nullptr && instance->kind == "INSTANCE") return;
    }
    std::string wanted;
    for (std::string_view kind : kinds) wanted += std::string{wanted.empty() ? "" : " or "} + std::string{kind};
    if (found == nullptr) {
      error(token->place, owner(block) + ": no " + wanted + " named '" + token->value + "'");
    } else if (std::find(kinds.begin(), kinds.end(), found->kind) == kinds.end() && found->kind != "INSTANCE") {
      error(token->place, owner(block) + ": '" + token->value + "' is a " + found->kind + ", not a " + wanted);
    }
  }

  // "MEASUREMENT 'speed'" for a block with a name of its own, else its keyword.
  static std::string owner(const Block& block) {
    static const std::set<std::string, std::less<>> named{"MEASUREMENT",
                                                          "CHARACTERISTIC",
                                                          "AXIS_PTS",
                                                          "INSTANCE",
                                                          "COMPU_METHOD",
                                                          "UNIT",
                                                          "TYPEDEF_MEASUREMENT",
                                                          "TYPEDEF_CHARACTERISTIC",
                                                          "TYPEDEF_AXIS",
                                                          "STRUCTURE_COMPONENT",
                                                          "GROUP",
                                                          "FUNCTION"};
    if (!named.contains(block.keyword) || block.values.empty()) return block.keyword;
    return block.keyword + " '" + block.values[0].value + "'";
  }

  static const Token* value_at(const Block& block, std::size_t index) {
    return index < block.values.size() ? &block.values[index] : nullptr;
  }

  // The value `offset` places after `keyword` (FNC_VALUES 1 UWORD: the data type is 2 after it).
  static const Token* value_after(const Block& block, std::string_view keyword, std::size_t offset) {
    for (std::size_t index = 0; index + offset < block.values.size(); ++index) {
      if (block.values[index].value == keyword) return &block.values[index + offset];
    }
    return nullptr;
  }

  void check_format(const Block& block, const Token* format) {
    if (format != nullptr && format->kind == Token::Kind::text && !is_format(format->value)) {
      error(format->place, block.keyword + ": the format '" + format->value +
                               "' is not %Length.Layout (e.g. %8.3: 8 characters, 3 after the point)");
    }
  }

  void check_references(const Block& block) {
    const std::string& keyword = block.keyword;
    const std::vector<std::string_view> conversion{"COMPU_METHOD"};
    const std::vector<std::string_view> layout{"RECORD_LAYOUT"};
    const std::vector<std::string_view> measurement{"MEASUREMENT"};
    check_format(block, after(block, "FORMAT"));
    if (const Token* segment = after(block, "REF_MEMORY_SEGMENT")) expect(block, segment, {"MEMORY_SEGMENT"});
    if (keyword == "MEASUREMENT" || keyword == "TYPEDEF_MEASUREMENT") {
      expect(block, value_at(block, 3), conversion, "NO_COMPU_METHOD");
      check_limits(block, value_at(block, 2), value_at(block, 3), 6);
    } else if (keyword == "CHARACTERISTIC" || keyword == "TYPEDEF_CHARACTERISTIC") {
      const std::size_t shift = keyword == "CHARACTERISTIC" ? 0 : 1;
      expect(block, value_at(block, 4 - shift), layout);
      expect(block, value_at(block, 6 - shift), conversion, "NO_COMPU_METHOD");
      check_characteristic_shape(block);
      const Definition* record =
          block.values.size() > 4 - shift ? find("RECORD_LAYOUT", block.values[4 - shift].value) : nullptr;
      if (record != nullptr)
        check_limits(block, value_after(*record->block, "FNC_VALUES", 2), value_at(block, 6 - shift), 7 - shift);
      for (const Block& axis : block.children) {
        if (axis.keyword != "AXIS_DESCR") continue;
        expect(axis, value_at(axis, 1), measurement, "NO_INPUT_QUANTITY");
        expect(axis, value_at(axis, 2), conversion, "NO_COMPU_METHOD");
        expect(axis, after(axis, "AXIS_PTS_REF"), {"AXIS_PTS"});
        expect(axis, after(axis, "CURVE_AXIS_REF"), {"CHARACTERISTIC"});
        check_format(axis, after(axis, "FORMAT"));
      }
    } else if (keyword == "AXIS_PTS" || keyword == "TYPEDEF_AXIS") {
      const std::size_t shift = keyword == "AXIS_PTS" ? 0 : 1;
      expect(block, value_at(block, 3 - shift), measurement, "NO_INPUT_QUANTITY");
      expect(block, value_at(block, 4 - shift), layout);
      expect(block, value_at(block, 6 - shift), conversion, "NO_COMPU_METHOD");
    } else if (keyword == "COMPU_METHOD") {
      check_compu_method(block);
    } else if (keyword == "UNIT") {
      expect(block, after(block, "REF_UNIT"), {"UNIT"});
    } else if (keyword == "INSTANCE") {
      expect(block, value_at(block, 2),
             {"TYPEDEF_STRUCTURE", "TYPEDEF_MEASUREMENT", "TYPEDEF_CHARACTERISTIC", "TYPEDEF_AXIS", "TYPEDEF_BLOB"});
    } else if (keyword == "TYPEDEF_STRUCTURE") {
      for (const Block& component : block.children) {
        if (component.keyword == "STRUCTURE_COMPONENT") {
          expect(
              component, value_at(component, 1),
              {"TYPEDEF_STRUCTURE", "TYPEDEF_MEASUREMENT", "TYPEDEF_CHARACTERISTIC", "TYPEDEF_AXIS", "TYPEDEF_BLOB"});
        }
      }
    } else if (keyword == "GROUP" || keyword == "FUNCTION") {
      check_members(block);
    }
  }

  // LowerLimit <= UpperLimit (at `lower` and the value after it), and for a value read as it is stored
  // (NO_COMPU_METHOD, IDENTICAL), both within what its data type holds.
  void check_limits(const Block& block, const Token* type, const Token* conversion, std::size_t lower) {
    const Token* low = value_at(block, lower);
    const Token* high = value_at(block, lower + 1);
    const auto minimum = low != nullptr ? parse_number(low->value) : std::nullopt;
    const auto maximum = high != nullptr ? parse_number(high->value) : std::nullopt;
    if (!minimum || !maximum) return;
    if (*minimum > *maximum) {
      error(low->place, owner(block) + ": LowerLimit " + low->value + " is above UpperLimit " + high->value);
      return;
    }
    if (type == nullptr || conversion == nullptr) return;
    const Definition* method = find("COMPU_METHOD", conversion->value);
    const bool identical =
        conversion->value == "NO_COMPU_METHOD" ||
        (method != nullptr && method->block->values.size() > 2 && method->block->values[2].value == "IDENTICAL");
    const auto [smallest, largest] = range_of_datatype(type->value);
    if (identical && (*minimum < smallest || *maximum > largest)) {
      error(*minimum < smallest ? low->place : high->place, owner(block) + ": the limits " + low->value + " to " +
                                                                high->value + " are outside what " + type->value +
                                                                " holds");
    }
  }

  void check_members(const Block& block) {
    static const std::map<std::string_view, std::vector<std::string_view>> members{
        {"REF_MEASUREMENT", {"MEASUREMENT"}},
        {"REF_CHARACTERISTIC", {"CHARACTERISTIC", "AXIS_PTS"}},
        {"DEF_CHARACTERISTIC", {"CHARACTERISTIC", "AXIS_PTS"}},
        {"IN_MEASUREMENT", {"MEASUREMENT"}},
        {"OUT_MEASUREMENT", {"MEASUREMENT"}},
        {"LOC_MEASUREMENT", {"MEASUREMENT"}},
        {"SUB_GROUP", {"GROUP"}},
        {"SUB_FUNCTION", {"FUNCTION"}},
        {"FUNCTION_LIST", {"FUNCTION"}}};
    for (const Block& list : block.children) {
      const auto kinds = members.find(list.keyword);
      if (kinds == members.end()) continue;
      for (const Token& name : list.values) expect(list, &name, kinds->second);
    }
  }

  // CURVE has one axis, MAP two, ...; VAL_BLK and ASCII say how many values; the layout has the values (FNC_VALUES).
  void check_characteristic_shape(const Block& block) {
    const Token* type = value_at(block, 2);
    if (type == nullptr) return;
    static const std::map<std::string_view, std::size_t> axes{{"VALUE", 0},  {"VAL_BLK", 0}, {"ASCII", 0},
                                                              {"CURVE", 1},  {"MAP", 2},     {"CUBOID", 3},
                                                              {"CUBE_4", 4}, {"CUBE_5", 5}};
    const auto expected = axes.find(type->value);
    if (expected == axes.end()) return;
    const auto count =
        static_cast<std::size_t>(std::count_if(block.children.begin(), block.children.end(),
                                               [](const Block& inner) { return inner.keyword == "AXIS_DESCR"; }));
    if (count != expected->second) {
      error(type->place, block.keyword + " '" + block.values[0].value + "': a " + type->value + " has " +
                             std::to_string(expected->second) + " AXIS_DESCR, not " + std::to_string(count));
    }
    if ((type->value == "VAL_BLK" || type->value == "ASCII") && after(block, "MATRIX_DIM") == nullptr &&
        after(block, "NUMBER") == nullptr) {
      error(type->place, block.keyword + " '" + block.values[0].value + "': a " + type->value +
                             " needs MATRIX_DIM (or NUMBER) to say how many values it has");
    }
    const std::size_t deposit = block.keyword == "CHARACTERISTIC" ? 4 : 3;
    const Definition* layout =
        deposit < block.values.size() ? find("RECORD_LAYOUT", block.values[deposit].value) : nullptr;
    if (layout != nullptr && after(*layout->block, "FNC_VALUES") == nullptr) {
      error(block.values[deposit].place, block.keyword + " '" + block.values[0].value + "': RECORD_LAYOUT " +
                                             block.values[deposit].value + " has no FNC_VALUES");
    }
  }

  void check_compu_method(const Block& block) {
    check_format(block, value_at(block, 3));
    const Token* type = value_at(block, 2);
    if (type == nullptr) return;
    const std::string name = block.values[0].value;
    const std::map<std::string_view, std::string_view> needs{{"LINEAR", "COEFFS_LINEAR"},
                                                             {"RAT_FUNC", "COEFFS"},
                                                             {"TAB_INTP", "COMPU_TAB_REF"},
                                                             {"TAB_NOINTP", "COMPU_TAB_REF"},
                                                             {"TAB_VERB", "COMPU_TAB_REF"}};
    const auto needed = needs.find(type->value);
    if (needed != needs.end() && after(block, needed->second) == nullptr &&
        std::find_if(block.values.begin(), block.values.end(),
                     [&](const Token& token) { return token.value == needed->second; }) == block.values.end()) {
      error(type->place, "COMPU_METHOD '" + name + "': " + type->value + " needs " + std::string{needed->second});
    }
    if (type->value == "FORM" && child(block, "FORMULA") == nullptr)
      error(type->place, "COMPU_METHOD '" + name + "': FORM needs a FORMULA");
    expect(block, after(block, "COMPU_TAB_REF"), {"COMPU_TAB", "COMPU_VTAB", "COMPU_VTAB_RANGE"});
    expect(block, after(block, "REF_UNIT"), {"UNIT"});
  }

  // ---- Memory: what MEASUREMENTs, CHARACTERISTICs, AXIS_PTS and INSTANCEs occupy lies in a MEMORY_SEGMENT, when
  // the module declares any; the EPK too.

  struct Segment {
    std::uint64_t address = 0;
    std::uint64_t size = 0;
  };

  std::vector<Segment> segments(const Block& module) {
    std::vector<Segment> result;
    const Block* parameters = child(module, "MOD_PAR");
    if (parameters == nullptr) return result;
    for (const Block& segment : parameters->children) {
      if (segment.keyword != "MEMORY_SEGMENT" || segment.values.size() < 7) continue;
      const auto address = parse_whole(segment.values[5].value);
      const auto size = parse_whole(segment.values[6].value);
      if (address && size) result.push_back({static_cast<std::uint64_t>(*address), static_cast<std::uint64_t>(*size)});
    }
    return result;
  }

  // The number of elements MATRIX_DIM (or ARRAY_SIZE, NUMBER) gives, 1 without it.
  static std::uint64_t elements(const Block& block) {
    for (std::string_view keyword : {"MATRIX_DIM", "ARRAY_SIZE", "NUMBER"}) {
      for (std::size_t index = 0; index < block.values.size(); ++index) {
        if (block.values[index].value != keyword) continue;
        std::uint64_t count = 1;
        for (++index; index < block.values.size(); ++index) {
          const auto dimension = parse_whole(block.values[index].value);
          if (!dimension || *dimension < 0) break;
          count *= static_cast<std::uint64_t>(*dimension);
        }
        return count;
      }
    }
    return 1;
  }

  // Where a block's memory starts and how many bytes it takes (1 where the size depends on more than the A2L says).
  std::optional<std::pair<const Token*, std::uint64_t>> occupies(const Block& block) {
    const Token* address = nullptr;
    std::uint64_t size = 1;
    if (block.keyword == "MEASUREMENT") {
      address = after(block, "ECU_ADDRESS");
      if (block.values.size() > 2) size = size_of_datatype(block.values[2].value) * elements(block);
    } else if (block.keyword == "CHARACTERISTIC") {
      address = value_at(block, 3);
      const Definition* layout = block.values.size() > 4 ? find("RECORD_LAYOUT", block.values[4].value) : nullptr;
      const Token* type = value_at(block, 2);
      if (layout != nullptr && type != nullptr && (type->value == "VALUE" || type->value == "VAL_BLK")) {
        const Block& record = *layout->block;
        for (std::size_t index = 0; index + 2 < record.values.size(); ++index) {
          if (record.values[index].value == "FNC_VALUES")
            size = size_of_datatype(record.values[index + 2].value) * elements(block);
        }
      }
    } else if (block.keyword == "AXIS_PTS") {
      address = value_at(block, 2);
    } else if (block.keyword == "INSTANCE") {
      address = value_at(block, 3);
    }
    if (address == nullptr) return std::nullopt;
    return std::pair{address, size};
  }

  static std::string bytes(std::uint64_t count) { return std::to_string(count) + (count == 1 ? " byte" : " bytes"); }

  static bool inside(const std::vector<Segment>& declared, std::uint64_t address, std::uint64_t size) {
    return std::any_of(declared.begin(), declared.end(), [&](const Segment& segment) {
      return address >= segment.address && address + size <= segment.address + segment.size;
    });
  }

  void check_memory(const Block& module) {
    const std::vector<Segment> declared = segments(module);
    if (!declared.empty()) {
      for (const Block& block : module.children) {
        const auto range = occupies(block);
        const auto address = range ? parse_whole(range->first->value) : std::nullopt;
        if (!address || block.values.empty() || inside(declared, static_cast<std::uint64_t>(*address), range->second))
          continue;
        error(range->first->place, block.keyword + " '" + block.values[0].value + "' at " + range->first->value + " (" +
                                       bytes(range->second) + ") is in no MEMORY_SEGMENT");
      }
    }
    const Block* parameters = child(module, "MOD_PAR");
    if (parameters == nullptr) return;
    const Token* epk = after(*parameters, "EPK");
    const Token* address = after(*parameters, "ADDR_EPK");
    if (address != nullptr && epk == nullptr) {
      error(address->place, "MOD_PAR: ADDR_EPK without EPK (what should a master find there?)");
    } else if (epk != nullptr && address == nullptr) {
      warning(epk->place, "MOD_PAR: EPK without ADDR_EPK: a master cannot compare it with the ECU's");
    } else if (epk != nullptr && !declared.empty()) {
      const auto where = parse_whole(address->value);
      if (where && !inside(declared, static_cast<std::uint64_t>(*where), epk->value.size())) {
        error(address->place, "MOD_PAR: the EPK at " + address->value + " (" + bytes(epk->value.size()) +
                                  ") is in no MEMORY_SEGMENT, so a master cannot upload it");
      }
    }
  }

  // ---- IF_DATA XCP's numbers: packet sizes, events, segments and pages.

  static std::optional<std::int64_t> whole_at(const Block& block, std::size_t index) {
    return index < block.values.size() ? parse_whole(block.values[index].value) : std::nullopt;
  }

  void check_xcp(const Block& module, const Block& xcp) {
    std::int64_t max_dto = 0xFFFF;
    if (const Block* protocol = child(xcp, "PROTOCOL_LAYER")) {
      const auto cto = whole_at(*protocol, 8);
      const auto dto = whole_at(*protocol, 9);
      if (cto && *cto < 8) error(protocol->values[8].place, "PROTOCOL_LAYER: MAX_CTO is at least 8");
      if (dto && *dto < 8) error(protocol->values[9].place, "PROTOCOL_LAYER: MAX_DTO is at least 8");
      if (dto) max_dto = *dto;
    }
    if (const Block* daq = child(xcp, "DAQ")) check_daq(*daq, max_dto);
    check_segments(module, xcp);
  }

  void check_daq(const Block& daq, std::int64_t max_dto) {
    const auto channels = whole_at(daq, 2);
    std::map<std::string, const Token*> names;
    std::map<std::string, const Token*> short_names;
    std::map<std::int64_t, const Token*> numbers;
    std::size_t events = 0;
    for (const Block& event : daq.children) {
      if (event.keyword != "EVENT" || event.values.size() < 8) continue;
      ++events;
      auto unique = [this](auto& seen, const auto& key, const Token& token, const std::string& what) {
        if (const auto [first, inserted] = seen.emplace(key, &token); !inserted) {
          error(token.place, "EVENT: " + what + " '" + token.value + "' is taken by the event at line " +
                                 std::to_string(first->second->place.line));
        }
      };
      unique(names, event.values[0].value, event.values[0], "the name");
      unique(short_names, event.values[1].value, event.values[1], "the short name");
      if (const auto channel = whole_at(event, 2)) {
        unique(numbers, *channel, event.values[2], "the channel");
        if (channels && *channel >= *channels) {
          error(event.values[2].place,
                "EVENT: channel " + event.values[2].value + " is not below MAX_EVENT_CHANNEL " + daq.values[2].value);
        }
      }
      if (const auto unit = whole_at(event, 6); unit && *unit > 9) {
        error(event.values[6].place,
              "EVENT: TIME_UNIT " + event.values[6].value + " is not a unit (0 = 1 ns ... 9 = 1 s)");
      }
    }
    if (channels && static_cast<std::size_t>(*channels) != events) {
      error(daq.values[2].place,
            "DAQ: MAX_EVENT_CHANNEL is " + daq.values[2].value + " but " + std::to_string(events) + " EVENTs follow");
    }
    const auto entry = whole_at(daq, 8);
    if (entry && daq.values.size() > 6) {
      const std::string& field = daq.values[6].value;
      const std::int64_t identification = field.ends_with("ABSOLUTE")  ? 1
                                          : field.ends_with("BYTE")    ? 2
                                          : field.ends_with("ALIGNED") ? 4
                                                                       : 3;
      if (*entry + identification > max_dto) {
        error(daq.values[8].place, "DAQ: an ODT entry of " + daq.values[8].value + " bytes and its identification (" +
                                       std::to_string(identification) + ") do not fit MAX_DTO " +
                                       std::to_string(max_dto));
      }
    }
  }

  void check_segments(const Block& module, const Block& xcp) {
    const Block* pag = child(xcp, "PAG");
    const auto max_segments = pag != nullptr ? whole_at(*pag, 0) : std::nullopt;
    const Block* parameters = child(module, "MOD_PAR");
    if (parameters == nullptr) return;
    std::map<std::int64_t, const Token*> numbers;
    for (const Block& memory : parameters->children) {
      const Block* interface = memory.keyword == "MEMORY_SEGMENT" ? child(memory, "IF_DATA") : nullptr;
      const Block* segment = interface != nullptr ? child(*interface, "SEGMENT") : nullptr;
      const auto number = segment != nullptr ? whole_at(*segment, 0) : std::nullopt;
      if (!number) continue;
      const Token& token = segment->values[0];
      if (const auto [first, inserted] = numbers.emplace(*number, &token); !inserted) {
        error(token.place, "SEGMENT: number " + token.value + " is taken by the segment at line " +
                               std::to_string(first->second->place.line));
      }
      if (pag == nullptr) {
        error(token.place, "SEGMENT: a calibration segment, but IF_DATA XCP has no PAG");
      } else if (max_segments && *number >= *max_segments) {
        error(token.place,
              "SEGMENT: number " + token.value + " is not below PAG's MAX_SEGMENTS " + pag->values[0].value);
      }
      const auto pages = whole_at(*segment, 1);
      std::set<std::int64_t> page_numbers;
      for (const Block& page : segment->children) {
        const auto page_number = page.keyword == "PAGE" ? whole_at(page, 0) : std::nullopt;
        if (!page_number) continue;
        if (pages && *page_number >= *pages) {
          error(page.values[0].place,
                "PAGE: page " + page.values[0].value + " of a segment with " + segment->values[1].value + " pages");
        }
        if (!page_numbers.insert(*page_number).second) {
          error(page.values[0].place, "PAGE: page " + page.values[0].value + " is described twice");
        }
      }
    }
  }

  const a2l_syntax::Tree& tree_;
  std::vector<Problem> problems_;
  std::set<std::string, std::less<>> unchecked_interfaces_;
  std::map<std::string, std::map<std::string, Definition, std::less<>>, std::less<>> definitions_;
};

}  // namespace

std::string A2lProblem::text() const {
  return place + ": " + (severity == Severity::error ? "error" : "warning") + ": " + message;
}

std::vector<A2lProblem> check_a2l(std::string_view text, std::string_view source) {
  auto parsed = a2l_syntax::parse(text, source);
  if (auto* failed = std::get_if<a2l_syntax::SyntaxError>(&parsed)) {
    return {{A2lProblem::Severity::error,
             failed->file + ":" + std::to_string(failed->place.line) + ":" + std::to_string(failed->place.column),
             failed->problem}};
  }
  return Checker{std::get<a2l_syntax::Tree>(parsed)}.check();
}

std::vector<A2lProblem> check_a2l_file(const std::string& path) {
  auto text = read_text_file(path);
  if (!text) return {{A2lProblem::Severity::error, path, "cannot open"}};
  return check_a2l(text.value(), path);
}

bool has_errors(const std::vector<A2lProblem>& problems) {
  return std::any_of(problems.begin(), problems.end(),
                     [](const A2lProblem& problem) { return problem.severity == A2lProblem::Severity::error; });
}

}  // namespace duet::xcp::host
