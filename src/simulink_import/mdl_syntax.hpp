#pragma once
// The nested-brace grammar of a classic .mdl file, without meaning: sections `Name { ... }` and pairs `Name value`.

#include <initializer_list>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "duet/support/result.hpp"

namespace duet::simulink_import {

// A section or a pair. A pair's value is its text as meant: quoted chunks joined with their escapes resolved, a bare
// token as written, a bracketed array with its brackets ("[0.5, 0.5; 1, 2]"). Elements the file writes without a
// name (a lone string in an array, a section opened by a bare '{') have an empty name.
struct MdlNode {
  std::string name;
  bool is_section = false;
  std::string value;              // a pair's
  std::vector<MdlNode> children;  // a section's, in file order
  int line = 0;
};

// Sections may not nest deeper than this: a file that does is damaged or hostile, and recursion must stay bounded.
inline constexpr int max_mdl_nesting = 200;

// The first pair of that name among the section's children, or null.
const MdlNode* find_pair(const MdlNode& section, std::string_view name);
// The value of that pair, or empty.
std::string pair_value(const MdlNode& section, std::string_view name);

// The pairs of a section into a map, keeping each as stored; a name given twice is an error (the later value would
// silently replace the first). Pairs without a name and the pairs named in `skipped` are left out.
Status add_mdl_pairs(const MdlNode& section, std::map<std::string, std::string>& into, const std::string& file,
                     std::initializer_list<std::string_view> skipped = {});

// "model.mdl:12: message": the form of every message the reader gives.
Failure mdl_failure(const std::string& file, int line, const std::string& message);

// The file's top level (Model, Library, Stateflow, MatData, ...) as the children of an unnamed section.
Result<MdlNode> parse_mdl_syntax(std::string_view utf8_text, const std::string& file);

}  // namespace duet::simulink_import
