#pragma once
// Reading back the CSV that `duet sim` (and `duet xcp record`) write, to plot it again.

#include <string_view>

#include "duet/plot/figure.hpp"
#include "duet/support/result.hpp"

namespace duet::plot {

// The CSV: a header `time_s,a,b,...` (the first column `time` or `time_<unit>`), then one row per sample with a
// number per column; the time never decreases. Spaces around a field, CR-LF line ends and blank lines are allowed;
// an empty value is a missing sample (NaN); `nan` and `inf` are read as such. There is no quoting: names hold no
// commas. The series get the header's names and no unit (the CSV does not say); the title is `source`.
// Errors read "source:line: problem", naming the column where there is one.
[[nodiscard]] duet::Result<Figure> read_csv(std::string_view text, std::string_view source);

}  // namespace duet::plot
