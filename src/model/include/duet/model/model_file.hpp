#pragma once
// Reading model files (docs/MODELS.md). The reader checks the file's shape (fields, types of values, names); what
// the blocks mean is validation's (validate.hpp).

#include <string>
#include <string_view>

#include "duet/model/diagnostic.hpp"
#include "duet/model/model.hpp"
#include "duet/support/result.hpp"

namespace duet::model {

inline constexpr int format_version = 1;

// The model, or the first problem as a formatted diagnostic (`file:line:column: error: ...`).
[[nodiscard]] Result<Model> parse_model(std::string_view text, const std::string& file);
[[nodiscard]] Result<Model> load_model(const std::string& path);

}  // namespace duet::model
