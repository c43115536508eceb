#pragma once
// What the block library tells a person (duet studio's palette, tooltips and parameter forms): per type a one-line
// summary and a category, per parameter what it means and what it takes. block_types.hpp says what the checker
// needs; this says what an editor needs, so that a form can refuse a wrong value before the checker sees it.

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace duet::model {

struct ParameterDocumentation {
  std::string_view name;
  std::string_view description;
  std::span<const std::string_view> choices = {};  // a word's values, when it has a fixed set
  std::optional<double> minimum = {};
  std::optional<double> maximum = {};
  enum class Kind : std::uint8_t { number, word, data_type } kind = Kind::number;
  bool integer = false;
};

struct BlockDocumentation {
  std::string_view type;
  std::string_view category;  // sources, math, logic, signals, discrete, control, rates, hardware, structure
  std::string_view summary;
  std::span<const ParameterDocumentation> parameters;
};

// Every type of block_types() has one; nullptr for a name that is no block type.
[[nodiscard]] const BlockDocumentation* find_block_documentation(std::string_view type);
[[nodiscard]] const ParameterDocumentation* find_parameter_documentation(const BlockDocumentation& block,
                                                                         std::string_view parameter);

// The names data_type parameters take, as model files spell them.
[[nodiscard]] std::span<const std::string_view> data_type_names();

}  // namespace duet::model
