#include "mdl_encoding.hpp"

#include <array>
#include <cstdint>
#include <optional>

namespace duet::simulink_import {
namespace {

enum class Encoding { utf8, iso_8859_1, windows_1252 };

struct NamedEncoding {
  std::string name;  // as the file writes it
  int line = 0;
};

std::string lower_case(std::string_view text) {
  std::string lower{text};
  for (char& c : lower)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return lower;
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) text.remove_suffix(1);
  return text;
}

// The encoding must be known before the text is tokenized, so it is looked for line by line: the pair is written on
// a line of its own, in ASCII, whatever the encoding.
std::optional<NamedEncoding> named_encoding(std::string_view bytes) {
  constexpr std::string_view key = "SavedCharacterEncoding";
  int line = 1;
  std::size_t start = 0;
  while (start < bytes.size()) {
    std::size_t end = bytes.find('\n', start);
    if (end == std::string_view::npos) end = bytes.size();
    const std::string_view text = trimmed(bytes.substr(start, end - start));
    if (text.starts_with(key) && text.size() > key.size() && (text[key.size()] == ' ' || text[key.size()] == '\t')) {
      std::string_view value = trimmed(text.substr(key.size()));
      if (value.size() >= 2 && value.front() == '"' && value.back() == '"') value = value.substr(1, value.size() - 2);
      return NamedEncoding{std::string{value}, line};
    }
    start = end + 1;
    ++line;
  }
  return std::nullopt;
}

void append_utf8(std::string& out, std::uint32_t code_point) {
  if (code_point < 0x80) {
    out += static_cast<char>(code_point);
  } else if (code_point < 0x800) {
    out += static_cast<char>(0xC0 | (code_point >> 6));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else {
    out += static_cast<char>(0xE0 | (code_point >> 12));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  }
}

// windows-1252 differs from ISO-8859-1 in 0x80..0x9F only; 0 marks its five unassigned bytes.
constexpr std::array<std::uint16_t, 32> windows_1252_high = {
    0x20AC, 0,      0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
    0x2039, 0x0152, 0,      0x017D, 0,      0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
    0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178};

std::string hex_byte(unsigned char byte) {
  constexpr std::string_view digits = "0123456789ABCDEF";
  return std::string{"0x"} + digits[byte >> 4] + digits[byte & 0xF];
}

// The length of the well-formed UTF-8 sequence at `at`, or 0.
std::size_t utf8_sequence_length(std::string_view bytes, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
  const unsigned char lead = byte(at);
  std::size_t length = 0;
  std::uint32_t lowest = 0;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2, lowest = 0x80;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3, lowest = 0x800;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4, lowest = 0x10000;
  } else {
    return 0;
  }
  if (at + length > bytes.size()) return 0;
  std::uint32_t code_point = lead & (0x3F >> (length - 1));
  for (std::size_t i = 1; i < length; ++i) {
    if ((byte(at + i) & 0xC0) != 0x80) return 0;
    code_point = (code_point << 6) | (byte(at + i) & 0x3F);
  }
  const bool surrogate = code_point >= 0xD800 && code_point <= 0xDFFF;
  return code_point < lowest || code_point > 0x10FFFF || surrogate ? 0 : length;
}

Result<std::string> converted(std::string_view bytes, Encoding encoding, const std::string& what,
                              const std::string& file) {
  std::string text;
  text.reserve(bytes.size() + bytes.size() / 8);
  int line = 1;
  for (std::size_t at = 0; at < bytes.size();) {
    const auto byte = static_cast<unsigned char>(bytes[at]);
    if (byte == '\n') ++line;
    if (byte < 0x80) {
      text += static_cast<char>(byte);
      ++at;
      continue;
    }
    const std::string place = file + ":" + std::to_string(line) + ": ";
    if (encoding == Encoding::utf8) {
      const std::size_t length = utf8_sequence_length(bytes, at);
      if (length == 0) return Failure{place + "byte " + hex_byte(byte) + " is not " + what};
      text.append(bytes.substr(at, length));
      at += length;
      continue;
    }
    std::uint32_t code_point = byte;
    if (encoding == Encoding::windows_1252 && byte < 0xA0) {
      code_point = windows_1252_high[byte - 0x80];
      if (code_point == 0) return Failure{place + "byte " + hex_byte(byte) + " has no character in windows-1252"};
    }
    append_utf8(text, code_point);
    ++at;
  }
  return text;
}

}  // namespace

Result<std::string> mdl_text_as_utf8(std::string_view bytes, const std::string& file) {
  constexpr std::string_view byte_order_mark = "\xEF\xBB\xBF";
  if (bytes.starts_with(byte_order_mark)) bytes.remove_prefix(byte_order_mark.size());
  const std::optional<NamedEncoding> named = named_encoding(bytes);
  if (!named) return converted(bytes, Encoding::utf8, "UTF-8, and the file names no SavedCharacterEncoding", file);
  const std::string name = lower_case(named->name);
  if (name == "utf-8" || name == "us-ascii") return converted(bytes, Encoding::utf8, "UTF-8", file);
  if (name == "iso-8859-1") return converted(bytes, Encoding::iso_8859_1, "", file);
  if (name == "windows-1252") return converted(bytes, Encoding::windows_1252, "", file);
  return Failure{file + ":" + std::to_string(named->line) + ": SavedCharacterEncoding '" + named->name +
                 "' is not read (ISO-8859-1, windows-1252 and UTF-8 are); save the model as UTF-8, or as .slx"};
}

}  // namespace duet::simulink_import
