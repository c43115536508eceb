#pragma once
// The block library as the studio's palette and forms see it (docs/STUDIO.md, "library"): every type the checker
// knows, with its ports and parameters, and what each means and takes.

#include <nlohmann/json.hpp>

namespace duet::studio {

[[nodiscard]] nlohmann::json library_json();

}  // namespace duet::studio
