// Types and sizes: models that validate but whose signals do not fit the blocks they meet, each with the message it
// must get; and what build_program infers where a model is right.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>

#include "duet/model/model_file.hpp"
#include "duet/model/program.hpp"

namespace duet::model {
namespace {

std::string model_text(const std::string& blocks, const std::string& header) {
  return "duet_model: 1\nname: m\nbase_period_us: 100\n" + header + "blocks:\n" + blocks;
}

// The diagnostics of build_program, formatted, one per line. `file` is where the model pretends to be (Code blocks
// look for their header beside it).
std::string diagnostics_of(const std::string& blocks, const std::string& header = {},
                           const std::string& file = "m.yaml") {
  const auto model = parse_model(model_text(blocks, header), file);
  if (!model.ok()) return "(does not read: " + model.error() + ")";
  std::string lines;
  for (const Diagnostic& diagnostic : build_program(model.value()).diagnostics) {
    lines += format("m.yaml", diagnostic) + "\n";
  }
  return lines;
}

struct Case {
  const char* name;
  const char* header;
  const char* blocks;
  const char* messages;
};

const Case cases[] = {
    {"declared_type_differs_from_driver", "signals:\n  x: {type: single}\n",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n",
     "m.yaml:5:3: error: type mismatch: signal 'x' is declared single but block 'c' (Constant) drives it with double "
     "(declare it as double, or convert it with a Convert block)\n"},
    {"declared_size_differs_from_driver", "signals:\n  x: {size: 3}\n",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n",
     "m.yaml:5:3: error: type mismatch: signal 'x' is declared double[3] but block 'c' (Constant) drives it with "
     "double (declare it as double, or convert it with a Convert block)\n"},
    {"sum_of_two_types", "",
     "  - {name: a, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: b, type: Constant, parameters: {value: 2, type: single}, outputs: {y: z}}\n"
     "  - {name: s, type: Sum, inputs: {u1: x, u2: z}, outputs: {y: total}}\n",
     "m.yaml:7:42: error: type mismatch: input 'u2' (signal 'z') of block 's' (Sum) is single, but input 'u1' (signal "
     "'x') is double (convert one of them with a Convert block)\n"},
    {"sum_of_two_sizes", "",
     "  - {name: a, type: Constant, parameters: {value: [1, 2]}, outputs: {y: x}}\n"
     "  - {name: b, type: Constant, parameters: {value: [1, 2, 3]}, outputs: {y: z}}\n"
     "  - {name: s, type: Sum, inputs: {u1: x, u2: z}, outputs: {y: total}}\n",
     "m.yaml:7:42: error: size mismatch: input 'u2' (signal 'z') of block 's' (Sum) is double[3], but input 'u1' "
     "(signal 'x') is double[2] (a Sum works element by element on inputs of one size)\n"},
    {"switch_on_and_off_differ", "",
     "  - {name: a, type: Constant, parameters: {value: 1, type: int8}, outputs: {y: on}}\n"
     "  - {name: b, type: Constant, parameters: {value: 2}, outputs: {y: off}}\n"
     "  - {name: pin, type: GpioIn, parameters: {pin: PA0}, outputs: {y: pressed}}\n"
     "  - {name: s, type: Switch, inputs: {on: on, condition: pressed, off: off}, outputs: {y: chosen}}\n",
     "m.yaml:8:66: error: type mismatch: input 'off' (signal 'off') of block 's' (Switch) is double, but input 'on' "
     "(signal 'on') is int8 (convert one of them with a Convert block)\n"},
    {"gain_on_a_boolean", "",
     "  - {name: pin, type: GpioIn, parameters: {pin: PA0}, outputs: {y: pressed}}\n"
     "  - {name: g, type: Gain, parameters: {k: 2}, inputs: {u: pressed}, outputs: {y: twice}}\n",
     "m.yaml:6:56: error: type mismatch: block 'g' (Gain) does arithmetic, but input 'u' (signal 'pressed') is boolean "
     "(convert it to a number with a Convert block)\n"},
    {"tunable_parameter_of_another_type", "parameters:\n  K: {value: 2, type: single}\n",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: g, type: Gain, parameters: {k: K}, inputs: {u: x}, outputs: {y: y}}\n",
     "m.yaml:8:43: error: type mismatch: parameter 'K' is single but block 'g' (Gain) computes in double (declare 'K' "
     "with type: double)\n"},
    {"literal_vector_of_the_wrong_size", "",
     "  - {name: c, type: Constant, parameters: {value: [1, 2]}, outputs: {y: x}}\n"
     "  - {name: g, type: Gain, parameters: {k: [1, 2, 3]}, inputs: {u: x}, outputs: {y: y}}\n",
     "m.yaml:6:43: error: size mismatch: parameter 'k' of block 'g' (Gain) has 3 elements but the block computes on "
     "double[2] (give a scalar, or one value per element)\n"},
    {"tunable_vector_of_the_wrong_size", "parameters:\n  limits: [1, 2, 3]\n",
     "  - {name: c, type: Constant, parameters: {value: [1, 2]}, outputs: {y: x}}\n"
     "  - {name: d, type: UnitDelay, parameters: {initial: limits}, inputs: {u: x}, outputs: {y: y}}\n",
     "m.yaml:8:54: error: size mismatch: parameter 'limits' is double[3] but block 'd' (UnitDelay) computes on "
     "double[2] (give a scalar, or one value per element)\n"},
    {"literal_beyond_int8", "",
     "  - {name: c, type: Constant, parameters: {value: 3, type: int8}, outputs: {y: x}}\n"
     "  - {name: g, type: Gain, parameters: {k: 300}, inputs: {u: x}, outputs: {y: y}}\n",
     "m.yaml:6:43: error: type mismatch: parameter 'k' of block 'g' (Gain) is 300, which is not a value of int8 (the "
     "block computes in its input's type, int8: give a value of that type, or convert the input)\n"},
    {"constant_beyond_its_type", "",
     "  - {name: c, type: Constant, parameters: {value: 300, type: int8}, outputs: {y: x}}\n",
     "m.yaml:5:51: error: type mismatch: parameter 'value' of block 'c' (Constant) is 300, which is not a value of "
     "int8 (the Constant's type is int8: give a value of that type, or another type)\n"},
    {"fraction_for_an_integer", "",
     "  - {name: c, type: Counter, parameters: {limit: 9}, outputs: {y: n}}\n"
     "  - {name: k, type: Compare, parameters: {operator: '>', value: 2.5}, inputs: {u: n}, outputs: {y: big}}\n",
     "m.yaml:6:65: error: type mismatch: parameter 'value' of block 'k' (Compare) is 2.5, which is not a value of "
     "uint32 (a Compare compares in its input's type, uint32: give a value of that type, or convert the input)\n"},
    {"integrator_on_an_integer", "",
     "  - {name: c, type: Counter, parameters: {limit: 9}, outputs: {y: n}}\n"
     "  - {name: i, type: DiscreteIntegrator, inputs: {u: n}, outputs: {y: sum}}\n",
     "m.yaml:6:50: error: type mismatch: block 'i' (DiscreteIntegrator) computes in floating point, but input 'u' "
     "(signal 'n') is uint32 (convert it to single or double with a Convert block)\n"},
    {"pid_on_an_integer", "",
     "  - {name: c, type: Constant, parameters: {value: 3, type: int16}, outputs: {y: e}}\n"
     "  - {name: pid, type: DiscretePid, parameters: {p: 2}, inputs: {error: e}, outputs: {y: u}}\n",
     "m.yaml:6:65: error: type mismatch: block 'pid' (DiscretePid) computes in floating point, but input 'error' "
     "(signal 'e') is int16 (convert it to single or double with a Convert block)\n"},
    {"gpio_out_fed_a_double", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: led, type: GpioOut, parameters: {pin: PA5}, inputs: {u: x}}\n",
     "m.yaml:6:65: error: type mismatch: block 'led' (GpioOut) writes a boolean, but input 'u' (signal 'x') is double "
     "(compare the value (Compare) or convert it to boolean)\n"},
    {"matrix_multiply_inner_sizes", "",
     "  - {name: a, type: Constant, parameters: {value: [[1, 2, 3], [4, 5, 6]]}, outputs: {y: m}}\n"
     "  - {name: b, type: Constant, parameters: {value: [1, 2]}, outputs: {y: v}}\n"
     "  - {name: p, type: MatrixMultiply, inputs: {a: m, b: v}, outputs: {y: y}}\n",
     "m.yaml:7:52: error: size mismatch: block 'p' (MatrixMultiply) multiplies double[2x3] by double[2] (the columns "
     "of a must equal the rows of b; a vector is a column)\n"},
    {"demux_with_more_outputs_than_elements", "",
     "  - {name: c, type: Constant, parameters: {value: [1, 2]}, outputs: {y: v}}\n"
     "  - {name: d, type: Demux, inputs: {u: v}, outputs: {y1: a, y2: b, y3: c}}\n",
     "m.yaml:6:68: error: size mismatch: output 'y3' of block 'd' (Demux) is element 3 of input 'u' (signal 'v'), "
     "which is double[2] (output yN carries element N: connect y1 to y2 only)\n"},
    {"demux_output_beyond_the_elements", "",
     "  - {name: c, type: Constant, parameters: {value: [1, 2]}, outputs: {y: v}}\n"
     "  - {name: d, type: Demux, inputs: {u: v}, outputs: {y4: last}}\n",
     "m.yaml:6:54: error: size mismatch: output 'y4' of block 'd' (Demux) is element 4 of input 'u' (signal 'v'), "
     "which is double[2] (output yN carries element N: connect y1 to y2 only)\n"},
    {"atan2_of_two_types", "",
     "  - {name: a, type: Constant, parameters: {value: 1}, outputs: {y: y}}\n"
     "  - {name: b, type: Constant, parameters: {value: 2, type: single}, outputs: {y: x}}\n"
     "  - {name: t, type: Atan2, inputs: {y_in: y, x_in: x}, outputs: {y: angle}}\n",
     "m.yaml:7:46: error: type mismatch: input 'x_in' (signal 'x') of block 't' (Atan2) is single, but input 'y_in' "
     "(signal 'y') is double (convert one of them with a Convert block)\n"},
    {"mux_of_two_types", "",
     "  - {name: a, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: pin, type: GpioIn, parameters: {pin: PA0}, outputs: {y: pressed}}\n"
     "  - {name: m, type: Mux, inputs: {u1: x, u2: pressed}, outputs: {y: both}}\n",
     "m.yaml:7:42: error: type mismatch: input 'u2' (signal 'pressed') of block 'm' (Mux) is boolean, but input 'u1' "
     "(signal 'x') is double (convert one of them with a Convert block)\n"},
    {"saturation_of_a_boolean", "",
     "  - {name: pin, type: GpioIn, parameters: {pin: PA0}, outputs: {y: pressed}}\n"
     "  - {name: s, type: Saturation, parameters: {lower: 0, upper: 1}, inputs: {u: pressed}, outputs: {y: y}}\n",
     "m.yaml:6:76: error: type mismatch: block 's' (Saturation) does arithmetic, but input 'u' (signal 'pressed') is "
     "boolean (convert it to a number with a Convert block)\n"},
    {"boolean_counter", "", "  - {name: c, type: Counter, parameters: {limit: 1, type: boolean}, outputs: {y: n}}\n",
     "m.yaml:5:59: error: type mismatch: block 'c' (Counter) cannot count in boolean (give it an integer type, or "
     "leave out 'type' for uint32)\n"},
    {"unknown_data_type", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: k, type: Convert, parameters: {type: int9}, inputs: {u: x}, outputs: {y: y}}\n",
     "m.yaml:6:49: error: parameter 'type' of block 'k' (Convert) is 'int9', which is not a data type (did you mean "
     "'int8'?)\n"},
    {"unknown_compare_operator", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: k, type: Compare, parameters: {operator: '=<', value: 0}, inputs: {u: x}, outputs: {y: y}}\n",
     "m.yaml:6:53: error: block 'k' (Compare) has no operator '=<' (its operators: <, <=, ==, !=, >= and >)\n"},
    {"unknown_logic_operator", "",
     "  - {name: a, type: GpioIn, parameters: {pin: PA0}, outputs: {y: p}}\n"
     "  - {name: b, type: GpioIn, parameters: {pin: PA1}, outputs: {y: q}}\n"
     "  - {name: l, type: Logic, parameters: {operator: and}, inputs: {u1: p, u2: q}, outputs: {y: y}}\n",
     "m.yaml:7:51: error: block 'l' (Logic) has no operator 'and' (did you mean 'AND'?)\n"},
    {"signs_for_another_number_of_inputs", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: s, type: Sum, parameters: {signs: '+-+'}, inputs: {u1: x, u2: x}, outputs: {y: y}}\n",
     "m.yaml:6:46: error: signs '+-+' of block 's' (Sum) give 3 signs for 2 inputs (one + or - per input, u1 first)\n"},
    {"logic_of_two_sizes", "",
     "  - {name: a, type: Constant, parameters: {value: [1, 0, 1], type: boolean}, outputs: {y: p}}\n"
     "  - {name: b, type: Constant, parameters: {value: [1, 0], type: boolean}, outputs: {y: q}}\n"
     "  - {name: l, type: Logic, parameters: {operator: OR}, inputs: {u1: p, u2: q}, outputs: {y: y}}\n",
     "m.yaml:7:72: error: size mismatch: input 'u2' (signal 'q') of block 'l' (Logic) is boolean[2], but input 'u1' "
     "(signal 'p') is boolean[3] (a Logic works element by element on inputs of one size)\n"},
    {"switch_condition_of_another_size", "",
     "  - {name: a, type: Constant, parameters: {value: [1, 2, 3]}, outputs: {y: on}}\n"
     "  - {name: b, type: Constant, parameters: {value: [4, 5, 6]}, outputs: {y: off}}\n"
     "  - {name: c, type: Constant, parameters: {value: [1, 0], type: boolean}, outputs: {y: which}}\n"
     "  - {name: s, type: Switch, inputs: {on: on, condition: which, off: off}, outputs: {y: chosen}}\n",
     "m.yaml:8:46: error: size mismatch: input 'condition' (signal 'which') of block 's' (Switch) is boolean[2], but "
     "input 'on' (signal 'on') is double[3] (give one condition, or one per element)\n"},
    {"constant_parameter_of_another_type", "parameters:\n  K: 2\n",
     "  - {name: c, type: Constant, parameters: {value: K, type: int8}, outputs: {y: x}}\n",
     "m.yaml:7:51: error: type mismatch: parameter 'K' is double but block 'c' (Constant) has type: int8 (declare 'K' "
     "with type: int8, or leave out the Constant's type)\n"},
    {"rate_transition_initial_beyond_its_type", "",
     "  - {name: c, type: Counter, parameters: {limit: 9, type: uint8}, outputs: {y: n}}\n"
     "  - {name: t, type: RateTransition, period: {multiple: 4}, parameters: {initial: -1}, inputs: {u: n},"
     " outputs: {y: slow}}\n",
     "m.yaml:6:82: error: type mismatch: parameter 'initial' of block 't' (RateTransition) is -1, which is not a value "
     "of uint8 (the block computes in its input's type, uint8: give a value of that type, or convert the input)\n"},
    {"unknown_rate_transition_mode", "",
     "  - {name: c, type: Counter, parameters: {limit: 9}, outputs: {y: n}}\n"
     "  - {name: t, type: RateTransition, period: {multiple: 4}, parameters: {mode: fastest}, inputs: {u: n},"
     " outputs: {y: slow}}\n",
     "m.yaml:6:79: error: block 't' (RateTransition) has no mode 'fastest' (its modes: deterministic, between periodic "
     "rates, and latest, with an interrupt task)\n"},
    {"signs_other_than_plus_and_minus", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: s, type: Sum, parameters: {signs: '+*'}, inputs: {u1: x, u2: x}, outputs: {y: y}}\n",
     "m.yaml:6:46: error: signs '+*' of block 's' (Sum) are not all + or - (one + or - per input, u1 first: '+-' is u1 "
     "- u2)\n"},
    {"selector_index_of_several_elements", "",
     "  - {name: c, type: Constant, parameters: {value: [1, 2, 3]}, outputs: {y: v}}\n"
     "  - {name: i, type: Constant, parameters: {value: [0, 1], type: uint8}, outputs: {y: at}}\n"
     "  - {name: s, type: Selector, inputs: {u: v, index: at}, outputs: {y: y}}\n",
     "m.yaml:7:46: error: size mismatch: input 'index' (signal 'at') of block 's' (Selector) is uint8[2] (a Selector "
     "takes one index, a scalar)\n"},
    {"declared_type_through_a_loop_that_converts", "signals:\n  acc: {type: single}\n",
     "  - {name: delay, type: UnitDelay, inputs: {u: next}, outputs: {y: acc}}\n"
     "  - {name: k, type: Convert, parameters: {type: int8}, inputs: {u: acc}, outputs: {y: next}}\n",
     "m.yaml:5:3: error: type mismatch: signal 'acc' is declared single but block 'delay' (UnitDelay) drives it with "
     "int8 (declare it as int8, or convert it with a Convert block)\n"},
    {"loop_guessed_scalar_but_vector", "",
     "  - {name: n, type: Not, inputs: {u: old}, outputs: {y: x}}\n"
     "  - {name: m, type: Mux, inputs: {u1: x, u2: x}, outputs: {y: pair}}\n"
     "  - {name: d, type: UnitDelay, inputs: {u: pair}, outputs: {y: old}}\n",
     "m.yaml:5:54: error: type mismatch: block 'n' (Not) drives signal 'x' with boolean[2], but the loop it is in was "
     "taken for boolean before its inputs were known (a loop gives each signal one type and size all the way round; if "
     "this one does, declare it: signals: {x: {type: boolean, size: 2}})\n"},
    {"rate_transition_of_a_constant", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: one}}\n"
     "  - {name: t, type: RateTransition, period: {multiple: 4}, inputs: {u: one}, outputs: {y: slow}}\n",
     "m.yaml:6:5: error: block 't' (RateTransition) reads signal 'one' of block 'c', a constant (every rate reads a "
     "constant directly: remove the RateTransition)\n"},
    {"rate_transition_between_rates_not_multiples", "",
     "  - {name: c, type: Counter, parameters: {limit: 9}, period: {multiple: 2}, outputs: {y: n}}\n"
     "  - {name: t, type: RateTransition, period: {multiple: 5}, inputs: {u: n}, outputs: {y: m}}\n"
     "  - {name: g, type: Convert, parameters: {type: double}, inputs: {u: m}, outputs: {y: x}}\n",
     "m.yaml:6:5: error: RateTransition 't' joins rates of 200 us and 500 us, which are not multiples of each other "
     "(make the slower period a multiple of the faster, or pass the value through a rate both divide)\n"},
    {"rate_transition_latest_between_periodic_rates", "",
     "  - {name: c, type: Counter, parameters: {limit: 9}, outputs: {y: n}}\n"
     "  - {name: t, type: RateTransition, period: {multiple: 4}, parameters: {mode: latest}, inputs: {u: n}, "
     "outputs: {y: m}}\n"
     "  - {name: g, type: Convert, parameters: {type: double}, inputs: {u: m}, outputs: {y: x}}\n",
     "m.yaml:6:79: error: RateTransition 't' joins two periodic rates, where the transfer is deterministic (write "
     "mode: deterministic, or leave mode out; latest is for interrupt tasks)\n"},
    {"rate_transition_deterministic_to_an_interrupt", "",
     "  - {name: c, type: Counter, parameters: {limit: 9}, outputs: {y: n}}\n"
     "  - name: isr\n    type: Subsystem\n    trigger: {interrupt: UART0_RX, priority: 2}\n    inputs: {count: "
     "n_latest}\n"
     "    blocks:\n"
     "      - {name: pin, type: Compare, parameters: {operator: \">\", value: 3}, inputs: {u: count}, outputs: {y: "
     "high}}\n"
     "  - {name: t, type: RateTransition, parameters: {mode: deterministic}, inputs: {u: n}, outputs: {y: n_latest}}\n",
     "m.yaml:12:56: error: RateTransition 't' joins 100 us and interrupt UART0_RX, which share no time base: it cannot "
     "be deterministic (write mode: latest, or leave mode out)\n"},
    {"enabled_by_a_double", "",
     "  - {name: n, type: Counter, parameters: {limit: 3}, outputs: {y: n}}\n"
     "  - {name: level, type: Convert, parameters: {type: double}, inputs: {u: n}, outputs: {y: level}}\n"
     "  - name: s\n    type: Subsystem\n    enable: level\n    blocks:\n"
     "      - {name: c, type: Counter, parameters: {limit: 9}, outputs: {y: m}}\n",
     "m.yaml:7:5: error: type mismatch: subsystem 's' is enabled by signal 'level', which is double (an enabling "
     "signal is one boolean: make it with a Compare block)\n"},
    {"byte_unpack_past_its_input", "",
     "  - {name: c, type: Constant, parameters: {value: 1, type: single}, outputs: {y: x}}\n"
     "  - {name: p, type: BytePack, inputs: {u1: x}, outputs: {y: bytes}}\n"
     "  - {name: u, type: ByteUnpack, parameters: {type: uint32, offset: 2}, inputs: {u: bytes}, outputs: {y: n}}\n",
     "m.yaml:7:5: error: block 'u' (ByteUnpack) reads bytes 2 to 5 of input 'u' (signal 'bytes'), which has 4 (check "
     "offset, count and type)\n"},
    {"byte_unpack_of_doubles", "",
     "  - {name: c, type: Constant, parameters: {value: [1, 2]}, outputs: {y: x}}\n"
     "  - {name: u, type: ByteUnpack, parameters: {type: int16}, inputs: {u: x}, outputs: {y: n}}\n",
     "m.yaml:6:69: error: type mismatch: block 'u' (ByteUnpack) reads bytes, but input 'u' (signal 'x') is double[2] "
     "(give it uint8 elements (an SpiDma's, an IpcReceive's))\n"},
    {"product_signs_other_than_times_and_divide", "",
     "  - {name: c, type: Constant, parameters: {value: 2}, outputs: {y: x}}\n"
     "  - {name: p, type: Product, parameters: {signs: '*+'}, inputs: {u1: x, u2: x}, outputs: {y: y}}\n",
     "m.yaml:6:50: error: signs '*+' of block 'p' (Product) are not one * or / per input (u1 first: '*/' is u1 / "
     "u2)\n"},
    {"kalman_filter_r_of_the_wrong_size", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: m}}\n"
     "  - name: k\n    type: KalmanFilter\n"
     "    parameters: {a: [[1, 1], [0, 1]], c: [[1, 0]], g: [[0], [1]], q: [[1]], r: [[1, 0], [0, 1]]}\n"
     "    inputs: {measured: m}\n    outputs: {estimate: x}\n",
     "m.yaml:8:80: error: size mismatch: parameter 'r' of block 'k' (KalmanFilter) is 2x2, but it must be 1x1 "
     "(matrices are lists of rows; a vector input is a column)\n"},
    {"kalman_filter_with_gain_and_q", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: m}}\n"
     "  - name: k\n    type: KalmanFilter\n"
     "    parameters: {a: [[1, 1], [0, 1]], c: [[1, 0]], gain: [[0.5], [0.1]], q: [[1]]}\n"
     "    inputs: {measured: m}\n    outputs: {estimate: x}\n",
     "m.yaml:8:77: error: block 'k' (KalmanFilter) is given a steady-state gain and 'q' (give either gain (steady "
     "state) or g, q and r (time-varying))\n"},
    {"transfer_function_of_unequal_lengths", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: u}}\n"
     "  - name: h\n    type: TransferFunction\n"
     "    parameters: {numerator: [1, 0.5], denominator: [1, -0.5, 0.25]}\n"
     "    inputs: {u: u}\n    outputs: {y: y}\n",
     "m.yaml:8:52: error: block 'h' (TransferFunction) has 2 numerator and 3 denominator coefficients (give N+1 of "
     "each (order N >= 1, highest power of z first; pad the numerator with leading zeros))\n"},
    {"unknown_min_max_function", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: m, type: MinMax, parameters: {function: mid}, inputs: {u1: x, u2: x}, outputs: {y: y}}\n",
     "m.yaml:6:52: error: block 'm' (MinMax) has no function 'mid' (give min or max)\n"},
    {"tunable_pulse_period", "parameters:\n  T: 0.5\n",
     "  - {name: p, type: PulseGenerator, parameters: {period_s: T, width_s: 0.1}, outputs: {y: y}}\n",
     "m.yaml:7:60: error: parameter 'period_s' of block 'p' (PulseGenerator) names the tunable parameter 'T', but it "
     "sizes the generated code (give a number, or a constant (constants: in the model))\n"},
    {"moving_average_of_no_window", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: a, type: MovingAverage, parameters: {window: 0}, inputs: {u: x}, outputs: {y: y}}\n",
     "m.yaml:6:57: error: parameter 'window' of block 'a' (MovingAverage) must be one number, 1 or more (for example "
     "window: 1)\n"},
    {"pid_gain_as_input_and_parameter", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: a, type: DiscretePid, parameters: {p: 2}, inputs: {error: x, p: x}, outputs: {y: y}}\n",
     "m.yaml:6:50: error: block 'a' (DiscretePid) has both an input 'p' and a parameter 'p' (give the gain one way: "
     "the input (external) or the parameter)\n"},
    {"pid_gain_of_another_type", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: k, type: Constant, parameters: {value: 1, type: single}, outputs: {y: gain}}\n"
     "  - {name: a, type: DiscretePid, inputs: {error: x, p: gain}, outputs: {y: y}}\n",
     "m.yaml:7:53: error: type mismatch: input 'p' (signal 'gain') of block 'a' (DiscretePid) is single, but input "
     "'error' (signal 'x') is double (a gain is one value, or one per element, of the error's type)\n"},
    {"pid_reset_not_boolean", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: a, type: DiscretePid, parameters: {p: 2}, inputs: {error: x, reset: x}, outputs: {y: y}}\n",
     "m.yaml:6:73: error: type mismatch: input 'reset' (signal 'x') of block 'a' (DiscretePid) is double, but a reset "
     "is boolean (give one boolean, or one per element of the error (Compare gives a boolean))\n"},
    {"relational_unknown_operator", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: r, type: Relational, parameters: {operator: '=>'}, inputs: {u1: x, u2: x}, outputs: {y: y}}\n",
     "m.yaml:6:56: error: block 'r' (Relational) has no operator '=>' (its operators: <, <=, ==, !=, >= and "
     ">)\n"},
    {"relational_of_two_types", "",
     "  - {name: a, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: b, type: Constant, parameters: {value: 2, type: int16}, outputs: {y: z}}\n"
     "  - {name: r, type: Relational, parameters: {operator: '<'}, inputs: {u1: x, u2: z}, outputs: {y: y}}\n",
     "m.yaml:7:78: error: type mismatch: input 'u2' (signal 'z') of block 'r' (Relational) is int16, but input "
     "'u1' (signal 'x') is double (convert one of them with a Convert block)\n"},
    {"relational_of_two_sizes", "",
     "  - {name: a, type: Constant, parameters: {value: [1, 2]}, outputs: {y: x}}\n"
     "  - {name: b, type: Constant, parameters: {value: [1, 2, 3]}, outputs: {y: z}}\n"
     "  - {name: r, type: Relational, parameters: {operator: '<'}, inputs: {u1: x, u2: z}, outputs: {y: y}}\n",
     "m.yaml:7:78: error: size mismatch: input 'u2' (signal 'z') of block 'r' (Relational) is double[3], but "
     "input 'u1' (signal 'x') is double[2] (compare inputs of one size, or one of them with a scalar)\n"},
    {"dead_zone_start_above_end", "",
     "  - {name: c, type: Constant, parameters: {value: [1, 2]}, outputs: {y: x}}\n"
     "  - {name: d, type: DeadZone, parameters: {start: [-1, 0.5], end: 0.25}, inputs: {u: x}, outputs: {y: y}}\n",
     "m.yaml:6:51: error: parameter 'start' of block 'd' (DeadZone) is 0.5, above its end, 0.25 (the dead zone "
     "is start..end: give start <= end)\n"},
    {"dead_zone_of_integers", "",
     "  - {name: c, type: Constant, parameters: {value: 1, type: int16}, outputs: {y: x}}\n"
     "  - {name: d, type: DeadZone, parameters: {start: -1, end: 1}, inputs: {u: x}, outputs: {y: y}}\n",
     "m.yaml:6:73: error: type mismatch: block 'd' (DeadZone) computes in floating point, but input 'u' "
     "(signal 'x') is int16 (convert it to single or double with a Convert block)\n"},
    {"interpolation_of_one_breakpoint", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: f, type: Interpolation, parameters: {breakpoints: [0], table: [1]}, inputs: {u: x}, outputs: {y: "
     "y}}\n",
     "m.yaml:6:62: error: parameter 'breakpoints' of block 'f' (Interpolation) has 1 value, but it needs at "
     "least 2 (give two or more breakpoints in increasing order)\n"},
    {"interpolation_breakpoints_not_increasing", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: f, type: Interpolation, parameters: {breakpoints: [0, 1, 1, 2], table: [1, 2, 3, 4]}, inputs: {u: x},"
     " outputs: {y: y}}\n",
     "m.yaml:6:62: error: parameter 'breakpoints' of block 'f' (Interpolation) does not increase strictly: 1 "
     "follows 1 (each breakpoint must be above the one before)\n"},
    {"interpolation_table_of_another_size", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: f, type: Interpolation, parameters: {breakpoints: [0, 1, 2], table: [1, 2]}, inputs: {u: x},"
     " outputs: {y: y}}\n",
     "m.yaml:6:80: error: size mismatch: parameter 'table' of block 'f' (Interpolation) has 2 values for 3 "
     "breakpoints (give one table value per breakpoint)\n"},
    {"interpolation_flat_extrapolated_linearly", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: f, type: Interpolation, parameters: {breakpoints: [0, 1], table: [1, 2], method: flat,"
     " extrapolation: linear}, inputs: {u: x}, outputs: {y: y}}\n",
     "m.yaml:6:114: error: block 'f' (Interpolation) extrapolates linearly, but its method is 'flat', which "
     "does not interpolate (give method: linear, or leave out extrapolation (clip))\n"},
    {"interpolation_unknown_method", "",
     "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
     "  - {name: f, type: Interpolation, parameters: {breakpoints: [0, 1], table: [1, 2], method: cubic},"
     " inputs: {u: x}, outputs: {y: y}}\n",
     "m.yaml:6:93: error: block 'f' (Interpolation) has no method 'cubic' (give linear or nearest or flat or "
     "above)\n"},
    {"interpolation_table_of_another_type", "parameters:\n  t: {value: [1, 2], type: double}\n",
     "  - {name: c, type: Constant, parameters: {value: 1, type: single}, outputs: {y: x}}\n"
     "  - {name: f, type: Interpolation, parameters: {breakpoints: [0, 1], table: t}, inputs: {u: x},"
     " outputs: {y: y}}\n",
     "m.yaml:8:77: error: type mismatch: parameter 't' is double[2] but block 'f' (Interpolation) computes in "
     "single (declare 't' with type: single)\n"},
};

class Mistyped : public ::testing::TestWithParam<Case> {};

TEST_P(Mistyped, GetsItsMessages) {
  EXPECT_EQ(diagnostics_of(GetParam().blocks, GetParam().header), GetParam().messages);
}

INSTANTIATE_TEST_SUITE_P(TypingCorpus, Mistyped, ::testing::ValuesIn(cases),
                         [](const auto& test) { return std::string{test.param.name}; });

// A Code block's header must be beside the model: the model pretends to live in a folder of its own with one.
class TypingCode : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = std::filesystem::temp_directory_path() /
              ("duet_typing_" + std::string{::testing::UnitTest::GetInstance()->current_test_info()->name()});
    std::filesystem::create_directories(folder_);
    std::ofstream{folder_ / "logic.hpp"} << "// declared for the test\n";
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  [[nodiscard]] std::string file() const { return (folder_ / "m.yaml").string(); }

 private:
  std::filesystem::path folder_;
};

TEST_F(TypingCode, AnInputDeclaredOfAnotherTypeThanItsSignal) {
  EXPECT_EQ(diagnostics_of("  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
                           "  - {name: logic, type: Code, function: f, file: logic.hpp,\n"
                           "     inputs: {up: {signal: x, type: double}, u1: {signal: x, type: single}},\n"
                           "     outputs: {y: {signal: y, type: single, size: 2}}}\n"
                           "  - {name: g, type: Gain, parameters: {k: 2}, inputs: {u: y}, outputs: {y: z}}\n",
                           "", file()),
            "m.yaml:7:46: error: type mismatch: input 'u1' of block 'logic' (Code) is declared single but signal 'x' "
            "is double (declare the port as the signal is, or convert the signal)\n");
}

TEST_F(TypingCode, ParametersAndStateHoldValuesOfTheirTypes) {
  EXPECT_EQ(
      diagnostics_of("  - {name: logic, type: Code, function: f, file: logic.hpp,\n"
                     "     outputs: {y: {signal: y, type: single}},\n"
                     "     parameters: {limit: {value: 300, type: int8}},\n"
                     "     state: {last: {type: single, size: 2, initial: [1, 2, 3]}}}\n",
                     "", file()),
      "m.yaml:7:26: error: type mismatch: parameter 'limit' of block 'logic' (Code) is 300, which is not a "
      "value of int8 (give a value of int8, or declare another type)\n"
      "m.yaml:8:14: error: size mismatch: state 'last' of block 'logic' (Code) has 3 values for single[2] (give a "
      "scalar, or one value per element)\n");
}

TEST_F(TypingCode, OutputsAreWhatTheBlockDeclares) {
  const auto model =
      parse_model(model_text("  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
                             "  - {name: logic, type: Code, function: f, file: logic.hpp,\n"
                             "     inputs: {u2: {signal: x, type: double}, u1: {signal: x, type: double}},\n"
                             "     outputs: {y: {signal: y, type: int16, size: [2, 3]}}}\n",
                             ""),
                  file());
  ASSERT_TRUE(model.ok()) << model.error();
  const ProgramBuild build = build_program(model.value());
  ASSERT_TRUE(build.program) << format("m.yaml", build.diagnostics.front());
  EXPECT_EQ(describe(build.program->signals[*build.program->find_signal("y")].type), "int16[2x3]");
  // The function takes its inputs as the model lists them, whatever their names.
  const ProgramBlock& logic = build.program->blocks[1];
  EXPECT_EQ(logic.input_ports, (std::vector<std::string>{"u2", "u1"}));
}

// What build_program makes of a valid model: the signals' types by name.
class Typed {
 public:
  explicit Typed(const std::string& blocks, const std::string& header = {}) : model_(std::make_unique<Model>()) {
    auto parsed = parse_model(model_text(blocks, header), "m.yaml");
    if (!parsed.ok()) {
      ADD_FAILURE() << parsed.error();
      return;
    }
    *model_ = std::move(parsed.value());
    ProgramBuild build = build_program(*model_);
    for (const Diagnostic& diagnostic : build.diagnostics) ADD_FAILURE() << format("m.yaml", diagnostic);
    program_ = std::move(build.program);
  }

  // "double", "int16[3]", ...; "?" for a signal the model does not have.
  [[nodiscard]] std::string type_of(const std::string& signal) const {
    if (!program_) return "(no program)";
    const auto index = program_->find_signal(signal);
    return index ? describe(program_->signals[*index].type) : "?";
  }

 private:
  std::unique_ptr<Model> model_;  // the program points into it
  std::optional<Program> program_;
};

TEST(Typing, AConvertGivesItsTypeAtTheInputsSize) {
  const Typed typed{
      "  - {name: c, type: Constant, parameters: {value: [1.5, 2.5]}, outputs: {y: x}}\n"
      "  - {name: k, type: Convert, parameters: {type: int16}, inputs: {u: x}, outputs: {y: y}}\n"};
  EXPECT_EQ(typed.type_of("x"), "double[2]");
  EXPECT_EQ(typed.type_of("y"), "int16[2]");
}

TEST(Typing, AMuxCountsTheElementsOfItsInputs) {
  const Typed typed{
      "  - {name: a, type: Constant, parameters: {value: 1, type: single}, outputs: {y: a}}\n"
      "  - {name: b, type: Constant, parameters: {value: 2, type: single}, outputs: {y: b}}\n"
      "  - {name: c, type: Constant, parameters: {value: [3, 4, 5], type: single}, outputs: {y: c}}\n"
      "  - {name: m, type: Mux, inputs: {u1: a, u2: b, u3: c}, outputs: {y: all}}\n"
      "  - {name: d, type: Demux, inputs: {u: all}, outputs: {y1: first, y4: fourth}}\n"};
  EXPECT_EQ(typed.type_of("all"), "single[5]");
  EXPECT_EQ(typed.type_of("first"), "single");
  EXPECT_EQ(typed.type_of("fourth"), "single");
}

TEST(Typing, SourcesHaveTheirOwnTypes) {
  const Typed typed{
      "  - {name: n, type: Counter, parameters: {limit: 9}, outputs: {y: n}}\n"
      "  - {name: m, type: Counter, parameters: {limit: 9, type: int8}, outputs: {y: m}}\n"
      "  - {name: pin, type: GpioIn, parameters: {pin: PA0}, outputs: {y: pressed}}\n"
      "  - {name: c, type: Constant, parameters: {value: [[1, 2], [3, 4]]}, outputs: {y: c}}\n"};
  EXPECT_EQ(typed.type_of("n"), "uint32");
  EXPECT_EQ(typed.type_of("m"), "int8");
  EXPECT_EQ(typed.type_of("pressed"), "boolean");
  EXPECT_EQ(typed.type_of("c"), "double[2x2]");
}

TEST(Typing, ACompareGivesBooleansOfItsInputsSize) {
  const Typed typed{
      "  - {name: c, type: Constant, parameters: {value: [1, 2, 3], type: int16}, outputs: {y: x}}\n"
      "  - {name: k, type: Compare, parameters: {operator: '>=', value: 2}, inputs: {u: x},"
      " outputs: {y: big}}\n"
      "  - {name: n, type: Not, inputs: {u: big}, outputs: {y: small}}\n"};
  EXPECT_EQ(typed.type_of("big"), "boolean[3]");
  EXPECT_EQ(typed.type_of("small"), "boolean[3]");
}

TEST(Typing, ARelationalGivesBooleansOfTheLargerInput) {
  const Typed typed{
      "  - {name: a, type: Constant, parameters: {value: [1, 2, 3], type: uint8}, outputs: {y: x}}\n"
      "  - {name: b, type: Constant, parameters: {value: 2, type: uint8}, outputs: {y: s}}\n"
      "  - {name: r, type: Relational, parameters: {operator: '<'}, inputs: {u1: s, u2: x}, outputs: {y: below}}\n"
      "  - {name: q, type: Relational, parameters: {operator: '=='}, inputs: {u1: s, u2: s}, outputs: {y: same}}\n"};
  EXPECT_EQ(typed.type_of("below"), "boolean[3]");
  EXPECT_EQ(typed.type_of("same"), "boolean");
}

TEST(Typing, DeadZoneAndInterpolationComputeInTheirInputsType) {
  const Typed typed{
      "  - {name: a, type: Constant, parameters: {value: [1, 2], type: single}, outputs: {y: x}}\n"
      "  - {name: d, type: DeadZone, parameters: {start: -1, end: 1}, inputs: {u: x}, outputs: {y: zoned}}\n"
      "  - {name: f, type: Interpolation, parameters: {breakpoints: [0, 1], table: [5, 6]}, inputs: {u: x},"
      " outputs: {y: looked}}\n"};
  EXPECT_EQ(typed.type_of("zoned"), "single[2]");
  EXPECT_EQ(typed.type_of("looked"), "single[2]");
}

TEST(Typing, AMatrixTimesAVectorIsAVector) {
  const Typed typed{
      "  - {name: a, type: Constant, parameters: {value: [[1, 2], [3, 4]]}, outputs: {y: m}}\n"
      "  - {name: b, type: Constant, parameters: {value: [5, 6]}, outputs: {y: v}}\n"
      "  - {name: c, type: Constant, parameters: {value: [[1, 0, 2], [0, 1, 3]]}, outputs: {y: w}}\n"
      "  - {name: p, type: MatrixMultiply, inputs: {a: m, b: v}, outputs: {y: mv}}\n"
      "  - {name: q, type: MatrixMultiply, inputs: {a: m, b: w}, outputs: {y: mw}}\n"};
  EXPECT_EQ(typed.type_of("mv"), "double[2]");
  EXPECT_EQ(typed.type_of("mw"), "double[2x3]");
}

TEST(Typing, ALookupHasItsTablesTypeAndTheTunableParametersTypeReachesItsReaders) {
  const Typed typed{
      "  - {name: i, type: Counter, parameters: {limit: 3, type: uint8}, outputs: {y: i}}\n"
      "  - {name: l, type: Lookup, parameters: {table: T}, inputs: {index: i}, outputs: {y: y}}\n"
      "  - {name: k, type: Constant, parameters: {value: K}, outputs: {y: k}}\n"
      "  - {name: g, type: Gain, parameters: {k: K}, inputs: {u: k}, outputs: {y: kk}}\n",
      "parameters:\n  T: {value: [1, 2, 4, 8], type: int32}\n  K: {value: [1, 2], type: single}\n"};
  EXPECT_EQ(typed.type_of("y"), "int32");
  EXPECT_EQ(typed.type_of("k"), "single[2]");
  EXPECT_EQ(typed.type_of("kk"), "single[2]");
}

TEST(Typing, AFeedbackLoopThroughNotIsBooleanWithoutComplaint) {
  const Typed typed{
      "  - {name: toggle, type: Not, inputs: {u: old}, outputs: {y: state}}\n"
      "  - {name: delay, type: UnitDelay, parameters: {initial: true}, inputs: {u: state},"
      " outputs: {y: old}}\n"
      "  - {name: pin, type: GpioOut, parameters: {pin: PA5}, inputs: {u: state}}\n"};
  EXPECT_EQ(typed.type_of("state"), "boolean");
  EXPECT_EQ(typed.type_of("old"), "boolean");
}

TEST(Typing, ADeclaredTypeSeedsALoopThatNothingElseTypes) {
  const Typed typed{
      "  - {name: delay, type: UnitDelay, inputs: {u: next}, outputs: {y: acc}}\n"
      "  - {name: twice, type: Sum, inputs: {u1: acc, u2: acc}, outputs: {y: next}}\n",
      "signals:\n  acc: {type: single, size: 2}\n"};
  EXPECT_EQ(typed.type_of("acc"), "single[2]");
  EXPECT_EQ(typed.type_of("next"), "single[2]");
}

TEST(Typing, ALoopNothingTypesIsDouble) {
  const Typed typed{
      "  - {name: delay, type: UnitDelay, inputs: {u: next}, outputs: {y: acc}}\n"
      "  - {name: twice, type: Sum, inputs: {u1: acc, u2: acc}, outputs: {y: next}}\n"};
  EXPECT_EQ(typed.type_of("acc"), "double");
}

TEST(Typing, TypesCrossSubsystemsAndRateTransitions) {
  const Typed typed{
      "  - {name: c, type: Counter, parameters: {limit: 9, type: int8}, outputs: {y: n}}\n"
      "  - {name: t, type: RateTransition, period: {multiple: 4}, inputs: {u: n}, outputs: {y: slow}}\n"
      "  - name: s\n    type: Subsystem\n    inputs: {in: slow}\n    outputs: {out: doubled}\n"
      "    blocks:\n"
      "      - {name: g, type: Gain, parameters: {k: 2}, inputs: {u: in}, outputs: {y: out}}\n"};
  EXPECT_EQ(typed.type_of("slow"), "int8");
  EXPECT_EQ(typed.type_of("doubled"), "int8");  // the subsystem's output is the parent's signal
}

}  // namespace
}  // namespace duet::model
