// Simulation: small models run through model::simulate (the lock-step executive) or the Interpreter, their values
// checked step by step against hand computation. Where the order of floating-point operations matters, the expected
// values come from the block library itself (duet/blocks), which is what generated code calls too.
#include "duet/model/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "duet/blocks/arithmetic.hpp"
#include "duet/blocks/matrix.hpp"
#include "duet/blocks/state.hpp"
#include "duet/blocks/trigonometry.hpp"
#include "duet/model/interpreter.hpp"
#include "duet/model/model_file.hpp"
#include "duet/model/program.hpp"
#include "duet/plant/plant.hpp"

namespace duet::model {
namespace {

using Column = std::vector<double>;

// A model built from YAML text, kept together with the program that points into it.
class Built {
 public:
  explicit Built(const std::string& blocks, const std::string& header = {}, int base_period_us = 100)
      : model_(std::make_unique<Model>()) {
    auto parsed = parse_model("duet_model: 1\nname: m\nbase_period_us: " + std::to_string(base_period_us) + "\n" +
                                  header + "blocks:\n" + blocks,
                              "m.yaml");
    if (!parsed.ok()) {
      ADD_FAILURE() << parsed.error();
      return;
    }
    *model_ = std::move(parsed.value());
    ProgramBuild build = build_program(*model_);
    for (const Diagnostic& diagnostic : build.diagnostics) ADD_FAILURE() << format("m.yaml", diagnostic);
    program_ = std::move(build.program);
  }

  [[nodiscard]] bool ok() const { return program_.has_value(); }
  [[nodiscard]] const Program& program() const { return *program_; }
  [[nodiscard]] std::size_t signal(const std::string& name) const {
    const auto index = program_->find_signal(name);
    EXPECT_TRUE(index) << "no signal " << name;
    return index.value_or(0);
  }
  [[nodiscard]] std::size_t parameter(const std::string& name) const {
    for (std::size_t index = 0; index < model_->parameters.size(); ++index) {
      if (model_->parameters[index].name == name) return index;
    }
    ADD_FAILURE() << "no parameter " << name;
    return 0;
  }
  [[nodiscard]] double period_s() const { return model_->base_period_us * 1e-6; }

 private:
  std::unique_ptr<Model> model_;
  std::optional<Program> program_;
};

// `ticks` base ticks of the model against `plant`; the recorded columns by name ("x", or "v[0]", "v[1]", ...).
std::map<std::string, Column> run(const Built& built, plant::Plant& plant, const std::vector<std::string>& signals,
                                  int ticks, std::function<void(std::uint64_t, Interpreter&)> before_tick = {}) {
  std::map<std::string, Column> columns;
  if (!built.ok()) return columns;
  SimulationOptions options{(ticks - 1) * built.period_s(), signals, std::move(before_tick)};
  const auto result = simulate(built.program(), plant, options);
  if (!result.ok()) {
    ADD_FAILURE() << result.error();
    return columns;
  }
  const Recording& recording = result.value().recording;
  EXPECT_EQ(recording.time_s.size(), static_cast<std::size_t>(ticks));
  for (std::size_t k = 0; k < recording.names.size(); ++k) columns[recording.names[k]] = recording.columns[k];
  return columns;
}

std::map<std::string, Column> run(const Built& built, const std::vector<std::string>& signals, int ticks) {
  plant::Loopback plant;
  return run(built, plant, signals, ticks);
}

// x = 0, 1, 2, ... as a double, one step per base tick (a Counter converted).
constexpr const char* ramp =
    "  - {name: count, type: Counter, parameters: {limit: 1000}, outputs: {y: n}}\n"
    "  - {name: ramp, type: Convert, parameters: {type: double}, inputs: {u: n}, outputs: {y: x}}\n";

TEST(Simulation, RecordsOneRowPerBaseTickAtItsTime) {
  const Built built{ramp};
  plant::Loopback plant;
  const auto result = simulate(built.program(), plant, {10 * built.period_s(), {"x"}, {}});
  ASSERT_TRUE(result.ok()) << result.error();
  const Recording& recording = result.value().recording;
  ASSERT_EQ(recording.time_s.size(), 11U);
  EXPECT_EQ(result.value().ticks, 11U);
  for (std::size_t k = 0; k < recording.time_s.size(); ++k) {
    EXPECT_EQ(recording.time_s[k], static_cast<double>(k) * built.period_s());
  }
  EXPECT_EQ(recording.names, std::vector<std::string>{"x"});
  EXPECT_EQ(recording.columns[0], (Column{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
}

TEST(Simulation, DurationZeroGivesOneRow) {
  const Built built{ramp};
  plant::Loopback plant;
  const auto result = simulate(built.program(), plant, {0.0, {"x"}, {}});
  ASSERT_TRUE(result.ok()) << result.error();
  EXPECT_EQ(result.value().recording.time_s, Column{0.0});
  EXPECT_EQ(result.value().recording.columns, std::vector<Column>{{0.0}});
}

TEST(Simulation, TwoRunsGiveTheSameCsvBitForBit) {
  const Built built{std::string{ramp} +
                    "  - {name: w, type: Gain, parameters: {k: 0.1}, inputs: {u: x}, outputs: {y: w}}\n"
                    "  - {name: angle, type: Atan2, inputs: {y_in: w, x_in: x}, outputs: {y: angle}}\n"
                    "  - {name: i, type: DiscreteIntegrator, inputs: {u: angle}, outputs: {y: area}}\n"};
  plant::Loopback first_plant;
  plant::Loopback second_plant;
  const auto first = simulate(built.program(), first_plant, {0.05, {}, {}});
  const auto second = simulate(built.program(), second_plant, {0.05, {}, {}});
  ASSERT_TRUE(first.ok() && second.ok());
  EXPECT_EQ(to_csv(first.value().recording), to_csv(second.value().recording));
  EXPECT_EQ(to_csv(first.value().recording).substr(0, 23), "time_s,n,x,w,angle,area");
}

TEST(Simulation, AnUnknownSignalIsRefusedByName) {
  const Built built{ramp};
  plant::Loopback plant;
  const auto result = simulate(built.program(), plant, {1.0, {"x", "ramp_x"}, {}});
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error(), "the model has no signal 'ramp_x' (its signals: n, x)");
  const auto typo = simulate(built.program(), plant, {1.0, {"nn"}, {}});
  ASSERT_FALSE(typo.ok());
  EXPECT_EQ(typo.error(), "the model has no signal 'nn' (did you mean 'n'?)");
}

TEST(Simulation, TheMeasurableSignalsAreRecordedByDefault) {
  const Built built{ramp, "signals:\n  x: {unit: m, measurable: true}\n"};
  plant::Loopback plant;
  const auto result = simulate(built.program(), plant, {0.0, {}, {}});
  ASSERT_TRUE(result.ok()) << result.error();
  EXPECT_EQ(result.value().recording.names, std::vector<std::string>{"x"});
  EXPECT_EQ(result.value().recording.units, std::vector<std::string>{"m"});
}

// Constants: a literal and a model constant are computed once; a Constant naming a tunable parameter is that
// parameter, and every reader sees a new value from the step after it is written, constant readers too.
TEST(SimulationBlocks, ConstantsAndATunableParameter) {
  const Built built{std::string{ramp} +
                        "  - {name: literal, type: Constant, parameters: {value: 1.5}, outputs: {y: a}}\n"
                        "  - {name: named, type: Constant, parameters: {value: three}, outputs: {y: b}}\n"
                        "  - {name: tuned, type: Constant, parameters: {value: K}, outputs: {y: k}}\n"
                        "  - {name: scaled, type: Gain, parameters: {k: K}, inputs: {u: x}, outputs: {y: kx}}\n"
                        "  - {name: offset, type: Sum, inputs: {u1: a, u2: k}, outputs: {y: a_plus_k}}\n"
                        "  - {name: both, type: Sum, inputs: {u1: a, u2: b}, outputs: {y: a_plus_b}}\n",
                    "constants:\n  three: 3\nparameters:\n  K: 2\n"};
  const std::size_t k = built.parameter("K");
  plant::Loopback plant;
  const auto columns =
      run(built, plant, {"a", "b", "k", "kx", "a_plus_k", "a_plus_b"}, 7, [k](std::uint64_t tick, Interpreter& model) {
        if (tick == 2) model.set_parameter(k, 0, 5);
        if (tick == 4) model.use_reference_page(true);
        if (tick == 6) model.use_reference_page(false);
      });
  EXPECT_EQ(columns.at("a"), Column(7, 1.5));
  EXPECT_EQ(columns.at("b"), Column(7, 3));
  EXPECT_EQ(columns.at("k"), (Column{2, 2, 5, 5, 2, 2, 5}));
  EXPECT_EQ(columns.at("kx"), (Column{0, 2, 10, 15, 8, 10, 30}));
  EXPECT_EQ(columns.at("a_plus_k"), (Column{3.5, 3.5, 6.5, 6.5, 3.5, 3.5, 6.5}));
  EXPECT_EQ(columns.at("a_plus_b"), Column(7, 4.5));
}

TEST(SimulationBlocks, ParametersOfTheirOwnTypeOnTheInterpreter) {
  const Built built{
      "  - {name: n, type: Counter, parameters: {limit: 1000, type: int16}, outputs: {y: n}}\n"
      "  - {name: g, type: Gain, parameters: {k: K}, inputs: {u: n}, outputs: {y: y}}\n",
      "parameters:\n  K: {value: 3, type: int16}\n"};
  ASSERT_TRUE(built.ok());
  plant::Loopback plant;
  auto created = Interpreter::create(built.program(), plant);
  ASSERT_TRUE(created.ok()) << created.error();
  Interpreter& model = *created.value();
  model.initialize();
  const std::size_t y = built.signal("y");
  model.run_task(0);
  EXPECT_EQ(model.signal(y), 0);
  model.run_task(0);
  EXPECT_EQ(model.signal(y), 3);
  model.set_parameter(built.parameter("K"), 0, 40000);  // converted to int16: saturates
  model.run_task(0);
  EXPECT_EQ(model.signal(y), static_cast<std::int16_t>(2 * 32767));  // wraps as two's complement
  EXPECT_EQ(model.signal_bytes(y).size(), 2U);
  model.initialize();  // state back to the start; the working page keeps its value
  model.run_task(0);
  model.run_task(0);
  EXPECT_EQ(model.signal(y), 32767);
}

TEST(SimulationBlocks, GainScalarAndElementWise) {
  const Built built{std::string{ramp} +
                    "  - {name: half, type: Gain, parameters: {k: 0.5}, inputs: {u: x}, outputs: {y: half}}\n"
                    "  - {name: v, type: Mux, inputs: {u1: x, u2: x, u3: x}, outputs: {y: v}}\n"
                    "  - {name: g, type: Gain, parameters: {k: [2, -1, 0.25]}, inputs: {u: v}, outputs: {y: w}}\n"};
  const auto columns = run(built, {"half", "w"}, 4);
  EXPECT_EQ(columns.at("half"), (Column{0, 0.5, 1, 1.5}));
  EXPECT_EQ(columns.at("w[0]"), (Column{0, 2, 4, 6}));
  EXPECT_EQ(columns.at("w[1]"), (Column{0, -1, -2, -3}));
  EXPECT_EQ(columns.at("w[2]"), (Column{0, 0.25, 0.5, 0.75}));
}

TEST(SimulationBlocks, SumWithSignsAndProduct) {
  const Built built{std::string{ramp} +
                    "  - {name: ten, type: Constant, parameters: {value: 10}, outputs: {y: ten}}\n"
                    "  - {name: twice, type: Gain, parameters: {k: 2}, inputs: {u: x}, outputs: {y: x2}}\n"
                    "  - {name: s, type: Sum, parameters: {signs: '+-+'}, inputs: {u1: x, u2: x2, u3: ten},"
                    " outputs: {y: s}}\n"
                    "  - {name: t, type: Sum, parameters: {signs: '-+'}, inputs: {u1: x, u2: ten}, outputs: {y: t}}\n"
                    "  - {name: r, type: Sum, parameters: {signs: '|--'}, inputs: {u1: x, u2: ten}, outputs: {y: r}}\n"
                    "  - {name: plain, type: Sum, inputs: {u1: x, u2: x2, u3: ten}, outputs: {y: plain}}\n"
                    "  - {name: p, type: Product, inputs: {u1: x, u2: x2, u3: ten}, outputs: {y: p}}\n"};
  const auto columns = run(built, {"s", "t", "r", "plain", "p"}, 4);
  EXPECT_EQ(columns.at("s"), (Column{10, 9, 8, 7}));         // x - 2x + 10
  EXPECT_EQ(columns.at("t"), (Column{10, 9, 8, 7}));         // -x + 10
  EXPECT_EQ(columns.at("r"), (Column{-10, -11, -12, -13}));  // -x - 10
  EXPECT_EQ(columns.at("plain"), (Column{10, 13, 16, 19}));
  EXPECT_EQ(columns.at("p"), (Column{0, 20, 80, 180}));  // x * 2x * 10
}

TEST(SimulationBlocks, IntegerSumsWrap) {
  const Built built{
      "  - {name: n, type: Counter, parameters: {limit: 255, type: uint8, initial: 254}, outputs: {y: n}}\n"
      "  - {name: one, type: Constant, parameters: {value: 1, type: uint8}, outputs: {y: one}}\n"
      "  - {name: s, type: Sum, inputs: {u1: n, u2: one}, outputs: {y: s}}\n"
      "  - {name: d, type: Sum, parameters: {signs: '-+'}, inputs: {u1: n, u2: one}, outputs: {y: d}}\n"};
  const auto columns = run(built, {"n", "s", "d"}, 3);
  EXPECT_EQ(columns.at("n"), (Column{254, 255, 0}));
  EXPECT_EQ(columns.at("s"), (Column{255, 0, 1}));
  EXPECT_EQ(columns.at("d"), (Column{3, 2, 1}));  // 1 - n, modulo 256
}

// p, q = (0, 0), (0, 1), (1, 0), (1, 1) over ticks 0..3, from direct lookups of the step count.
constexpr const char* truth_table =
    "  - {name: count, type: Counter, parameters: {limit: 3}, outputs: {y: n}}\n"
    "  - {name: p, type: Lookup, parameters: {table: [0, 0, 1, 1]}, inputs: {index: n}, outputs: {y: p}}\n"
    "  - {name: q, type: Lookup, parameters: {table: Q}, inputs: {index: n}, outputs: {y: q}}\n";
constexpr const char* truth_header = "parameters:\n  Q: {value: [0, 1, 0, 1], type: boolean}\n";

TEST(SimulationBlocks, NotAndTheFiveLogicOperators) {
  std::string blocks = truth_table;
  for (const char* op : {"AND", "OR", "XOR", "NAND", "NOR"}) {
    blocks += "  - {name: l_" + std::string{op} + ", type: Logic, parameters: {operator: " + op +
              "}, inputs: {u1: p, u2: q}, outputs: {y: " + op + "}}\n";
  }
  blocks +=
      "  - {name: three, type: Logic, parameters: {operator: XOR}, inputs: {u1: p, u2: q, u3: NAND},"
      " outputs: {y: XOR3}}\n"
      "  - {name: not_p, type: Not, inputs: {u: p}, outputs: {y: not_p}}\n";
  const Built built{blocks, truth_header};
  const auto columns = run(built, {"AND", "OR", "XOR", "NAND", "NOR", "XOR3", "not_p", "q"}, 4);
  EXPECT_EQ(columns.at("q"), (Column{0, 1, 0, 1}));
  EXPECT_EQ(columns.at("AND"), (Column{0, 0, 0, 1}));
  EXPECT_EQ(columns.at("OR"), (Column{0, 1, 1, 1}));
  EXPECT_EQ(columns.at("XOR"), (Column{0, 1, 1, 0}));
  EXPECT_EQ(columns.at("NAND"), (Column{1, 1, 1, 0}));
  EXPECT_EQ(columns.at("NOR"), (Column{1, 0, 0, 0}));
  EXPECT_EQ(columns.at("XOR3"), (Column{1, 0, 0, 0}));  // p ^ q ^ !(p & q)
  EXPECT_EQ(columns.at("not_p"), (Column{1, 1, 0, 0}));
}

TEST(SimulationBlocks, TheSixComparisons) {
  std::string blocks = ramp;
  const std::vector<std::pair<std::string, std::string>> operators{{"lt", "<"},  {"le", "<="}, {"eq", "=="},
                                                                   {"ne", "!="}, {"ge", ">="}, {"gt", ">"}};
  for (const auto& [name, op] : operators) {
    blocks += "  - {name: " + name + ", type: Compare, parameters: {operator: '" + op +
              "', value: 2}, inputs: {u: x}, outputs: {y: " + name + "}}\n";
  }
  const Built built{blocks};
  const auto columns = run(built, {"lt", "le", "eq", "ne", "ge", "gt"}, 5);  // x = 0..4 against 2
  EXPECT_EQ(columns.at("lt"), (Column{1, 1, 0, 0, 0}));
  EXPECT_EQ(columns.at("le"), (Column{1, 1, 1, 0, 0}));
  EXPECT_EQ(columns.at("eq"), (Column{0, 0, 1, 0, 0}));
  EXPECT_EQ(columns.at("ne"), (Column{1, 1, 0, 1, 1}));
  EXPECT_EQ(columns.at("ge"), (Column{0, 0, 1, 1, 1}));
  EXPECT_EQ(columns.at("gt"), (Column{0, 0, 0, 1, 1}));
}

TEST(SimulationBlocks, SwitchSaturationAbs) {
  const Built built{std::string{ramp} +
                    "  - {name: odd, type: Lookup, parameters: {table: [0, 1, 0, 1, 0]}, inputs: {index: n},"
                    " outputs: {y: odd}}\n"
                    "  - {name: minus, type: Gain, parameters: {k: -1}, inputs: {u: x}, outputs: {y: minus_x}}\n"
                    "  - {name: s, type: Switch, inputs: {on: x, condition: odd, off: minus_x}, outputs: {y: s}}\n"
                    "  - {name: sat, type: Saturation, parameters: {lower: 1, upper: 3}, inputs: {u: x},"
                    " outputs: {y: sat}}\n"
                    "  - {name: abs, type: Abs, inputs: {u: minus_x}, outputs: {y: abs}}\n"};
  const auto columns = run(built, {"s", "sat", "abs"}, 5);
  EXPECT_EQ(columns.at("s"), (Column{-0.0, 1, -2, 3, -4}));
  EXPECT_EQ(columns.at("sat"), (Column{1, 1, 2, 3, 3}));
  EXPECT_EQ(columns.at("abs"), (Column{0, 1, 2, 3, 4}));
}

TEST(SimulationBlocks, Atan2AsTheBlockLibraryComputesIt) {
  const Built built{std::string{ramp} +
                    "  - {name: x_in, type: Constant, parameters: {value: -1.5, type: single}, outputs: {y: across}}\n"
                    "  - {name: k, type: Convert, parameters: {type: single}, inputs: {u: x}, outputs: {y: up}}\n"
                    "  - {name: t, type: Atan2, inputs: {y_in: up, x_in: across}, outputs: {y: angle}}\n"};
  const auto columns = run(built, {"angle"}, 4);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(columns.at("angle")[static_cast<std::size_t>(k)],
              static_cast<double>(blocks::atan2(static_cast<float>(k), -1.5F)));
  }
}

TEST(SimulationBlocks, ConvertSaturatesAndTruncates) {
  const Built built{
      "  - {name: count, type: Counter, parameters: {limit: 5}, outputs: {y: n}}\n"
      "  - {name: u, type: Lookup, parameters: {table: [-200.7, -3.9, 3.9, 127.5, 300, 0.5]},"
      " inputs: {index: n}, outputs: {y: u}}\n"
      "  - {name: to_int8, type: Convert, parameters: {type: int8}, inputs: {u: u}, outputs: {y: i8}}\n"
      "  - {name: to_uint8, type: Convert, parameters: {type: uint8}, inputs: {u: u}, outputs: {y: u8}}\n"
      "  - {name: to_bool, type: Convert, parameters: {type: boolean}, inputs: {u: u}, outputs: {y: b}}\n"
      "  - {name: back, type: Convert, parameters: {type: single}, inputs: {u: i8}, outputs: {y: f}}\n"};
  const auto columns = run(built, {"i8", "u8", "b", "f"}, 6);
  EXPECT_EQ(columns.at("i8"), (Column{-128, -3, 3, 127, 127, 0}));
  EXPECT_EQ(columns.at("u8"), (Column{0, 0, 3, 127, 255, 0}));
  EXPECT_EQ(columns.at("b"), (Column{1, 1, 1, 1, 1, 1}));
  EXPECT_EQ(columns.at("f"), (Column{-128, -3, 3, 127, 127, 0}));
}

TEST(SimulationBlocks, MuxDemuxSelector) {
  const Built built{std::string{ramp} +
                    "  - {name: c, type: Constant, parameters: {value: [10, 20]}, outputs: {y: c}}\n"
                    "  - {name: m, type: Mux, inputs: {u1: x, u2: c}, outputs: {y: v}}\n"
                    "  - {name: d, type: Demux, inputs: {u: v}, outputs: {y1: first, y3: third}}\n"
                    "  - {name: s, type: Selector, inputs: {u: v, index: n}, outputs: {y: picked}}\n"
                    "  - {name: back, type: Gain, parameters: {k: -1}, inputs: {u: x}, outputs: {y: minus_x}}\n"
                    "  - {name: s2, type: Selector, inputs: {u: v, index: minus_x}, outputs: {y: clamped}}\n"};
  const auto columns = run(built, {"v", "first", "third", "picked", "clamped"}, 5);
  EXPECT_EQ(columns.at("v[0]"), (Column{0, 1, 2, 3, 4}));
  EXPECT_EQ(columns.at("v[1]"), Column(5, 10));
  EXPECT_EQ(columns.at("v[2]"), Column(5, 20));
  EXPECT_EQ(columns.at("first"), (Column{0, 1, 2, 3, 4}));
  EXPECT_EQ(columns.at("third"), Column(5, 20));
  EXPECT_EQ(columns.at("picked"), (Column{0, 10, 20, 20, 20}));  // 0-based, clamped to the last
  EXPECT_EQ(columns.at("clamped"), (Column{0, 1, 2, 3, 4}));     // negative indexes read the first
}

TEST(SimulationBlocks, LookupInATunableTableClampsItsIndex) {
  const Built built{std::string{ramp} +
                        "  - {name: minus, type: Sum, parameters: {signs: '+-'}, inputs: {u1: x, u2: two},"
                        " outputs: {y: i}}\n"
                        "  - {name: two, type: Constant, parameters: {value: 2}, outputs: {y: two}}\n"
                        "  - {name: l, type: Lookup, parameters: {table: T}, inputs: {index: i}, outputs: {y: y}}\n",
                    "parameters:\n  T: {value: [5, 6, 7], type: int16}\n"};
  const std::size_t table = built.parameter("T");
  plant::Loopback plant;
  const auto columns = run(built, plant, {"y"}, 7, [table](std::uint64_t tick, Interpreter& model) {
    if (tick == 5) model.set_parameter(table, 2, -7);
  });
  EXPECT_EQ(columns.at("y"), (Column{5, 5, 5, 6, 7, -7, -7}));  // index -2, -1, 0, 1, 2, 3, 4; T[2] = -7 from tick 5
}

TEST(SimulationBlocks, RelationalComparesTwoSignalsAndExpandsAScalar) {
  const Built built{std::string{ramp} +
                    "  - {name: c, type: Constant, parameters: {value: [1, 3]}, outputs: {y: limits}}\n"
                    "  - {name: ge, type: Relational, parameters: {operator: '>='}, inputs: {u1: x, u2: limits},"
                    " outputs: {y: reached}}\n"
                    "  - {name: ne, type: Relational, parameters: {operator: '!='}, inputs: {u1: limits, u2: x},"
                    " outputs: {y: apart}}\n"};
  const auto columns = run(built, {"reached", "apart"}, 5);  // x = 0..4 against 1 and 3
  EXPECT_EQ(columns.at("reached[0]"), (Column{0, 1, 1, 1, 1}));
  EXPECT_EQ(columns.at("reached[1]"), (Column{0, 0, 0, 1, 1}));
  EXPECT_EQ(columns.at("apart[0]"), (Column{1, 0, 1, 1, 1}));
  EXPECT_EQ(columns.at("apart[1]"), (Column{1, 1, 1, 0, 1}));
}

TEST(SimulationBlocks, DeadZone) {
  const Built built{std::string{ramp} +
                    "  - {name: d, type: DeadZone, parameters: {start: 1, end: 3}, inputs: {u: x}, outputs: {y: y}}\n"
                    "  - {name: p, type: DeadZone, parameters: {start: 2, end: 2}, inputs: {u: x}, outputs: {y: z}}\n"};
  const auto columns = run(built, {"y", "z"}, 6);
  EXPECT_EQ(columns.at("y"), (Column{-1, 0, 0, 0, 1, 2}));
  EXPECT_EQ(columns.at("z"), (Column{-2, -1, 0, 1, 2, 3}));
}

TEST(SimulationBlocks, InterpolationInATunableTable) {
  const Built built{std::string{ramp} +
                        "  - {name: clip, type: Interpolation, parameters: {breakpoints: [1, 2, 4], table: T},"
                        " inputs: {u: x}, outputs: {y: clipped}}\n"
                        "  - {name: line, type: Interpolation, parameters: {breakpoints: [1, 2, 4], table: T,"
                        " extrapolation: linear}, inputs: {u: x}, outputs: {y: extended}}\n"
                        "  - {name: near, type: Interpolation, parameters: {breakpoints: [1, 2, 4], table: T,"
                        " method: nearest}, inputs: {u: x}, outputs: {y: nearest}}\n",
                    "parameters:\n  T: [10, 20, 0]\n"};
  const std::size_t table = built.parameter("T");
  plant::Loopback plant;
  const auto columns =
      run(built, plant, {"clipped", "extended", "nearest"}, 6, [table](std::uint64_t tick, Interpreter& model) {
        if (tick == 5) model.set_parameter(table, 2, 8);
      });
  // x = 0..5; from tick 5 the last value is 8: (8 - 20) * 1.5 + 20 = 2.
  EXPECT_EQ(columns.at("clipped"), (Column{10, 10, 20, 10, 0, 8}));
  EXPECT_EQ(columns.at("extended"), (Column{0, 10, 20, 10, 0, 2}));
  EXPECT_EQ(columns.at("nearest"), (Column{10, 10, 20, 0, 0, 8}));  // 3 is midway between 2 and 4: the upper
}

TEST(SimulationBlocks, CounterWrapsAtItsLimit) {
  const Built built{
      "  - {name: a, type: Counter, parameters: {limit: 2}, outputs: {y: a}}\n"
      "  - {name: b, type: Counter, parameters: {limit: 3, initial: 2, type: int8}, outputs: {y: b}}\n"};
  const auto columns = run(built, {"a", "b"}, 7);
  EXPECT_EQ(columns.at("a"), (Column{0, 1, 2, 0, 1, 2, 0}));
  EXPECT_EQ(columns.at("b"), (Column{2, 3, 0, 1, 2, 3, 0}));
}

TEST(SimulationBlocks, UnitDelayStartsFromItsInitialValue) {
  const Built built{std::string{ramp} +
                    "  - {name: d, type: UnitDelay, parameters: {initial: 7}, inputs: {u: x}, outputs: {y: old}}\n"
                    "  - {name: v, type: Mux, inputs: {u1: x, u2: x}, outputs: {y: v}}\n"
                    "  - {name: dv, type: UnitDelay, parameters: {initial: [1, 2]}, inputs: {u: v}, outputs: {y: dv}}\n"
                    "  - {name: toggle, type: Not, inputs: {u: was}, outputs: {y: state}}\n"
                    "  - {name: memory, type: UnitDelay, inputs: {u: state}, outputs: {y: was}}\n"};
  const auto columns = run(built, {"old", "dv", "state"}, 4);
  EXPECT_EQ(columns.at("old"), (Column{7, 0, 1, 2}));
  EXPECT_EQ(columns.at("dv[0]"), (Column{1, 0, 1, 2}));
  EXPECT_EQ(columns.at("dv[1]"), (Column{2, 0, 1, 2}));
  EXPECT_EQ(columns.at("state"), (Column{1, 0, 1, 0}));
}

TEST(SimulationBlocks, DiscreteIntegratorWithLimits) {
  const Built built{std::string{ramp} +
                        "  - {name: i, type: DiscreteIntegrator, parameters: {gain: 2, initial: 0.5, lower: -1,"
                        " upper: 10}, inputs: {u: x}, outputs: {y: y}}\n"
                        "  - {name: minus, type: Gain, parameters: {k: -3}, inputs: {u: x}, outputs: {y: down}}\n"
                        "  - {name: j, type: DiscreteIntegrator, parameters: {lower: -1}, inputs: {u: down},"
                        " outputs: {y: z}}\n",
                    "", 250000};
  const auto columns = run(built, {"y", "z"}, 8);
  const double ts = built.program().blocks[2].period_s;
  blocks::DiscreteIntegrator<double> i{0.5};
  blocks::DiscreteIntegrator<double> j{0};
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_EQ(columns.at("y")[k], i.output()) << k;
    EXPECT_EQ(columns.at("z")[k], j.output()) << k;
    i.update(static_cast<double>(k), 2, ts, -1, 10);
    j.update(-3 * static_cast<double>(k), 1, ts, -1, INFINITY);
  }
  EXPECT_EQ(columns.at("y"), (Column{0.5, 0.5, 1, 2, 3.5, 5.5, 8, 10}));  // x(k) * 2 * 0.25, up to 10
  EXPECT_EQ(columns.at("z").back(), -1);
}

TEST(SimulationBlocks, DiscreteDerivative) {
  const Built built{std::string{ramp} +
                        "  - {name: sq, type: Product, inputs: {u1: x, u2: x}, outputs: {y: sq}}\n"
                        "  - {name: d, type: DiscreteDerivative, parameters: {gain: 0.5}, inputs: {u: sq},"
                        " outputs: {y: y}}\n",
                    "", 250000};
  const auto columns = run(built, {"y"}, 5);
  EXPECT_EQ(columns.at("y"), (Column{0, 2, 6, 10, 14}));  // 0.5 * (k^2 - (k-1)^2) / 0.25
}

TEST(SimulationBlocks, DiscretePidAsTheBlockLibrarySteppedByHand) {
  const Built built{
      "  - {name: count, type: Counter, parameters: {limit: 5}, outputs: {y: n}}\n"
      "  - {name: e, type: Lookup, parameters: {table: E}, inputs: {index: n}, outputs: {y: e}}\n"
      "  - {name: pid, type: DiscretePid, parameters: {p: 1.5, i: 0.7, d: 0.05, n: 20, lower: -2,"
      " upper: 2.5}, inputs: {error: e}, outputs: {y: u}}\n"
      "  - {name: pi, type: DiscretePid, parameters: {p: 0.3, i: 2}, inputs: {error: e},"
      " outputs: {y: v}}\n",
      "parameters:\n  E: {value: [1, 0.8, 0.3, -0.4, -1.1, 0.1], type: single}\n", 10000};
  const auto columns = run(built, {"u", "v"}, 12);
  const std::vector<float> errors{1.0F, 0.8F, 0.3F, -0.4F, -1.1F, 0.1F};
  const auto ts = static_cast<float>(built.program().blocks[2].period_s);
  const blocks::PidGains<float> pid_gains{1.5F, 0.7F, 0.05F, 20.0F, -2.0F, 2.5F};
  const blocks::PidGains<float> pi_gains{0.3F, 2.0F, 0.0F, 100.0F, -INFINITY, INFINITY};
  blocks::DiscretePid<float> pid{0, 0};
  blocks::DiscretePid<float> pi{0, 0};
  for (std::size_t k = 0; k < 12; ++k) {
    const float error = errors[std::min<std::size_t>(k % 6, 5)];
    EXPECT_EQ(columns.at("u")[k], static_cast<double>(pid.output(error, pid_gains))) << k;
    EXPECT_EQ(columns.at("v")[k], static_cast<double>(pi.output(error, pi_gains))) << k;
    pid.update(error, pid_gains, ts);
    pi.update(error, pi_gains, ts);
  }
}

TEST(SimulationBlocks, DiscretePidRestsWhileItsResetIsTrue) {
  // The reset is true at counts 2 and 3 (of 0..5): the interpreter follows the block library's overloads with reset,
  // and after the reset the PID starts from rest, unlike one without it.
  const Built built{
      "  - {name: count, type: Counter, parameters: {limit: 5}, outputs: {y: n}}\n"
      "  - {name: e, type: Lookup, parameters: {table: E}, inputs: {index: n}, outputs: {y: e}}\n"
      "  - {name: late, type: Compare, parameters: {operator: \">=\", value: 2}, inputs: {u: n}, outputs: {y: a}}\n"
      "  - {name: early, type: Compare, parameters: {operator: \"<=\", value: 3}, inputs: {u: n}, outputs: {y: b}}\n"
      "  - {name: both, type: Logic, parameters: {operator: AND}, inputs: {u1: a, u2: b}, outputs: {y: r}}\n"
      "  - {name: pid, type: DiscretePid, parameters: {p: 1.5, i: 0.7, d: 0.05, n: 20, lower: -2, upper: 2.5,"
      " anti_windup: clamping}, inputs: {error: e, reset: r}, outputs: {y: u}}\n"
      "  - {name: free, type: DiscretePid, parameters: {p: 1.5, i: 0.7, d: 0.05, n: 20, lower: -2, upper: 2.5,"
      " anti_windup: clamping}, inputs: {error: e}, outputs: {y: v}}\n",
      "parameters:\n  E: {value: [1, 0.8, 0.3, -0.4, -1.1, 0.1], type: single}\n", 10000};
  const auto columns = run(built, {"u", "v"}, 12);
  const std::vector<float> errors{1.0F, 0.8F, 0.3F, -0.4F, -1.1F, 0.1F};
  const auto ts = static_cast<float>(built.program().blocks[5].period_s);
  const blocks::PidGains<float> gains{1.5F, 0.7F, 0.05F, 20.0F, -2.0F, 2.5F};
  blocks::DiscretePid<float> pid{0, 0};
  for (std::size_t k = 0; k < 12; ++k) {
    const std::size_t count = k % 6;
    const float error = errors[count];
    const bool reset = count >= 2 && count <= 3;
    EXPECT_EQ(columns.at("u")[k], static_cast<double>(pid.output(error, gains, reset))) << k;
    pid.update_clamped(error, gains, ts, reset);
  }
  EXPECT_NE(columns.at("u"), columns.at("v"));  // the same PID without the reset
}

TEST(SimulationBlocks, MatrixMultiplyAsTheBlockLibrary) {
  const Built built{std::string{ramp} +
                    "  - {name: a, type: Constant, parameters: {value: [[0.1, 0.2], [-0.3, 0.7]]}, outputs: {y: a}}\n"
                    "  - {name: one, type: Constant, parameters: {value: 1.1}, outputs: {y: one}}\n"
                    "  - {name: v, type: Mux, inputs: {u1: x, u2: one}, outputs: {y: v}}\n"
                    "  - {name: p, type: MatrixMultiply, inputs: {a: a, b: v}, outputs: {y: av}}\n"
                    "  - {name: q, type: MatrixMultiply, inputs: {a: a, b: a}, outputs: {y: aa}}\n"};
  const auto columns = run(built, {"av", "aa"}, 3);
  const double a[] = {0.1, 0.2, -0.3, 0.7};
  double aa[4];
  blocks::matrix_multiply(a, a, aa, 2, 2, 2);
  for (std::size_t k = 0; k < 3; ++k) {
    const double v[] = {static_cast<double>(k), 1.1};
    double av[2];
    blocks::matrix_multiply(a, v, av, 2, 2, 1);
    EXPECT_EQ(columns.at("av[0]")[k], av[0]);
    EXPECT_EQ(columns.at("av[1]")[k], av[1]);
    for (std::size_t e = 0; e < 4; ++e) EXPECT_EQ(columns.at("aa[" + std::to_string(e) + "]")[k], aa[e]);
  }
}

TEST(SimulationBlocks, AModelOfTunableConstantsGetsABaseRateToSeeThemChange) {
  const Built built{
      "  - {name: k, type: Constant, parameters: {value: K}, outputs: {y: k}}\n"
      "  - {name: g, type: Gain, parameters: {k: 3}, inputs: {u: k}, outputs: {y: y}}\n"
      "  - {name: c, type: Constant, parameters: {value: 4}, outputs: {y: c}}\n",
      "parameters:\n  K: 1\n"};
  ASSERT_TRUE(built.ok());
  ASSERT_EQ(built.program().tasks.size(), 1U);
  EXPECT_EQ(built.program().tasks[0].name, "rate 1");
  EXPECT_EQ(built.program().initial_outputs.size(), 2U);  // the parameter itself and c
  const std::size_t k = built.parameter("K");
  plant::Loopback plant;
  const auto columns = run(built, plant, {"y", "c"}, 3, [k](std::uint64_t tick, Interpreter& model) {
    if (tick == 1) model.set_parameter(k, 0, 2);
  });
  EXPECT_EQ(columns.at("y"), (Column{3, 6, 6}));
  EXPECT_EQ(columns.at("c"), (Column{4, 4, 4}));
}

// Rate transitions between the base rate and a rate 4 times slower, single-tasking as the executive runs them.
TEST(SimulationRates, FastToSlowLatchesAtTheSlowReleases) {
  const Built built{std::string{ramp} +
                    "  - {name: down, type: RateTransition, period: {multiple: 4}, parameters: {initial: -1},"
                    " inputs: {u: x}, outputs: {y: slow}}\n"
                    "  - {name: twice, type: Gain, parameters: {k: 2}, inputs: {u: slow}, outputs: {y: slow2}}\n"
                    "  - {name: ticks, type: Counter, period: {multiple: 4}, parameters: {limit: 100},"
                    " outputs: {y: slow_count}}\n"};
  plant::Loopback plant;
  const auto result = simulate(built.program(), plant, {11 * built.period_s(), {"slow", "slow2", "slow_count"}, {}});
  ASSERT_TRUE(result.ok()) << result.error();
  const auto& columns = result.value().recording.columns;
  EXPECT_EQ(columns[0], (Column{0, 0, 0, 0, 4, 4, 4, 4, 8, 8, 8, 8}));  // x at ticks 0, 4, 8
  EXPECT_EQ(columns[1], (Column{0, 0, 0, 0, 8, 8, 8, 8, 16, 16, 16, 16}));
  EXPECT_EQ(columns[2], (Column{0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2}));
  EXPECT_EQ(result.value().activations, (std::vector<std::uint32_t>{12, 3}));
}

TEST(SimulationRates, SlowToFastIsDelayedByOneSlowPeriod) {
  const Built built{
      "  - {name: ticks, type: Counter, period: {multiple: 4}, parameters: {limit: 100},"
      " outputs: {y: n}}\n"
      "  - {name: slow, type: Convert, parameters: {type: double}, inputs: {u: n}, outputs: {y: x}}\n"
      "  - {name: up, type: RateTransition, period: base, parameters: {initial: 42}, inputs: {u: x},"
      " outputs: {y: fast}}\n"
      "  - {name: fast_count, type: Counter, parameters: {limit: 100}, outputs: {y: m}}\n"
      "  - {name: both, type: Sum, inputs: {u1: fast, u2: fast}, outputs: {y: fast2}}\n"};
  const auto columns = run(built, {"x", "fast", "fast2"}, 13);
  EXPECT_EQ(columns.at("x"), (Column{0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3}));
  EXPECT_EQ(columns.at("fast"), (Column{42, 42, 42, 42, 0, 0, 0, 0, 1, 1, 1, 1, 2}));
  EXPECT_EQ(columns.at("fast2"), (Column{84, 84, 84, 84, 0, 0, 0, 0, 2, 2, 2, 2, 4}));
}

TEST(SimulationRates, TransitionsBetweenTwoSlowerRates) {
  // Rates 2 and 6: the release comes every third activation of the faster one.
  const Built built{
      "  - {name: ticks, type: Counter, period: {multiple: 2}, parameters: {limit: 100},"
      " outputs: {y: n}}\n"
      "  - {name: down, type: RateTransition, period: {multiple: 6}, inputs: {u: n}, outputs: {y: slow}}\n"
      "  - {name: up, type: RateTransition, period: {multiple: 2}, parameters: {initial: 9},"
      " inputs: {u: slow}, outputs: {y: back}}\n"};
  const auto columns = run(built, {"n", "slow", "back"}, 14);
  EXPECT_EQ(columns.at("n"), (Column{0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6}));
  EXPECT_EQ(columns.at("slow"), (Column{0, 0, 0, 0, 0, 0, 3, 3, 3, 3, 3, 3, 6, 6}));
  EXPECT_EQ(columns.at("back"), (Column{9, 9, 9, 9, 9, 9, 0, 0, 0, 0, 0, 0, 3, 3}));
}

// An enabled subsystem runs while its signal is true; its outputs and its state hold while it is false.
TEST(SimulationSubsystems, AnEnabledSubsystemHoldsWhileDisabled) {
  const Built built{std::string{ramp} +
                    "  - name: s\n    type: Subsystem\n    enable: on\n    inputs: {u: x}\n"
                    "    outputs: {y: held, count: counted}\n    blocks:\n"
                    "      - {name: g, type: Gain, parameters: {k: 10}, inputs: {u: u}, outputs: {y: y}}\n"
                    "      - {name: c, type: Counter, parameters: {limit: 100}, outputs: {y: count}}\n"
                    "  - {name: pattern, type: Lookup, parameters: {table: [1, 1, 0, 0, 1, 0, 1]}, inputs: {index: n},"
                    " outputs: {y: level}}\n"
                    "  - {name: enabled, type: Compare, parameters: {operator: '>', value: 0.5}, inputs: {u: level},"
                    " outputs: {y: on}}\n"};
  const auto columns = run(built, {"on", "held", "counted"}, 7);
  EXPECT_EQ(columns.at("on"), (Column{1, 1, 0, 0, 1, 0, 1}));
  EXPECT_EQ(columns.at("held"), (Column{0, 10, 10, 10, 40, 40, 60}));
  EXPECT_EQ(columns.at("counted"), (Column{0, 1, 1, 1, 2, 2, 3}));
}

TEST(SimulationSubsystems, ASubsystemEnabledByATunableParameterStartsWhenItIsSet) {
  const Built built{
      "  - {name: start, type: Constant, parameters: {value: playing}, outputs: {y: playing_now}}\n"
      "  - name: play\n    type: Subsystem\n    enable: playing_now\n    outputs: {index: position}\n"
      "    blocks:\n"
      "      - {name: counter, type: Counter, parameters: {limit: 100}, outputs: {y: index}}\n"
      "  - name: always\n    type: Subsystem\n    enable: yes\n    outputs: {index: ticks}\n"
      "    blocks:\n"
      "      - {name: counter, type: Counter, parameters: {limit: 100}, outputs: {y: index}}\n"
      "  - {name: on, type: Constant, parameters: {value: true, type: boolean}, outputs: {y: yes}}\n",
      "parameters:\n  playing: {value: false, type: boolean}\n"};
  const std::size_t playing = built.parameter("playing");
  plant::Loopback plant;
  const auto columns = run(built, plant, {"position", "ticks"}, 6, [playing](std::uint64_t tick, Interpreter& model) {
    if (tick == 2) model.set_parameter(playing, 0, 1);
  });
  EXPECT_EQ(columns.at("position"), (Column{0, 0, 0, 1, 2, 3}));
  EXPECT_EQ(columns.at("ticks"), (Column{0, 1, 2, 3, 4, 5}));
}

TEST(SimulationHardware, GpioThroughTheLoopbackPlant) {
  const Built built{std::string{truth_table} +
                        "  - {name: led, type: GpioOut, parameters: {pin: LED0}, inputs: {u: bit}}\n"
                        "  - {name: bit, type: Compare, parameters: {operator: '>', value: 0.5}, inputs: {u: p},"
                        " outputs: {y: bit}}\n"
                        "  - {name: delay, type: UnitDelay, inputs: {u: echo}, outputs: {y: echo_before}}\n"
                        "  - {name: echo, type: GpioIn, parameters: {pin: LED0}, outputs: {y: echo}}\n"
                        "  - {name: button, type: GpioIn, parameters: {pin: BUTTON}, outputs: {y: button}}\n",
                    truth_header};
  plant::Loopback plant;
  const auto columns = run(built, plant, {"bit", "echo", "button"}, 4);
  EXPECT_EQ(columns.at("bit"), (Column{0, 0, 1, 1}));
  EXPECT_EQ(columns.at("button"), (Column{0, 0, 0, 0}));  // never written: reads 0
  EXPECT_EQ(plant.value("gpio:LED0"), std::vector<double>{1});
  EXPECT_EQ(plant.writes(), 4U);
  // The pin reads back what the model wrote: in the same tick if it runs after the write, else a tick later.
  const auto& order = built.program().tasks[0].outputs;
  const auto position = [&](const std::string& path) {
    return std::find_if(order.begin(), order.end(),
                        [&](std::size_t block) { return built.program().blocks[block].path == path; }) -
           order.begin();
  };
  if (position("echo") > position("led")) {
    EXPECT_EQ(columns.at("echo"), (Column{0, 0, 1, 1}));
  } else {
    EXPECT_EQ(columns.at("echo"), (Column{0, 0, 0, 1}));
  }
}

TEST(SimulationHardware, AnSpiTransferWritesThenReadsItsResource) {
  const Built built{
      "  - {name: data, type: Constant, period: base, parameters: {value: [7, 300, -1]},"
      " outputs: {y: transmit}}\n"
      "  - {name: spi, type: SpiDma, parameters: {spi: SPI1, size: 3}, inputs: {transmit: transmit},"
      " outputs: {received: received}}\n"};
  const auto columns = run(built, {"received"}, 2);
  EXPECT_EQ(columns.at("received[0]"), (Column{7, 7}));  // the loopback plant answers what was sent, as uint8
  EXPECT_EQ(columns.at("received[1]"), (Column{255, 255}));
  EXPECT_EQ(columns.at("received[2]"), (Column{0, 0}));
}

TEST(SimulationRates, ASlowIntegratorStepsWithItsOwnPeriod) {
  const Built built{
      "  - {name: one, type: Constant, parameters: {value: 1}, outputs: {y: one}}\n"
      "  - {name: i, type: DiscreteIntegrator, period: {multiple: 4}, inputs: {u: one}, outputs: {y: y}}\n"
      "  - {name: count, type: Counter, parameters: {limit: 9}, outputs: {y: n}}\n",
      "", 250000};
  const auto columns = run(built, {"y"}, 9);
  EXPECT_EQ(columns.at("y"), (Column{0, 0, 0, 0, 1, 1, 1, 1, 2}));  // 1 * 4 * 0.25 s per slow step
}

// A plant that raises one interrupt at chosen base ticks.
class Interrupting : public plant::Loopback {
 public:
  Interrupting(std::string interrupt, double period_s, std::set<int> ticks)
      : interrupt_(std::move(interrupt)), period_s_(period_s), ticks_(std::move(ticks)) {}

  void advance(double time_s, const plant::RaiseInterrupt& raise) override {
    if (ticks_.count(static_cast<int>(std::lround(time_s / period_s_))) != 0) raise(interrupt_);
  }

 private:
  std::string interrupt_;
  double period_s_;
  std::set<int> ticks_;
};

TEST(SimulationInterrupts, AnInterruptTaskRunsWhenThePlantRaisesIt) {
  const Built built{
      "  - name: isr\n    type: Subsystem\n    trigger: {interrupt: EXTI0, priority: 1}\n"
      "    outputs: {presses: presses}\n    blocks:\n"
      "      - {name: c, type: Counter, parameters: {limit: 1000}, outputs: {y: before}}\n"
      "      - {name: k, type: Convert, parameters: {type: double}, inputs: {u: before},"
      " outputs: {y: counted}}\n"
      "      - {name: one, type: Constant, parameters: {value: 1}, outputs: {y: one}}\n"
      "      - {name: s, type: Sum, inputs: {u1: counted, u2: one}, outputs: {y: presses}}\n"
      "  - {name: latest, type: RateTransition, period: base, parameters: {mode: latest, initial: -1},"
      " inputs: {u: presses}, outputs: {y: seen}}\n"
      "  - {name: g, type: Gain, parameters: {k: 10}, inputs: {u: seen}, outputs: {y: seen10}}\n"};
  ASSERT_TRUE(built.ok());
  ASSERT_EQ(built.program().tasks.size(), 2U);
  EXPECT_EQ(built.program().tasks[1].name, "EXTI0");
  Interrupting plant{"EXTI0", built.period_s(), {2, 5, 6}};
  const auto result = simulate(built.program(), plant, {8 * built.period_s(), {"seen10", "presses"}, {}});
  ASSERT_TRUE(result.ok()) << result.error();
  const auto& columns = result.value().recording.columns;
  EXPECT_EQ(columns[0], (Column{-10, -10, 10, 10, 10, 20, 30, 30, 30}));  // the initial value until the first
  EXPECT_EQ(columns[1], (Column{0, 0, 1, 1, 1, 2, 3, 3, 3}));
  EXPECT_EQ(result.value().activations, (std::vector<std::uint32_t>{9, 3}));
}

TEST(SimulationInterrupts, AnInterruptTaskReadsThePeriodicTasksLatestValue) {
  const Built built{std::string{ramp} +
                    "  - {name: to_isr, type: RateTransition, inputs: {u: x}, outputs: {y: x_latest}}\n"
                    "  - name: isr\n    type: Subsystem\n    trigger: {interrupt: EXTI0, priority: 1}\n"
                    "    inputs: {value: x_latest}\n    outputs: {sample: sample}\n    blocks:\n"
                    "      - {name: hold, type: Gain, parameters: {k: 1}, inputs: {u: value}, outputs: {y: sample}}\n"};
  Interrupting plant{"EXTI0", built.period_s(), {0, 3, 4}};
  const auto columns = run(built, plant, {"sample"}, 6);
  // The interrupt comes before the base tick: it sees what the previous tick wrote (0 before the first).
  EXPECT_EQ(columns.at("sample"), (Column{0, 0, 0, 2, 3, 3}));
}
}  // namespace
}  // namespace duet::model
