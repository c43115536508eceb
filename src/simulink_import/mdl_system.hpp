#pragma once
// A classic .mdl `System { Block {...} Line {...} }` section into a System: blocks with their parameters, masks and
// nested systems; lines with their branches flattened and their ends checked against the system's blocks.

#include <initializer_list>
#include <map>
#include <string>
#include <string_view>

#include "duet/simulink_import/simulink_model.hpp"
#include "duet/support/result.hpp"
#include "mdl_syntax.hpp"

namespace duet::simulink_import {

// `path` names the system in messages ("model/Controller"); `file` is the .mdl file, which becomes System::part.
Result<System> read_mdl_system(const MdlNode& section, const std::string& path, const std::string& file);

// The pairs of a section into a map, keeping each as stored; a name given twice is an error (the later value would
// silently replace the first). Pairs without a name and the pairs named in `skipped` are left out.
Status add_mdl_pairs(const MdlNode& section, std::map<std::string, std::string>& into, const std::string& file,
                     std::initializer_list<std::string_view> skipped = {});

}  // namespace duet::simulink_import
