#pragma once
// A double as the shortest text that reads back as the same double ("0.05", "1e-07", "-inf", "nan"): what a
// number in a file, a report or a message should look like, exact and without noise.

#include <string>

namespace duet {

[[nodiscard]] std::string shortest_text(double value);

}  // namespace duet
