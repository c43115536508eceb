// Validation: models that read fine but mean nothing runnable, each with the message it must get.
#include "duet/model/validate.hpp"

#include <gtest/gtest.h>

#include "duet/model/model_file.hpp"

namespace duet::model {
namespace {

// The model's diagnostics, formatted, one per line.
std::string diagnostics_of(const std::string& blocks, const std::string& header = {}) {
  const std::string text = "duet_model: 1\nname: m\nbase_period_us: 100\n" + header + "blocks:\n" + blocks;
  const auto model = parse_model(text, "m.yaml");
  if (!model.ok()) return "(does not read: " + model.error() + ")";
  std::string lines;
  for (const Diagnostic& diagnostic : validate(model.value())) lines += format("m.yaml", diagnostic) + "\n";
  return lines;
}

TEST(Validate, AValidModelHasNothingToSay) {
  EXPECT_EQ(diagnostics_of("  - {name: toggle, type: Not, inputs: {u: old}, outputs: {y: state}}\n"
                           "  - {name: delay, type: UnitDelay, inputs: {u: state}, outputs: {y: old}}\n"
                           "  - {name: pin, type: GpioOut, parameters: {pin: PA5}, inputs: {u: state}}\n"),
            "");
}

struct Case {
  const char* name;
  const char* header;
  const char* blocks;
  const char* messages;
};

const Case cases[] = {
    {"unknown_type", "", "  - {name: g, type: Gian}\n",
     "m.yaml:5:21: error: unknown block type 'Gian' (did you mean 'Gain'?)\n"},
    {"unknown_type_far", "", "  - {name: g, type: Integrator}\n",
     "m.yaml:5:21: error: unknown block type 'Integrator' (docs/MODELS.md lists the block types)\n"},
    {"unknown_input_port", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: g, type: Gain, parameters: {k: 2}, inputs: {in: x}}\n",
     "m.yaml:6:56: error: block 'g' (Gain) has no input 'in' (its inputs: u)\n"
     "m.yaml:6:5: error: input 'u' of block 'g' is not connected (connect it: inputs: {u: SIGNAL})\n"},
    {"unknown_output_port", "", "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {out: x}}\n",
     "m.yaml:5:65: error: block 'c' (Constant) has no output 'out' (its outputs: y)\n"},
    {"unconnected_input", "", "  - {name: g, type: Gain, parameters: {k: 2}, outputs: {y: x}}\n",
     "m.yaml:5:5: error: input 'u' of block 'g' is not connected (connect it: inputs: {u: SIGNAL})\n"},
    {"no_driver", "",
     "  - {name: g, type: Gain, parameters: {k: 2}, inputs: {u: thetta}}\n"
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: theta}}\n",
     "m.yaml:5:56: error: input 'u' of block 'g' reads signal 'thetta', which nothing drives (did you mean "
     "'theta'?)\n"},
    {"two_drivers", "",
     "  - {name: a, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: b, type: Constant, parameters: {value: 2}, outputs: {y: x}}\n",
     "m.yaml:6:65: error: signal 'x' has two drivers: block 'a' (output y) and block 'b' (output y) (a signal has "
     "exactly one driver)\n"},
    {"duplicate_block", "",
     "  - {name: a, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: a, type: GpioOut, parameters: {pin: PA5}, inputs: {u: x}}\n",
     "m.yaml:6:5: error: two blocks are named 'a' (names are unique within a subsystem)\n"},
    {"unknown_parameter", "", "  - {name: c, type: Constant, parameters: {value: 1, gain: 2}, outputs: {y: x}}\n",
     "m.yaml:5:60: error: block 'c' (Constant) has no parameter 'gain' (its parameters: value, type)\n"},
    {"missing_parameter", "", "  - {name: c, type: Constant, outputs: {y: x}}\n",
     "m.yaml:5:5: error: block 'c' (Constant) needs parameter 'value' (parameters: {value: VALUE})\n"},
    {"unknown_reference", "parameters:\n  Kp: 1\n",
     "  - {name: c, type: Constant, parameters: {value: Kq}, outputs: {y: x}}\n",
     "m.yaml:7:51: error: parameter 'value' of block 'c' names 'Kq', which is neither a parameter nor a constant of "
     "the model (did you mean 'Kp'?)\n"
     "m.yaml:5:3: warning: parameter 'Kp' is not used (remove it, or use it in a block)\n"},
    {"algebraic_loop", "",
     "  - {name: a, type: Gain, parameters: {k: 2}, inputs: {u: z}, outputs: {y: x}}\n"
     "  - {name: b, type: Sum, inputs: {u1: x, u2: x}, outputs: {y: z}}\n",
     "m.yaml:5:5: error: algebraic loop: 'a' -> 'b' -> 'a' (a block without direct feedthrough in the loop, such as "
     "a UnitDelay, breaks it)\n"},
    {"sum_with_gap", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: s, type: Sum, inputs: {u1: x, u3: x}, outputs: {y: z}}\n",
     "m.yaml:6:5: error: input 'u2' of block 's' is not connected (a Sum takes inputs u1, u2, ... without gaps, at "
     "least two)\n"},
    {"sum_bad_port", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: s, type: Sum, inputs: {u1: x, u2: x, v: x}, outputs: {y: z}}\n",
     "m.yaml:6:49: error: block 's' (Sum) has no input 'v' (its inputs are u1, u2, ...)\n"},
    {"subsystem_output_not_driven", "",
     "  - name: s\n    type: Subsystem\n    outputs: {y: x}\n    blocks:\n"
     "      - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: z}}\n",
     "m.yaml:7:15: error: output 'y' of the subsystem is not driven inside it (a block inside must drive a signal "
     "named 'y')\n"},
    {"subsystem_scope", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: outer}}\n"
     "  - name: s\n    type: Subsystem\n    blocks:\n"
     "      - {name: g, type: GpioOut, parameters: {pin: PA5}, inputs: {u: outer}}\n",
     "m.yaml:9:67: error: input 'u' of block 'g' reads signal 'outer', which nothing drives (an output of a block, or "
     "of the subsystem's inputs, must drive it)\n"},
    {"unused_constant_and_signal", "constants:\n  n: 3\nsignals:\n  theta: {unit: deg}\n",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n",
     "m.yaml:5:3: warning: constant 'n' is not used (remove it, or use it in a block)\n"
     "m.yaml:7:3: warning: signal 'theta' is declared but nothing drives it (remove the declaration, or drive the "
     "signal)\n"},
    {"rate_crossing", "",
     "  - {name: fast, type: Counter, parameters: {limit: 10}, outputs: {y: n}}\n"
     "  - {name: slow, type: Gain, period: {multiple: 10}, parameters: {k: 2}, inputs: {u: n}, outputs: {y: m}}\n",
     "m.yaml:6:83: error: rate crossing: block 'slow' (1000 us) reads signal 'n' of block 'fast' (100 us) directly "
     "(put a RateTransition between them)\n"},
    {"inherited_mixed_rates", "",
     "  - {name: fast, type: Counter, parameters: {limit: 10}, outputs: {y: a}}\n"
     "  - {name: slow, type: Counter, period_us: 1000, parameters: {limit: 10}, outputs: {y: b}}\n"
     "  - {name: s, type: Sum, inputs: {u1: a, u2: b}, outputs: {y: c}}\n",
     "m.yaml:7:42: error: rate crossing: block 's' (100 us) reads signal 'b' of block 'slow' (1000 us) directly (put a "
     "RateTransition between them)\n"},
    {"interrupt_reads_periodic", "",
     "  - {name: fast, type: Counter, parameters: {limit: 10}, outputs: {y: n}}\n"
     "  - name: isr\n    type: Subsystem\n    trigger: {interrupt: EXTI0, priority: 5}\n    inputs: {count: n}\n"
     "    blocks:\n"
     "      - {name: pin, type: GpioOut, parameters: {pin: PA5}, inputs: {u: count}}\n",
     "m.yaml:11:69: error: the interrupt task 'EXTI0' reads signal 'n' of the periodic block 'fast' (100 us) directly "
     "(put a RateTransition (mode: latest) between them)\n"},
};

class Invalid : public ::testing::TestWithParam<Case> {};

TEST_P(Invalid, GetsItsMessages) {
  EXPECT_EQ(diagnostics_of(GetParam().blocks, GetParam().header), GetParam().messages);
}

INSTANTIATE_TEST_SUITE_P(Corpus, Invalid, ::testing::ValuesIn(cases),
                         [](const auto& test) { return std::string{test.param.name}; });

TEST(Validate, ADelayInsideASubsystemBreaksALoopThroughIt) {
  EXPECT_EQ(diagnostics_of("  - {name: g, type: Gain, parameters: {k: 2}, inputs: {u: back}, outputs: {y: forth}}\n"
                           "  - name: s\n    type: Subsystem\n    inputs: {u: forth}\n    outputs: {y: back}\n"
                           "    blocks:\n"
                           "      - {name: d, type: UnitDelay, inputs: {u: u}, outputs: {y: y}}\n"),
            "");
  EXPECT_NE(diagnostics_of("  - {name: g, type: Gain, parameters: {k: 2}, inputs: {u: back}, outputs: {y: forth}}\n"
                           "  - name: s\n    type: Subsystem\n    inputs: {u: forth}\n    outputs: {y: back}\n"
                           "    blocks:\n"
                           "      - {name: h, type: Gain, parameters: {k: 3}, inputs: {u: u}, outputs: {y: y}}\n")
                .find("algebraic loop: 'g' -> 's' -> 'g'"),
            std::string::npos);
}

}  // namespace
}  // namespace duet::model

namespace duet::model {
namespace {

const Case code_cases[] = {
    {"code_without_function", "", "  - {name: logic, type: Code, file: logic.hpp}\n",
     "(does not read: m.yaml:5:5: error: Code block 'logic' needs 'function' (the C++ function it calls))"},
    {"code_without_file", "", "  - {name: logic, type: Code, function: motor_logic}\n",
     "(does not read: m.yaml:5:5: error: Code block 'logic' needs 'file' (the header that declares the function, "
     "beside the model))"},
    {"code_untyped_port", "", "  - {name: logic, type: Code, function: f, file: f.hpp, inputs: {u: x}}\n",
     "(does not read: m.yaml:5:69: error: a Code block's port names its signal and its type ({signal: NAME, type: "
     "TYPE}))"},
    {"code_port_without_type", "",
     "  - {name: logic, type: Code, function: f, file: f.hpp, inputs: {u: {signal: x}}}\n",
     "(does not read: m.yaml:5:69: error: port u needs 'type')"},
    {"function_on_a_gain", "", "  - {name: g, type: Gain, function: f}\n",
     "(does not read: m.yaml:5:37: error: 'function' belongs to Code blocks (block 'g' is a Gain))"},
    {"code_state_without_type", "",
     "  - {name: logic, type: Code, function: f, file: f.hpp, state: {last: {initial: 0}}}\n",
     "(does not read: m.yaml:5:71: error: state last needs 'type')"},
    {"code_file_missing", "", "  - {name: logic, type: Code, function: f, file: no_such_header.hpp}\n",
     "m.yaml:5:50: error: file 'no_such_header.hpp' of Code block 'logic' is not there (the path is relative to the "
     "model file's folder)\n"},
};

INSTANTIATE_TEST_SUITE_P(Code, Invalid, ::testing::ValuesIn(code_cases),
                         [](const auto& test) { return std::string{test.param.name}; });

}  // namespace
}  // namespace duet::model
