#pragma once
// The block library as validation sees it: each type's ports and parameters, and whether its outputs depend on its
// inputs within a step (direct feedthrough), which orders execution and finds algebraic loops. What the blocks
// compute lives in src/blocks; this table only describes them.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace duet::model {

struct ParameterSpec {
  std::string_view name;
  bool required = true;
};

struct BlockType {
  std::string_view name;
  std::vector<std::string_view> inputs;  // fixed port names; see variadic_inputs
  std::vector<std::string_view> outputs;
  std::vector<ParameterSpec> parameters;
  bool direct_feedthrough = true;
  // Inputs u1, u2, ... in any number >= 2 (Sum, Product, Mux), instead of `inputs`.
  bool variadic_inputs = false;
  // Ports and parameters are the instance's own (Subsystem, Code): not checked against the table.
  bool user_defined_ports = false;
  // Inputs that may be left unconnected (a DiscretePid's gains from signals instead of its parameters).
  std::vector<std::string_view> optional_inputs = {};
};

[[nodiscard]] std::span<const BlockType> block_types();
// Parameters whose value is a word rather than a number or a reference: a pin, a timer, an operator, a data type.
[[nodiscard]] bool is_word_parameter(std::string_view parameter);
[[nodiscard]] const BlockType* find_block_type(std::string_view name);
// Blocks that reach the plant by a resource's name, as doubles: a plant model's PlantInput and PlantOutput, and a
// model's own Inport and Outport ("inport:NAME", "outport:NAME") when it runs on its own.
[[nodiscard]] bool is_plant_resource(std::string_view type);

}  // namespace duet::model
