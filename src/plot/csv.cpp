#include "duet/plot/csv.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace duet::plot {
namespace {

std::string_view trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string_view> fields_of(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trimmed(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

// A whole field as a number: from_chars takes "nan" and "inf" but no leading '+', which other writers use.
std::optional<double> number_in(std::string_view field) {
  if (field.starts_with('+')) field.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (error != std::errc{} || end != field.data() + field.size() || field.empty()) return std::nullopt;
  return value;
}

// Lines one by one, numbered from 1, without their line end.
class Lines {
 public:
  explicit Lines(std::string_view text) : rest_(text) {}
  [[nodiscard]] bool next(std::string_view& line) {
    if (rest_.empty()) return false;
    const std::size_t end = rest_.find('\n');
    line = rest_.substr(0, end);
    rest_ = end == std::string_view::npos ? std::string_view{} : rest_.substr(end + 1);
    ++number_;
    return true;
  }
  [[nodiscard]] std::size_t number() const { return number_; }

 private:
  std::string_view rest_;
  std::size_t number_ = 0;
};

class Reader {
 public:
  explicit Reader(std::string_view source) : source_(source) {}

  [[nodiscard]] Failure at(std::size_t line, const std::string& problem) const {
    return Failure{std::string{source_} + ":" + std::to_string(line) + ": " + problem};
  }

  [[nodiscard]] std::optional<Failure> header(std::string_view line, Figure& figure) const {
    const std::vector<std::string_view> names = fields_of(line);
    if (names[0] == "time") {
      figure.time_unit.clear();
    } else if (names[0].starts_with("time_") && names[0].size() > 5) {
      figure.time_unit = std::string{names[0].substr(5)};
    } else {
      return at(1, "the first column is '" + std::string{names[0]} + "'; expected the time, as time_s");
    }
    for (std::size_t column = 1; column < names.size(); ++column) {
      if (names[column].empty()) return at(1, "column " + std::to_string(column + 1) + " has no name");
      figure.series.push_back({.name = std::string{names[column]}, .unit = {}, .values = {}});
    }
    return std::nullopt;
  }

  [[nodiscard]] std::optional<Failure> row(std::size_t line, std::string_view text,
                                           const std::vector<std::string_view>& names, Figure& figure) const {
    const std::vector<std::string_view> fields = fields_of(text);
    if (fields.size() != names.size()) {
      return at(line, std::to_string(fields.size()) + " values; expected " + std::to_string(names.size()) +
                          ", one per column of the header");
    }
    const auto not_a_number = [&](std::size_t column, std::string_view what) {
      return at(line, "column " + std::to_string(column + 1) + " (" + std::string{names[column]} + "): '" +
                          std::string{fields[column]} + "' is not " + std::string{what});
    };
    const std::optional<double> time = number_in(fields[0]);
    if (!time || !std::isfinite(*time)) return not_a_number(0, "a finite number");
    if (!figure.time.empty() && *time < figure.time.back()) {
      return at(line, "the time " + std::string{fields[0]} + " is before the time of the row above");
    }
    figure.time.push_back(*time);
    for (std::size_t column = 1; column < fields.size(); ++column) {
      std::optional<double> value =
          fields[column].empty() ? std::numeric_limits<double>::quiet_NaN() : number_in(fields[column]);
      if (!value) return not_a_number(column, "a number");
      figure.series[column - 1].values.push_back(*value);
    }
    return std::nullopt;
  }

 private:
  std::string_view source_;
};

}  // namespace

Result<Figure> read_csv(std::string_view text, std::string_view source) {
  const Reader reader{source};
  Lines lines{text};
  std::string_view line;
  if (!lines.next(line) || trimmed(line).empty()) return reader.at(1, "no header; expected one such as time_s,a,b");
  Figure figure{.title = std::string{source}, .time = {}, .series = {}};
  if (auto failure = reader.header(line, figure)) return *failure;
  const std::vector<std::string_view> names = fields_of(line);

  const auto rows = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  figure.time.reserve(rows);
  for (Series& series : figure.series) series.values.reserve(rows);
  while (lines.next(line)) {
    if (trimmed(line).empty()) continue;
    if (auto failure = reader.row(lines.number(), line, names, figure)) return *failure;
  }
  return figure;
}

}  // namespace duet::plot
