// The options of each mapped block that no other test model simulates, in testing/options_r2020a (an R2020a package:
// systems/ parts, bddefaults.xml): imported, checked as duet checks it, simulated on input sequences chosen so that
// each option shows, and compared step by step with what Simulink's block computes by its documentation.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "duet/model/simulation.hpp"
#include "duet/simulink_import/import.hpp"
#include "duet/simulink_import/slx_model.hpp"
#include "testing/import_harness.hpp"
#include "testing/package_folder.hpp"

namespace duet::simulink_import {
namespace {

using ::testing::HasSubstr;
using Steps = std::vector<double>;

const std::filesystem::path testing = DUET_SIMULINK_TESTING_DIR;

// Eight steps of 0.25 s (the solver's fixed step). a, b and c count from 0 to 7 in binary (a the high bit), so the
// Logic blocks see every combination of their inputs.
const Steps u{-1, 0, 0.5, 2, 2.5, 4, 5, 1};
const Steps v{-2, 0, 1, 2, 2, 4, 6, 1};
double bit(std::size_t step, unsigned which) { return static_cast<double>((step >> which) & 1U); }

class BlockOptions : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto model = read_slx_model(parts_of(testing / "options_r2020a"), "options.slx");
    ASSERT_TRUE(model) << model.error();
    ASSERT_EQ(model.value().release, "R2020a");
    ASSERT_EQ(model.value().format, "slx (systems/)");
    imported_ = imported_with(model, "options_r2020a.m");
    const auto build = checked(imported_, keep_);
    ASSERT_TRUE(build);
    plant_.period_s = 0.25;
    auto simulated = model::simulate(*build->program, plant_, {.duration_s = 1.75, .record_plant = false});
    ASSERT_TRUE(simulated) << simulated.error();
  }
  // What the outport "y NAME" wrote, a value each time it ran.
  const Steps& steps(const std::string& name) {
    static const Steps none;
    const auto found = plant_.history.find("outport:y_" + name);
    EXPECT_NE(found, plant_.history.end()) << name;
    return found == plant_.history.end() ? none : found->second;
  }

  ImportResult imported_;
  std::unique_ptr<model::Model> keep_;
  Ports plant_{std::map<std::string, Ports::Inport>{{"inport:u", [](std::size_t step) { return u.at(step); }},
                                                    {"inport:v", [](std::size_t step) { return v.at(step); }},
                                                    {"inport:a", [](std::size_t step) { return bit(step, 2); }},
                                                    {"inport:b", [](std::size_t step) { return bit(step, 1); }},
                                                    {"inport:c", [](std::size_t step) { return bit(step, 0); }}}};
};

TEST_F(BlockOptions, RelationalOperatorsAndCompareToConstant) {
  // u against v: less at steps 2 and 6, greater at 0 and 4, equal at the others.
  EXPECT_EQ(steps("equal"), (Steps{0, 1, 0, 1, 0, 1, 0, 1}));
  EXPECT_EQ(steps("unequal"), (Steps{1, 0, 1, 0, 1, 0, 1, 0}));   // ~=
  EXPECT_EQ(steps("at_most"), (Steps{0, 1, 1, 1, 0, 1, 1, 1}));   // <=
  EXPECT_EQ(steps("greater"), (Steps{1, 0, 0, 0, 1, 0, 0, 0}));   // >
  EXPECT_EQ(steps("at_least"), (Steps{1, 1, 0, 1, 1, 1, 0, 1}));  // the file leaves out >=, bddefaults.xml has it
  // Compare To Constant (a library link): u <= 1, and u ~= 2.
  EXPECT_EQ(steps("small"), (Steps{1, 1, 1, 0, 0, 0, 0, 1}));
  EXPECT_EQ(steps("not_two"), (Steps{1, 1, 1, 0, 1, 1, 1, 1}));
  EXPECT_EQ(verdict(imported_, "options/not two").what, "Compare != 2");
}

TEST_F(BlockOptions, LogicOperatorsOfEveryCombination) {
  // In the subsystem "logic" (its own part, system_47.xml). a, b, c = the step's bits 2, 1, 0.
  EXPECT_EQ(steps("and"), (Steps{0, 0, 0, 0, 0, 0, 0, 1}));  // AND of three (bddefaults' Operator): only 1 1 1
  EXPECT_EQ(steps("or"), (Steps{0, 1, 1, 1, 1, 1, 1, 1}));   // OR of three: all but 0 0 0
  EXPECT_EQ(steps("xor"), (Steps{0, 1, 1, 0, 1, 0, 0, 1}));  // XOR of three: true for an odd count of true inputs
  EXPECT_EQ(steps("nor"), (Steps{1, 1, 0, 0, 0, 0, 0, 0}));  // NOR of a and b: neither set at steps 0 and 1
  EXPECT_EQ(steps("not"), (Steps{1, 1, 1, 1, 0, 0, 0, 0}));  // NOT a
}

TEST_F(BlockOptions, SwitchCriteriaAndThresholds) {
  // u1 = u, u3 = v. "u2 >= Threshold" (the default criteria), Threshold the variable threshold = 1, u2 = v: v = 1 at
  // step 2 is >= 1, so u there.
  EXPECT_EQ(steps("switch_at_least"), (Steps{-2, 0, 0.5, 2, 2.5, 4, 5, 1}));
  // "u2 > Threshold" with 1: v = 1 at steps 2 and 7 is not > 1, so v there.
  EXPECT_EQ(steps("switch_above"), (Steps{-2, 0, 1, 2, 2.5, 4, 5, 1}));
  // "u2 ~= 0" with u2 = a: u from step 4 on, where a = 1; its Threshold of 5 is not used (a >= 5 would never hold).
  EXPECT_EQ(steps("switch_nonzero"), (Steps{-2, 0, 1, 2, 2.5, 4, 5, 1}));
  EXPECT_THAT(imported_.model_text, HasSubstr("  threshold: {value: 1,"));  // the threshold stays tunable
}

TEST_F(BlockOptions, ArithmeticOfThreeInputsDivisionsAndTheReciprocal) {
  EXPECT_EQ(steps("smallest"), (Steps{-2, 0, 0.5, 1.5, 1.5, 1.5, 1.5, 1}));  // min(u, v, 1.5), Function min
  // Sum "|+-+": the bar only spaces the icon; u - v + c.
  EXPECT_EQ(steps("difference"), (Steps{1, 1, -0.5, 1, 0.5, 1, -1, 1}));
  EXPECT_EQ(steps("total"), (Steps{-3, 0, 1.5, 4, 5.5, 9, 12, 3}));  // Sum Inputs "3": u + v + a
  // Product "**/": u * v / 4, left to right.
  EXPECT_EQ(steps("scaled_product"), (Steps{0.5, 0, 0.125, 1, 1.25, 4, 7.5, 0.25}));
  EXPECT_EQ(steps("reciprocal"), (Steps{1, 1, -2, 1, 2, 1, -1, 1}));  // Math reciprocal of the signal: 1 / difference
  EXPECT_EQ(steps("ground"), Steps(1, 0.0));                          // Ground: 0, a constant, so written once
}

TEST_F(BlockOptions, VectorAndMatrixGainsAndProducts) {
  // [u; v] from the Mux. Gain [2 -3] element-wise: 2 u and -3 v.
  EXPECT_EQ(steps("weights_1"), (Steps{-2, 0, 1, 4, 5, 8, 10, 2}));
  EXPECT_EQ(steps("weights_2"), (Steps{6, 0, -3, -6, -6, -12, -18, -3}));
  // Gain K "Matrix(K*u) (u vector)", K = [1 -1; 0.5 2]: u - v and 0.5 u + 2 v.
  EXPECT_EQ(steps("mixing_1"), (Steps{1, 0, -0.5, 0, 0.5, 0, -1, 0}));
  EXPECT_EQ(steps("mixing_2"), (Steps{-4.5, 0, 2.25, 5, 5.25, 10, 14.5, 2.5}));
  EXPECT_THAT(imported_.model_text, HasSubstr("  K: {value: [[1, -1], [0.5, 2]],"));
  // Product "Matrix(*)" of M = [0 1; 1 1] and [u; v]: v and u + v.
  EXPECT_EQ(steps("matrix_1"), v);
  EXPECT_EQ(steps("matrix_2"), (Steps{-3, 0, 1.5, 4, 4.5, 8, 11, 2}));
  // Selector, IndexMode Zero-based, Indices [1 0]: the second element, then the first.
  EXPECT_EQ(steps("swapped_1"), v);
  EXPECT_EQ(steps("swapped_2"), u);
}

TEST_F(BlockOptions, LookupTableMethodsAndExtrapolation) {
  // Breakpoints [0 1 4], table [0 10 40]; u = -1 is below the range and 5 above it; 0.5 and 2.5 lie midway.
  // Linear point-slope (bddefaults' method) and linear extrapolation (its ExtrapMethod): the end segments' slopes 10
  // and 30 / 3 = 10 continue: -10 at -1, 40 + 10 at 5.
  EXPECT_EQ(steps("linear"), (Steps{-10, 0, 5, 20, 25, 40, 50, 10}));
  EXPECT_EQ(steps("clipped"), (Steps{0, 0, 5, 20, 25, 40, 40, 10}));  // Clip: the end values beyond the range
  // Nearest: midway (0.5, 2.5) takes the breakpoint of the higher index.
  EXPECT_EQ(steps("nearest"), (Steps{0, 0, 10, 10, 40, 40, 40, 10}));
  EXPECT_EQ(steps("flat"), (Steps{0, 0, 0, 10, 10, 40, 40, 10}));    // the breakpoint at or below u
  EXPECT_EQ(steps("above"), (Steps{0, 0, 10, 40, 40, 40, 40, 10}));  // the breakpoint at or above u
}

TEST_F(BlockOptions, LimitsGainsAndInitialConditionsOfStates) {
  // Saturation to [sat_lower, sat_upper] = [-0.5, 3], the limits tunable by those names.
  EXPECT_EQ(steps("limited"), (Steps{-0.5, 0, 0.5, 2, 2.5, 3, 3, 1}));
  EXPECT_THAT(imported_.model_text, HasSubstr("parameters: {lower: sat_lower, upper: sat_upper}"));
  // Forward Euler, gainval 2, from 1: y(0) = 1, y(k) = y(k-1) + 2 * 0.25 * u(k-1).
  EXPECT_EQ(steps("integral"), (Steps{1, 0.5, 0.5, 0.75, 1.75, 3, 5, 7.5}));
  // Delay of bddefaults' length 2 from delay_start = -4: two steps of -4, then u two steps late.
  EXPECT_EQ(steps("delayed"), (Steps{-4, -4, -1, 0, 0.5, 2, 2.5, 4}));
}

TEST_F(BlockOptions, RateTransitionsAndTheZeroOrderHoldStepByStep) {
  // Fast to slow (0.25 s to 0.5 s): the slow rate takes u at its own steps 0, 2, 4, 6.
  EXPECT_EQ(steps("slow"), (Steps{-1, 0.5, 2.5, 5}));
  EXPECT_EQ(steps("slow_gain"), (Steps{-10, 5, 25, 50}));  // 10 times that, at 0.5 s
  // Slow to fast, deterministic: the fast rate gets each slow value a slow period late, InitialCondition 9 before.
  EXPECT_EQ(steps("fast"), (Steps{9, 9, -10, -10, 5, 5, 25, 25}));
  // Zero-order hold at 0.75 s: u at steps 0, 3 and 6, written at its own rate.
  EXPECT_EQ(steps("held"), (Steps{-1, 2, 5}));
}

TEST_F(BlockOptions, SignalsTakeTheNamesOfTheirLinesAndPorts) {
  // The line from the Sum "difference" is named "spread"; the Sum "total" names its output port "sum of three".
  EXPECT_THAT(imported_.model_text, HasSubstr("inputs: {u1: u, u2: v, u3: c}\n    outputs: {y: spread}"));
  EXPECT_THAT(imported_.model_text, HasSubstr("inputs: {u1: reciprocal_one, u2: spread}"));
  EXPECT_THAT(imported_.model_text, HasSubstr("outputs: {y: sum_of_three}"));
}

}  // namespace
}  // namespace duet::simulink_import
