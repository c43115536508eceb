#pragma once
// What makes a zip entry's name unsafe to unpack; the reader refuses such entries and the writer does not make them.

#include <optional>
#include <string>
#include <string_view>

namespace duet::fmi {

// Empty when `name` is a relative '/'-separated path that stays inside the folder it is unpacked into.
[[nodiscard]] std::optional<std::string> entry_name_problem(std::string_view name);

}  // namespace duet::fmi
