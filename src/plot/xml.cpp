#include "xml.hpp"

#include <charconv>
#include <cmath>
#include <cstddef>

namespace duet::plot {
namespace {

// The length of the well-formed UTF-8 sequence starting at text[at], or 0 if there is none (RFC 3629: no overlong
// forms, no surrogates, nothing above U+10FFFF).
std::size_t utf8_length(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(at);
  std::size_t length = 0;
  unsigned char low = 0x80;  // the range the second byte must fall in
  unsigned char high = 0xBF;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;
    if (lead == 0xED) high = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;
    if (lead == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (at + length > text.size() || byte(at + 1) < low || byte(at + 1) > high) return 0;
  for (std::size_t i = at + 2; i < at + length; ++i) {
    if (byte(i) < 0x80 || byte(i) > 0xBF) return 0;
  }
  return length;
}

}  // namespace

std::string escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80) {
      const std::size_t length = utf8_length(text, i);
      const std::string_view sequence = text.substr(i, length);
      const bool character = length > 0 && sequence != "\xEF\xBF\xBE" && sequence != "\xEF\xBF\xBF";  // U+FFFE, U+FFFF
      out += character ? sequence : std::string_view{"\xEF\xBF\xBD"};
      i += length == 0 ? 1 : length;
      continue;
    }
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += (c < 0x20 && c != '\t' && c != '\n' && c != '\r') ? '?' : static_cast<char>(c);
    }
    ++i;
  }
  return out;
}

void append_coordinate(std::string& out, double value) {
  double rounded = std::round(value * 10) / 10;
  if (rounded == 0) rounded = 0;  // no "-0"
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, rounded, std::chars_format::fixed, 1);
  std::string_view text{buffer, error == std::errc{} ? static_cast<std::size_t>(end - buffer) : 0};
  if (text.ends_with(".0")) text.remove_suffix(2);
  out += text;
}

void append_attribute(std::string& out, std::string_view name, double value) {
  out += ' ';
  out += name;
  out += "=\"";
  append_coordinate(out, value);
  out += '"';
}

void append_line(std::string& out, double x1, double y1, double x2, double y2, std::string_view attributes) {
  out += "<line";
  append_attribute(out, "x1", x1);
  append_attribute(out, "y1", y1);
  append_attribute(out, "x2", x2);
  append_attribute(out, "y2", y2);
  out += ' ';
  out += attributes;
  out += "/>\n";
}

void append_text(std::string& out, double x, double y, std::string_view attributes, std::string_view text) {
  out += "<text";
  append_attribute(out, "x", x);
  append_attribute(out, "y", y);
  if (!attributes.empty()) out += ' ';
  out += attributes;
  out += '>';
  out += escaped(text);
  out += "</text>\n";
}

}  // namespace duet::plot
