// The fault path on the PC: the safe state against fake GPIO and timer register files (one BSRR store per pin, the
// PWM channels' compare registers 0 and loaded at once, MOE off on advanced timers only, nothing else touched), and the
// fault record filled from a fake frame and fault status, taken once at the next start, garbage ignored.
#include "duet/stm32mp15/fault.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <optional>

namespace duet::stm32mp15 {
namespace {

constexpr std::uint32_t untouched = 0xA5A5'0000;  // + the word's index: a register nobody wrote

template <std::size_t Words>
struct FakeRegisters {
  FakeRegisters() {
    for (std::uint32_t index = 0; index < Words; ++index) words[index] = untouched + index;
  }
  std::uintptr_t base() { return reinterpret_cast<std::uintptr_t>(words.data()); }
  std::uint32_t& at(std::uint32_t offset) { return words[offset / 4]; }
  std::array<std::uint32_t, Words> words;
};

using FakePort = FakeRegisters<10>;                    // GPIO, up to AFRH
using FakeTimer = FakeRegisters<Timer::bdtr / 4 + 1>;  // up to BDTR

class SafeStateTest : public ::testing::Test {
 protected:
  void TearDown() override { set_safe_state({}); }

  // Every word of `registers` as the fake made it, but those at `written` offsets.
  template <std::size_t Words>
  static void expect_untouched_but(FakeRegisters<Words>& registers, std::initializer_list<std::uint32_t> written) {
    for (std::uint32_t index = 0; index < Words; ++index) {
      if (std::find(written.begin(), written.end(), 4 * index) != written.end()) continue;
      EXPECT_EQ(registers.words[index], untouched + index) << "offset " << 4 * index;
    }
  }

  FakePort port_a, port_d, port_e;
  FakeTimer tim1, tim4;
};

TEST_F(SafeStateTest, EachPinIsDrivenByOneBsrrStore) {
  const std::array pins{SafePin{port_a.base(), 12, false},  // MTR_STBY low: the bridges off
                        SafePin{port_d.base(), 14, false},  // MTRR_N
                        SafePin{port_e.base(), 7, true}};   // a pin safe when high (e.g. a chip select)
  set_safe_state({pins, {}});
  enter_safe_state();
  EXPECT_EQ(port_a.at(GpioPort::bsrr), 1U << (16 + 12));
  EXPECT_EQ(port_d.at(GpioPort::bsrr), 1U << (16 + 14));
  EXPECT_EQ(port_e.at(GpioPort::bsrr), 1U << 7);
  expect_untouched_but(port_a, {GpioPort::bsrr});
  expect_untouched_but(port_d, {GpioPort::bsrr});
  expect_untouched_but(port_e, {GpioPort::bsrr});
}

// TIM1 as the robot sets it up: channels 3 and 4 PWM outputs, channel 1 a compare without a pin; TIM4 a capture.
void set_up_like_the_robot(FakeTimer& tim1, FakeTimer& tim4) {
  tim1.at(Timer::ccmr1) = 0;       // channel 1: frozen compare (CCxS = 00), its output off in CCER
  tim1.at(Timer::ccmr2) = 0x6868;  // channels 3 and 4: PWM mode 1, preload
  tim1.at(Timer::ccer) = 1U << 8 | 1U << 12;
  tim1.at(Timer::bdtr) = Timer::main_output_enable | Timer::idle_off_state;
  tim4.at(Timer::ccmr1) = 0;
  tim4.at(Timer::ccmr2) = 0x0100;  // channel 4: input (CCxS = 01)
  tim4.at(Timer::ccer) = 1U << 12;
}

TEST_F(SafeStateTest, PwmOutputsGoOffAndMoeOnlyOnAdvancedTimers) {
  set_up_like_the_robot(tim1, tim4);
  const std::array timers{Timer{tim1.base(), true}, Timer{tim4.base(), false}};
  set_safe_state({{}, timers});
  enter_safe_state();
  EXPECT_EQ(tim1.at(Timer::ccr1 + 8), 0U);                   // CCR3
  EXPECT_EQ(tim1.at(Timer::ccr1 + 12), 0U);                  // CCR4
  EXPECT_EQ(tim1.at(Timer::bdtr), Timer::idle_off_state);    // MOE off: the outputs to their idle level, low
  EXPECT_EQ(tim1.at(Timer::egr), Timer::update_generation);  // the zeros loaded now, not at the period's end
  expect_untouched_but(
      tim1, {Timer::ccmr1, Timer::ccmr2, Timer::ccer, Timer::ccr1 + 8, Timer::ccr1 + 12, Timer::bdtr, Timer::egr});
  expect_untouched_but(tim4, {Timer::ccmr1, Timer::ccmr2, Timer::ccer, Timer::egr});  // a capture is no output
}

TEST_F(SafeStateTest, ThePinsAndTimersOfOneTableAllGoSafe) {
  set_up_like_the_robot(tim1, tim4);
  const std::array pins{SafePin{port_a.base(), 12, false}, SafePin{port_d.base(), 1, false}};
  const std::array timers{Timer{tim1.base(), true}};
  set_safe_state({pins, timers});
  enter_safe_state();
  EXPECT_EQ(port_a.at(GpioPort::bsrr), 1U << 28);
  EXPECT_EQ(port_d.at(GpioPort::bsrr), 1U << 17);
  EXPECT_EQ(tim1.at(Timer::ccr1 + 8), 0U);   // MTR_PWMA, TIM1_CH3
  EXPECT_EQ(tim1.at(Timer::ccr1 + 12), 0U);  // MTR_PWMB, TIM1_CH4
  EXPECT_EQ(tim1.at(Timer::bdtr) & Timer::main_output_enable, 0U);
}

TEST_F(SafeStateTest, APinNumberBeyondThePortIsSkipped) {
  const std::array pins{SafePin{port_a.base(), 16, false}};
  set_safe_state({pins, {}});
  enter_safe_state();
  expect_untouched_but(port_a, {});
}

TEST_F(SafeStateTest, WithoutASafeStateNothingIsWritten) {
  enter_safe_state();  // the default: empty tables
  expect_untouched_but(port_a, {});
  expect_untouched_but(tim1, {});
}

TEST(FaultStatusTest, TheFourRegistersAreReadAtTheirOffsets) {
  std::array<std::uint32_t, 5> scb{0x0000'8200, 0x4000'0000, 0x0000'0002, 0x2000'0000, 0xDEAD'BEEF};  // DFSR between
  const FaultStatus status = read_fault_status(reinterpret_cast<std::uintptr_t>(scb.data()));
  EXPECT_EQ(status.cfsr, 0x0000'8200U);
  EXPECT_EQ(status.hfsr, 0x4000'0000U);
  EXPECT_EQ(status.mmfar, 0x2000'0000U);
  EXPECT_EQ(status.bfar, 0xDEAD'BEEFU);
}

class FaultRecordTest : public ::testing::Test {
 protected:
  // A precise bus fault at a bad address, escalated to HardFault (CFSR.PRECISERR | BFARVALID, HFSR.FORCED).
  static constexpr FaultStatus bus_fault{0x0000'8200, 0x4000'0000, 0x0000'0000, 0x6000'0000};
  static constexpr ExceptionFrame frame{1, 2, 3, 4, 12, 0x1000'0123, 0x1000'0456, 0x2100'0000};

  // Power-on contents: anything.
  FaultRecord record{0x1234'5678, 77, 3, 1, 2, 3, 4, 5, 6, 7, 8};
};

TEST_F(FaultRecordTest, TheRecordHoldsTheFrameAndStatus) {
  record_fault(record, 3, bus_fault, &frame, false);
  EXPECT_EQ(record.magic, FaultRecord::unreported);
  EXPECT_EQ(record.count, 1U);  // garbage before: the first fault
  EXPECT_EQ(record.exception, 3U);
  EXPECT_EQ(record.cfsr, 0x0000'8200U);
  EXPECT_EQ(record.hfsr, 0x4000'0000U);
  EXPECT_EQ(record.mmfar, 0U);
  EXPECT_EQ(record.bfar, 0x6000'0000U);
  EXPECT_EQ(record.pc, 0x1000'0456U);
  EXPECT_EQ(record.lr, 0x1000'0123U);
  EXPECT_EQ(record.xpsr, 0x2100'0000U);
  EXPECT_EQ(record.stack_overflow, 0U);
}

TEST_F(FaultRecordTest, TheNextStartTakesItOnce) {
  record_fault(record, 5, bus_fault, &frame, false);
  const std::optional<FaultRecord> fault = take_fault(record);
  ASSERT_TRUE(fault.has_value());
  EXPECT_EQ(fault->exception, 5U);
  EXPECT_EQ(fault->pc, 0x1000'0456U);
  EXPECT_EQ(fault->count, 1U);
  EXPECT_EQ(record.magic, FaultRecord::reported);
  EXPECT_FALSE(take_fault(record).has_value());
}

TEST_F(FaultRecordTest, TheCountGoesOnAcrossStarts) {
  record_fault(record, 3, bus_fault, &frame, false);
  ASSERT_TRUE(take_fault(record).has_value());
  record_fault(record, 6, bus_fault, &frame, false);
  record_fault(record, 4, bus_fault, &frame, false);  // before the next start took the one before: the last one is kept
  const std::optional<FaultRecord> fault = take_fault(record);
  ASSERT_TRUE(fault.has_value());
  EXPECT_EQ(fault->count, 3U);
  EXPECT_EQ(fault->exception, 4U);
}

TEST_F(FaultRecordTest, ARecordWithABadMagicIsIgnoredAndStartsTheCount) {
  EXPECT_FALSE(take_fault(record).has_value());
  EXPECT_EQ(record.magic, FaultRecord::reported);
  EXPECT_EQ(record.count, 0U);
  EXPECT_FALSE(take_fault(record).has_value());
  record_fault(record, 3, bus_fault, &frame, false);
  EXPECT_EQ(record.count, 1U);
}

TEST_F(FaultRecordTest, AFrameWhoseStackingFailedIsNotRead) {
  const FaultStatus stacking_error{1U << 12, 0x4000'0000, 0, 0};  // CFSR.STKERR
  record_fault(record, 3, stacking_error, nullptr, false);
  EXPECT_EQ(record.magic, FaultRecord::unreported);
  EXPECT_EQ(record.cfsr, 1U << 12);
  EXPECT_EQ(record.pc, 0U);
  EXPECT_EQ(record.lr, 0U);
  EXPECT_EQ(record.xpsr, 0U);
}

// The main stack ran into its guard: the core could not stack the frame there (CFSR.MSTKERR), and the record says why.
TEST_F(FaultRecordTest, AStackOverflowIsRecordedWithoutItsFrame) {
  const FaultStatus stacking_into_the_guard{1U << 4, 0x4000'0000, 0, 0};
  record_fault(record, 3, stacking_into_the_guard, nullptr, true);
  EXPECT_EQ(record.magic, FaultRecord::unreported);
  EXPECT_EQ(record.stack_overflow, 1U);
  EXPECT_EQ(record.pc, 0U);
}

}  // namespace
}  // namespace duet::stm32mp15
