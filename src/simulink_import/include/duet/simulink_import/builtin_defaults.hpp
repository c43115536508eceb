#pragma once
// What a block parameter is when its file leaves it out: Simulink writes only the parameters that differ from the
// built-in defaults, and from R2022a on no longer writes those defaults into the file. Files up to R2021b carry them
// (SimulinkModel::defaults), which take precedence; this table answers for the rest, by the release that saved the
// file, since some defaults changed (R2019b, R2020a). docs/IMPORT.md, "Defaults".

#include <optional>
#include <string_view>

namespace duet::simulink_import {

// The built-in default of `parameter` of a `block_type` block as `release` ("R2019b") fills it; an empty release
// counts as the newest. Nothing for a parameter the table does not know.
[[nodiscard]] std::optional<std::string_view> builtin_default(std::string_view block_type, std::string_view parameter,
                                                              std::string_view release);

}  // namespace duet::simulink_import
