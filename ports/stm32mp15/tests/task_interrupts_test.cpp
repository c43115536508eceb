// A model's tasks on the STM32MP15's NVIC: the base rate on TIM7, a slower rate on a line pended from software,
// interrupt tasks on their triggers' lines, each at the priority the task table gives, grouped as the model says.
#include "duet/cortex_m/task_interrupts.hpp"

#include <gtest/gtest.h>

#include <array>

#include "duet/stm32mp15/board.hpp"

namespace duet::cortex_m {
namespace {

namespace board = stm32mp15;

void nothing() {}

constexpr std::array tasks{
    rt::Task{.name = "rate 1", .kind = rt::TaskKind::periodic, .period_ticks = 1, .priority = {5, 1}, .entry = nothing},
    rt::Task{
        .name = "rate 10", .kind = rt::TaskKind::periodic, .period_ticks = 10, .priority = {6, 0}, .entry = nothing},
    rt::Task{.name = "EXTI8",
             .kind = rt::TaskKind::interrupt,
             .interrupt = board::interrupt::exti8,
             .priority = {1, 0},
             .entry = nothing},
    rt::Task{.name = "TIM2",
             .kind = rt::TaskKind::interrupt,
             .interrupt = board::interrupt::tim2,
             .priority = {0, 1},
             .entry = nothing}};
constexpr rt::ModelDescription model{.name = "m",
                                     .base_period_ns = 1'000'000,
                                     .tasks = tasks,
                                     .initialize = nothing,
                                     .terminate = nothing,
                                     .tasking_mode = rt::TaskingMode::multi,
                                     .sub_priority_bits = 1};
constexpr std::array<unsigned, 2> rate_lines{0, 125};
constexpr TaskLines lines{board::interrupt::tim7, rate_lines};

TEST(TaskInterrupts, EachTaskOnItsLineAtTheTablesPriority) {
  const TaskInterrupt base = task_interrupt(model, 0, lines);
  EXPECT_EQ(base.line, board::interrupt::tim7);
  EXPECT_EQ(base.priority, 5U << 1 | 1U);  // group 5, sub 1, with one sub-priority bit
  const TaskInterrupt slower = task_interrupt(model, 1, lines);
  EXPECT_EQ(slower.line, 125U);
  EXPECT_EQ(slower.priority, 6U << 1);
  EXPECT_EQ(task_interrupt(model, 2, lines).line, 66U);  // EXTI8
  EXPECT_EQ(task_interrupt(model, 2, lines).priority, 2U);
  EXPECT_EQ(task_interrupt(model, 3, lines).line, 28U);  // TIM2
  EXPECT_EQ(task_interrupt(model, 3, lines).priority, 1U);
}

}  // namespace
}  // namespace duet::cortex_m
