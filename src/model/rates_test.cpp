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
}

TEST(Rates, AnInheritedLoopRunsAtTheBaseRate) {
  const auto model = parse_model(R"(duet_model: 1
name: loop
base_period_us: 50
blocks:
  - {name: toggle, type: Not, inputs: {u: old}, outputs: {y: state}}
  - {name: delay, type: UnitDelay, inputs: {u: state}, outputs: {y: old}}
)",
                                 "m.yaml");
  ASSERT_TRUE(model.ok()) << model.error();
  const RateAnalysis rates = analyse_rates(model.value());
  EXPECT_TRUE(rates.diagnostics.empty());
  EXPECT_EQ(rates.block_rates.at("toggle"), (Rate{Rate::Kind::periodic, 1, {}}));
  ASSERT_EQ(rates.tasks.size(), 1U);
  EXPECT_DOUBLE_EQ(rates.tasks[0].period_us, 50);
}

}  // namespace
}  // namespace duet::model
