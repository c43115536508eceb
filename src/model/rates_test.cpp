// Rates and the task table.
#include "duet/model/rates.hpp"

#include <gtest/gtest.h>

#include "duet/model/model_file.hpp"

namespace duet::model {
namespace {

TEST(Rates, PropagateThroughInheritedBlocksAndMakeTheTaskTable) {
  const auto model = parse_model(R"(duet_model: 1
name: two_rates
base_period_us: 100
blocks:
  - {name: count, type: Counter, parameters: {limit: 100}, outputs: {y: n}}
  - {name: double_it, type: Gain, parameters: {k: 2}, inputs: {u: n}, outputs: {y: twice}}
  - {name: to_slow, type: RateTransition, period: {multiple: 10}, inputs: {u: twice}, outputs: {y: slow_twice}}
  - {name: offset, type: Constant, parameters: {value: 1}, outputs: {y: one}}
  - {name: add, type: Sum, inputs: {u1: slow_twice, u2: one}, outputs: {y: total}}
  - {name: to_isr, type: RateTransition, inputs: {u: total}, outputs: {y: latest}}
  - name: isr
    type: Subsystem
    trigger: {interrupt: EXTI0, priority: 5}
    inputs: {value: latest}
    blocks:
      - {name: pin, type: GpioOut, parameters: {pin: PA5}, inputs: {u: value}}
  - name: background_isr
    type: Subsystem
    trigger: {interrupt: USART1, priority: auto}
    blocks:
      - {name: level, type: GpioIn, parameters: {pin: PB1}, outputs: {y: level}}
)",
                                 "m.yaml");
  ASSERT_TRUE(model.ok()) << model.error();
  const RateAnalysis rates = analyse_rates(model.value());
  EXPECT_TRUE(rates.diagnostics.empty()) << format("m.yaml", rates.diagnostics.front());
  EXPECT_EQ(rates.block_rates.at("double_it"), (Rate{Rate::Kind::periodic, 1, {}}));  // inherited from the counter
  EXPECT_EQ(rates.block_rates.at("add"), (Rate{Rate::Kind::periodic, 10, {}}));       // from the transition
  EXPECT_EQ(rates.block_rates.at("offset").kind, Rate::Kind::constant);
  EXPECT_EQ(rates.block_rates.at("to_isr"), (Rate{Rate::Kind::interrupt, 0, "EXTI0"}));  // the rate of its reader
  EXPECT_EQ(rates.block_rates.at("isr/pin"), (Rate{Rate::Kind::interrupt, 0, "EXTI0"}));
  ASSERT_EQ(rates.tasks.size(), 4U);
  EXPECT_EQ(rates.tasks[0].name, "rate 1");
  EXPECT_DOUBLE_EQ(rates.tasks[0].period_us, 100);
  EXPECT_EQ(rates.tasks[1].name, "rate 10");
  EXPECT_DOUBLE_EQ(rates.tasks[1].period_us, 1000);
  EXPECT_EQ(rates.tasks[2].name, "EXTI0");
  EXPECT_EQ(rates.tasks[2].priority, 5);
  EXPECT_EQ(rates.tasks[3].name, "USART1");
  EXPECT_FALSE(rates.tasks[3].priority);  // auto: duet sched assigns it
  EXPECT_EQ(rates.tasks[0].blocks, (std::vector<std::string>{"count", "double_it"}));
  EXPECT_EQ(rates.tasks[1].blocks, (std::vector<std::string>{"to_slow", "add"}));
  EXPECT_EQ(rates.tasks[2].blocks, (std::vector<std::string>{"to_isr", "isr/pin"}));
  EXPECT_EQ(rates.constant_blocks, std::vector<std::string>{"offset"});
}

// The rates of a model made of `blocks` (YAML list items), with the base period `base_period_us`.
RateAnalysis rates_of(const std::string& blocks, int base_period_us = 100) {
  const auto model = parse_model(
      "duet_model: 1\nname: m\nbase_period_us: " + std::to_string(base_period_us) + "\nblocks:\n" + blocks, "m.yaml");
  EXPECT_TRUE(model.ok()) << model.error();
  return model.ok() ? analyse_rates(model.value()) : RateAnalysis{};
}

TEST(Rates, ExecutionOrderFollowsTheSignalsNotTheFile) {
  const RateAnalysis rates = rates_of(R"(
  - {name: out, type: GpioOut, parameters: {pin: PA5}, inputs: {u: limited}}
  - {name: limit, type: Saturation, parameters: {lower: 0, upper: 1}, inputs: {u: scaled}, outputs: {y: limited}}
  - {name: scale, type: Gain, parameters: {k: 2}, inputs: {u: previous}, outputs: {y: scaled}}
  - {name: memory, type: UnitDelay, inputs: {u: limited}, outputs: {y: previous}}
)");
  ASSERT_EQ(rates.tasks.size(), 1U);
  // The delay's output is its state: it goes first; then what depends on it, in the order of the signals.
  EXPECT_EQ(rates.tasks[0].blocks, (std::vector<std::string>{"memory", "scale", "limit", "out"}));
}

TEST(Rates, AnInheritedLoopRunsAtTheBaseRate) {
  const RateAnalysis rates = rates_of(R"(
  - {name: toggle, type: Not, inputs: {u: old}, outputs: {y: state}}
  - {name: delay, type: UnitDelay, inputs: {u: state}, outputs: {y: old}}
)",
                                      50);
  EXPECT_TRUE(rates.diagnostics.empty());
  EXPECT_EQ(rates.block_rates.at("toggle"), (Rate{Rate::Kind::periodic, 1, {}}));
  ASSERT_EQ(rates.tasks.size(), 1U);
  EXPECT_DOUBLE_EQ(rates.tasks[0].period_us, 50);
}

}  // namespace
}  // namespace duet::model
