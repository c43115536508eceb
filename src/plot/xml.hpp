#pragma once
// The small pieces of writing SVG by hand: text that is safe in XML, coordinates without needless digits, and the
// few elements written often.

#include <string>
#include <string_view>

namespace duet::plot {

// `text` as XML character data or attribute value: the five special characters as entities, control characters
// (which XML 1.0 forbids) as '?', and bytes that are not well-formed UTF-8 as U+FFFD. Names come from users' files.
[[nodiscard]] std::string escaped(std::string_view text);

// `value` rounded to 0.1 (a tenth of a pixel is finer than any screen), without a trailing ".0" or a "-0".
void append_coordinate(std::string& out, double value);

// ` name="value"`.
void append_attribute(std::string& out, std::string_view name, double value);

// `<line .../>` from (x1, y1) to (x2, y2); `attributes` is written as it is.
void append_line(std::string& out, double x1, double y1, double x2, double y2, std::string_view attributes);

// `<text ...>` at (x, y); `attributes` is written as it is, `text` escaped.
void append_text(std::string& out, double x, double y, std::string_view attributes, std::string_view text);

}  // namespace duet::plot
