#pragma once
// The A2L keywords the checker knows (ASAP2 1.71 and the AML of XCP 1.x's IF_DATA): for each block, where it may
// stand, its fixed values in order and the optional keywords it may hold with their values. Private to duet_xcp_host.

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace duet::xcp::host::a2l_rules {

// What a value must be: an identifier, a "text", a number, a whole number in a range, or one of some keywords.
struct Type {
  enum class Kind : std::uint8_t { identifier, text, number, whole, keyword };
  Kind kind = Kind::text;
  std::int64_t minimum = 0;
  std::int64_t maximum = 0;
  std::size_t max_length = 0;  // text: 0 for any length
  std::string name;            // as messages say it: "ulong", "{DATA, CODE, ...}"
  const std::vector<std::string>* keywords = nullptr;
};

// A value, or a group of values repeated: "Name:ident", "Dimension:uint+", "InVal,OutVal:float,float*".
struct Field {
  std::string label;
  std::vector<Type> group;
  bool repeated = false;
  bool at_least_one = false;
};

// An optional keyword with its values, on one line (ECU_ADDRESS 0x1000).
struct Item {
  std::string keyword;
  std::vector<Field> fields;
  bool repeatable = false;
};

struct BlockRule {
  std::string keyword;
  std::vector<std::string> parents;  // "MODULE"; "IF_DATA XCP" for the XCP blocks
  std::vector<Field> fields;
  std::map<std::string, Item, std::less<>> items;
  bool once = false;       // at most one per parent
  bool unchecked = false;  // content not checked (A2ML, IF_DATA of other tools)
};

// The rule for `keyword` inside `parent`, or nullptr; `known` says whether the keyword has a rule somewhere else.
const BlockRule* rule_for(std::string_view keyword, std::string_view parent, bool& known);
// The optional keywords at the top of a file (ASAP2_VERSION, A2ML_VERSION).
const BlockRule& file_rule();

}  // namespace duet::xcp::host::a2l_rules
