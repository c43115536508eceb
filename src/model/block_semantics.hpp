#pragma once
// For the model's passes (private to src/model): what simulation and generation must read alike from a block's
// parameters — operators, signs, sizes, how a rate transition hands over its value.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "duet/blocks/bytes.hpp"
#include "duet/blocks/interpolation.hpp"
#include "duet/blocks/logic.hpp"
#include "duet/blocks/state.hpp"
#include "duet/model/program.hpp"

namespace duet::model {

// Simulink's default derivative filter coefficient of a PID, 1/s.
inline constexpr double pid_default_filter = 100.0;

// A Sum's signs, one per input ("+-" subtracts u2 from u1); all '+' unless given.
[[nodiscard]] std::string sum_signs(const ProgramBlock& block);

// A Product's signs, one per input ("*/" divides u1 by u2); all '*' unless given.
[[nodiscard]] std::string product_signs(const ProgramBlock& block);

// A Step's or PulseGenerator's times in steps of its own rate (rounded to the nearest step).
struct SourceSteps {
  std::uint32_t start = 0;   // Step: the step of the change; PulseGenerator: the delay
  std::uint32_t period = 0;  // PulseGenerator
  std::uint32_t width = 0;   // PulseGenerator
};
[[nodiscard]] SourceSteps source_steps(const ProgramBlock& block);

[[nodiscard]] blocks::Endian endian_of(const ProgramBlock& block);   // little unless given
[[nodiscard]] std::size_t unpack_offset(const ProgramBlock& block);  // a ByteUnpack's first byte
[[nodiscard]] std::size_t block_window(const ProgramBlock& block);
// The place among the block's inputs of the input connected to `port`, if it is (a DiscretePid's external gains).
[[nodiscard]] std::optional<std::size_t> input_of(const ProgramBlock& block,
                                                  std::string_view port);  // a MovingAverage's window, 1 or more
[[nodiscard]] bool anti_windup_clamping(const ProgramBlock& block);        // a DiscretePid's anti_windup: clamping

// The size of what a block parameter gives, as matrices count it: a literal's as written, a tunable parameter's as
// declared; a vector is a column, a scalar 1x1. A parameter the block is not given has no elements.
struct ArgumentSize {
  std::size_t rows = 1;
  std::size_t columns = 1;
  std::size_t elements = 0;
};
[[nodiscard]] ArgumentSize argument_size(const Program& program, const ProgramBlock& block, const std::string& name);

struct MatrixSizes {
  std::size_t rows = 1;
  std::size_t inner = 1;
  std::size_t columns = 1;
};
[[nodiscard]] MatrixSizes matrix_sizes(const Program& program, const ProgramBlock& block);

// The element of a Demux's input that output `port` (y1, y2, ...) carries.
[[nodiscard]] std::size_t demux_element(const std::string& port);

[[nodiscard]] std::optional<blocks::CompareOperator> parse_compare_operator(std::string_view text);
[[nodiscard]] std::optional<blocks::LogicOperator> parse_logic_operator(std::string_view text);
[[nodiscard]] blocks::Edge edge_of(const ProgramBlock& block);  // rising, falling or either (the reader checks it)
// Of a validated block (check_types refuses unknown operators).
[[nodiscard]] blocks::CompareOperator compare_operator(const ProgramBlock& block);
[[nodiscard]] blocks::LogicOperator logic_operator(const ProgramBlock& block);
// An Interpolation's method (linear unless given) and extrapolation (clip unless given).
[[nodiscard]] blocks::InterpolationMethod interpolation_method(const ProgramBlock& block);
[[nodiscard]] blocks::Extrapolation extrapolation_of(const ProgramBlock& block);

// How a RateTransition hands its value from the writer's task to the reader's (duet/rt/rate_transition.hpp):
// between periodic rates deterministically at the slower rate's releases, which come every `ratio` activations of
// the faster task; with an interrupt task on either side, the latest value.
struct Transfer {
  enum class Kind : std::uint8_t { fast_to_slow, slow_to_fast, latest } kind = Kind::latest;
  std::uint32_t ratio = 1;
};
[[nodiscard]] Transfer transfer_of(const Program& program, const ProgramBlock& block);

}  // namespace duet::model
