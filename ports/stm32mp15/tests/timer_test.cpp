// TIM1/TIM2/TIM4/TIM5 for the robot against a fake register file: the motors' PWM set up in the reference manual's
// order with the thesis' duty (eq. 5.1), the once-per-period compare interrupt, input capture on one and both
// edges and its handler, the safe state, and what the timers cannot do refused with nothing touched. Expected
// register values are written out from RM0436's bit positions, not from the driver's constants.
#include "duet/stm32mp15/timer.hpp"

#include <gtest/gtest.h>

#include <array>
#include <limits>

namespace duet::stm32mp15 {
namespace {

constexpr std::uint32_t mcu_clock_hz = 209'000'000;
constexpr std::uint64_t pwm_period_ns = 500'000;  // 2 kHz: 104,500 clocks, prescaler 1 (/2), reload 52,249

class TimerTest : public ::testing::Test {
 protected:
  std::uint32_t& reg(std::uint32_t offset) { return registers[offset / 4]; }
  std::uint32_t& ccr(unsigned channel) { return reg(Timer::ccr1 + 4 * (channel - 1)); }
  std::uintptr_t base() { return reinterpret_cast<std::uintptr_t>(registers.data()); }

  // TIM1 as the robot's firmware sets it up: PWM on channels 3 and 4, the compare interrupt on channel 1.
  void start_motor_pwm(const Timer& timer) {
    ASSERT_TRUE(timer.configure_pwm(pwm_period_ns, mcu_clock_hz));
    ASSERT_TRUE(timer.enable_pwm_output(3, 40.0F));
    ASSERT_TRUE(timer.enable_pwm_output(4, 60.0F));
    ASSERT_TRUE(timer.enable_compare_interrupt(1, 10.0F));
    timer.start();
  }

  std::array<std::uint32_t, 0x50 / 4> registers{};
  Timer tim1{base(), true};
  Timer general{base(), false};
};

TEST_F(TimerTest, TheTimersAreWhereTheManualSays) {
  EXPECT_EQ(tim1_base, 0x4400'0000U);
  EXPECT_EQ(tim2_base, 0x4000'0000U);
  EXPECT_EQ(tim4_base, 0x4000'2000U);
  EXPECT_EQ(tim5_base, 0x4000'3000U);
  EXPECT_EQ(Timer::ccmr2, 0x1CU);
  EXPECT_EQ(Timer::ccer, 0x20U);
  EXPECT_EQ(Timer::ccr1, 0x34U);
  EXPECT_EQ(Timer::bdtr, 0x44U);
}

TEST_F(TimerTest, MotorPwmIsSetUpInTheManualsOrder) {
  reg(Timer::cr1) = 0x1;  // running from before
  reg(Timer::sr) = 0x1F;

  ASSERT_TRUE(tim1.configure_pwm(pwm_period_ns, mcu_clock_hz));  // the time base, the counter stopped
  EXPECT_EQ(reg(Timer::psc), 1U);
  EXPECT_EQ(reg(Timer::arr), 52'249U);
  EXPECT_EQ(reg(Timer::cr1), 0x80U);  // ARPE, not CEN

  ASSERT_TRUE(tim1.enable_pwm_output(3, 50.0F));  // MTR_PWMA, PE13
  ASSERT_TRUE(tim1.enable_pwm_output(4, 0.0F));   // MTR_PWMB, PE14
  EXPECT_EQ(reg(Timer::ccmr2), 0x6868U);          // OC3M = OC4M = 0110 (PWM mode 1), OC3PE, OC4PE, CC3S = CC4S = 00
  EXPECT_EQ(ccr(3), 26'125U);                     // 52,250 * 50 / 100
  EXPECT_EQ(ccr(4), 0U);
  EXPECT_EQ(reg(Timer::ccer), 0x1100U);  // CC3E, CC4E; active high, no complementary outputs
  // Nothing runs before the channels are set up: no update event, outputs and counter off.
  EXPECT_EQ(reg(Timer::egr), 0U);
  EXPECT_EQ(reg(Timer::bdtr), 0U);
  EXPECT_EQ(reg(Timer::cr1), 0x80U);

  tim1.start();
  EXPECT_EQ(reg(Timer::egr), 0x1U);      // UG: the preloaded values loaded before the first period
  EXPECT_EQ(reg(Timer::sr), 0U);         // and its UIF cleared
  EXPECT_EQ(reg(Timer::bdtr), 0x8400U);  // MOE, OSSI
  EXPECT_EQ(reg(Timer::cr1), 0x81U);     // ARPE, CEN
  EXPECT_EQ(reg(Timer::dier), 0U);       // PWM alone interrupts nothing
}

TEST_F(TimerTest, AChannelChangesOnlyItsOwnModeFields) {
  reg(Timer::ccmr2) = 0x0101'FFFF;  // channel 3's byte and OC3M[3] (bit 16) set, and OC4M[3] (bit 24)
  reg(Timer::ccer) = 0xF0FF;
  ASSERT_TRUE(tim1.configure_pwm(pwm_period_ns, mcu_clock_hz));
  ASSERT_TRUE(tim1.enable_pwm_output(3, 50.0F));
  EXPECT_EQ(reg(Timer::ccmr2), 0x0100'FF68U);
  EXPECT_EQ(reg(Timer::ccer), 0xF1FFU);
}

TEST_F(TimerTest, AGeneralPurposeTimersPwmNeedsNoMainOutputEnable) {
  reg(Timer::bdtr) = 0xAAAA'AAAA;  // TIM2-TIM5 have no BDTR
  ASSERT_TRUE(general.configure_pwm(pwm_period_ns, mcu_clock_hz));
  ASSERT_TRUE(general.enable_pwm_output(1, 50.0F));
  general.start();
  EXPECT_EQ(reg(Timer::ccmr1), 0x68U);
  EXPECT_EQ(reg(Timer::ccer), 0x1U);
  EXPECT_EQ(reg(Timer::bdtr), 0xAAAA'AAAAU);
  EXPECT_EQ(reg(Timer::cr1), 0x81U);
}

TEST_F(TimerTest, DutyFollowsTheThesisEquationClampedToThePeriod) {
  start_motor_pwm(tim1);
  const auto duty = [&](float percent) {
    EXPECT_TRUE(tim1.set_duty(3, percent));
    return ccr(3);
  };
  EXPECT_EQ(duty(0.0F), 0U);
  EXPECT_EQ(duty(50.0F), 26'125U);
  EXPECT_EQ(duty(100.0F), 52'250U);  // above ARR: high all period
  EXPECT_EQ(duty(25.5F), 13'323U);   // 13,323.75 truncated
  EXPECT_EQ(duty(150.0F), 52'250U);
  EXPECT_EQ(duty(std::numeric_limits<float>::infinity()), 52'250U);
  EXPECT_EQ(duty(-3.0F), 0U);
  EXPECT_EQ(duty(-std::numeric_limits<float>::infinity()), 0U);
  EXPECT_EQ(duty(std::numeric_limits<float>::quiet_NaN()), 0U);
  EXPECT_EQ(ccr(4), 31'350U);  // the other channel kept its 60 %
}

TEST_F(TimerTest, TheCompareInterruptComesOncePerPeriodWithoutAPin) {
  reg(Timer::ccmr1) = 0x0001'00FF;  // channel 1 left in some other mode
  reg(Timer::sr) = 0x1F;
  ASSERT_TRUE(tim1.configure_pwm(pwm_period_ns, mcu_clock_hz));
  ASSERT_TRUE(tim1.enable_compare_interrupt(1, 10.0F));
  EXPECT_EQ(reg(Timer::ccmr1), 0U);   // CC1S = 00, OC1M = 0000 (frozen), no preload
  EXPECT_EQ(ccr(1), 5'225U);          // 10 % of 52,250
  EXPECT_EQ(reg(Timer::sr), ~0x2U);   // a stale CC1IF cleared alone
  EXPECT_EQ(reg(Timer::dier), 0x2U);  // CC1IE
  EXPECT_EQ(reg(Timer::ccer), 0U);    // CC1E off: TIM1_CH1 drives no pin
}

TEST_F(TimerTest, TakingTheCompareFlagClearsItAlone) {
  start_motor_pwm(tim1);
  reg(Timer::sr) = 0x2 | 0x4;  // CC1IF, CC2IF
  EXPECT_TRUE(tim1.take_compare_flag(1));
  EXPECT_EQ(reg(Timer::sr), ~0x2U);  // rc_w0: zero on CC1IF, ones leave the others
  reg(Timer::sr) = 0x4;
  EXPECT_FALSE(tim1.take_compare_flag(1));
  EXPECT_EQ(reg(Timer::sr), 0x4U);  // not set: not written
}

TEST_F(TimerTest, TheLeftHallCapturesRisingEdgesAtOneMegahertz) {
  reg(Timer::sr) = 0xFFFF;
  ASSERT_TRUE(general.start_capture(1, CaptureEdges::rising, 1'000'000, mcu_clock_hz));  // TIM2_CH1, PG8
  EXPECT_EQ(reg(Timer::psc), 208U);                                                      // 209 MHz / 209
  EXPECT_EQ(reg(Timer::arr), 0xFFFFU);
  EXPECT_EQ(reg(Timer::ccmr1), 0x01U);  // CC1S = 01 (TI1), no filter, no input prescaler
  EXPECT_EQ(reg(Timer::ccer), 0x1U);    // CC1E, CC1P = CC1NP = 0: rising
  EXPECT_EQ(reg(Timer::dier), 0x2U);    // CC1IE
  EXPECT_EQ(reg(Timer::egr), 0x1U);     // UG loads the prescaler
  EXPECT_EQ(reg(Timer::sr), ~0x203U);   // CC1IF, CC1OF and UG's UIF cleared
  EXPECT_EQ(reg(Timer::cr1), 0x1U);     // CEN
}

TEST_F(TimerTest, TheRightHallCapturesOnChannelFour) {
  ASSERT_TRUE(general.start_capture(4, CaptureEdges::rising, 1'000'000, mcu_clock_hz));  // TIM4_CH4, PD15
  EXPECT_EQ(reg(Timer::ccmr2), 0x100U);                                                  // CC4S = 01 (TI4)
  EXPECT_EQ(reg(Timer::ccer), 0x1000U);                                                  // CC4E
  EXPECT_EQ(reg(Timer::dier), 0x10U);                                                    // CC4IE
  EXPECT_EQ(reg(Timer::sr), ~0x1011U);                                                   // CC4IF, CC4OF, UIF
}

TEST_F(TimerTest, TheEchoCapturesBothEdges) {
  reg(Timer::ccmr1) = 0xFFFF'FFFF;
  reg(Timer::ccer) = 0xFFFF;
  ASSERT_TRUE(general.start_capture(2, CaptureEdges::both, 1'000'000, mcu_clock_hz));  // TIM5_CH2, PH11
  EXPECT_EQ(reg(Timer::ccmr1), 0xFEFF'01FFU);  // CC2S = 01, IC2PSC = IC2F = 0, bit 24 clear; channel 1's byte kept
  EXPECT_EQ(reg(Timer::ccer), 0xFFBFU);        // CC2E, CC2P, CC2NP; CC2NE (bit 6) clear
  ASSERT_TRUE(general.start_capture(2, CaptureEdges::falling, 1'000'000, mcu_clock_hz));
  EXPECT_EQ(reg(Timer::ccer), 0xFF3FU);  // CC2E, CC2P
}

TEST_F(TimerTest, TheCounterClockIsTheNearestDivisionWithinATenthOfAPercent) {
  ASSERT_TRUE(general.start_capture(1, CaptureEdges::rising, 1'000'000, 208'877'930));  // the DK2's PLL3
  EXPECT_EQ(reg(Timer::psc), 208U);
  ASSERT_TRUE(general.start_capture(1, CaptureEdges::rising, 1'000'000, 1'000'000));
  EXPECT_EQ(reg(Timer::psc), 0U);
  ASSERT_TRUE(general.start_capture(1, CaptureEdges::rising, 1'000, 65'536'000));  // the largest divider
  EXPECT_EQ(reg(Timer::psc), 0xFFFFU);
}

TEST_F(TimerTest, TakingACaptureReadsRestartsAndClears) {
  ASSERT_TRUE(general.start_capture(1, CaptureEdges::rising, 1'000'000, mcu_clock_hz));
  reg(Timer::sr) = 0x2;  // CC1IF
  ccr(1) = 1'234;
  reg(Timer::cnt) = 77;
  const Capture capture = general.take_capture(1);
  EXPECT_TRUE(capture.captured);
  EXPECT_EQ(capture.count, 1'234U);
  EXPECT_FALSE(capture.overcaptured);
  EXPECT_FALSE(capture.wrapped);
  EXPECT_EQ(reg(Timer::cnt), 0U);
  // CC1OF and UIF written 0; CC1IF left to the read of CCR1, which clears it (an edge after that read is kept).
  EXPECT_EQ(reg(Timer::sr), ~0x201U);
}

TEST_F(TimerTest, MissedEdgesAndAWrappedCounterAreReported) {
  ASSERT_TRUE(general.start_capture(2, CaptureEdges::both, 1'000'000, mcu_clock_hz));
  reg(Timer::sr) = 0x4 | 0x400 | 0x1;  // CC2IF, CC2OF, UIF
  ccr(2) = 0x1'2345;                   // TIM5's 32-bit register, as read
  const Capture capture = general.take_capture(2);
  EXPECT_TRUE(capture.captured);
  EXPECT_EQ(capture.count, 0x1'2345U);
  EXPECT_TRUE(capture.overcaptured);
  EXPECT_TRUE(capture.wrapped);
  EXPECT_EQ(reg(Timer::sr), ~0x401U);
}

TEST_F(TimerTest, NoCaptureTouchesNothing) {
  ASSERT_TRUE(general.start_capture(1, CaptureEdges::rising, 1'000'000, mcu_clock_hz));
  reg(Timer::sr) = 0x4 | 0x1;  // another channel's flag and UIF, not CC1IF
  reg(Timer::cnt) = 77;
  const Capture capture = general.take_capture(1);
  EXPECT_FALSE(capture.captured);
  EXPECT_EQ(reg(Timer::cnt), 77U);
  EXPECT_EQ(reg(Timer::sr), 0x5U);
}

TEST_F(TimerTest, TheSafeStateZeroesThePwmAndTurnsTheOutputsOff) {
  start_motor_pwm(tim1);
  reg(Timer::egr) = 0;
  // Channel 2 as an enabled input (CC2S = 01, CC2E): its CCR2 is no duty.
  reg(Timer::ccmr1) |= 0x100U;
  reg(Timer::ccer) |= 0x10U;
  ccr(2) = 99;
  tim1.enter_safe_state();
  EXPECT_EQ(reg(Timer::bdtr), 0x400U);  // MOE off, OSSI: the outputs at their idle level, low
  EXPECT_EQ(ccr(3), 0U);
  EXPECT_EQ(ccr(4), 0U);
  EXPECT_EQ(reg(Timer::egr), 0x1U);  // UG: the zeros now, not at the end of the period
  EXPECT_EQ(ccr(1), 5'225U);         // the compare interrupt's channel drives no pin
  EXPECT_EQ(ccr(2), 99U);
  EXPECT_EQ(reg(Timer::cr1), 0x81U);  // still counting: the TIM1 task goes on
  EXPECT_EQ(reg(Timer::dier), 0x2U);
}

TEST_F(TimerTest, StopLeavesTheOutputsSafeAndTheTimerQuiet) {
  start_motor_pwm(tim1);
  tim1.stop();
  EXPECT_EQ(reg(Timer::bdtr), 0x400U);
  EXPECT_EQ(ccr(3), 0U);
  EXPECT_EQ(ccr(4), 0U);
  EXPECT_EQ(reg(Timer::dier), 0U);
  EXPECT_EQ(reg(Timer::cr1), 0U);
}

TEST_F(TimerTest, RefusesWhatItCannotDoTouchingNothing) {
  registers.fill(0xAAAA'AAAA);
  const auto untouched = registers;
  EXPECT_FALSE(tim1.configure_pwm(5, mcu_clock_hz));                // one count
  EXPECT_FALSE(tim1.configure_pwm(100'000'000'000, mcu_clock_hz));  // 100 s: beyond 16 + 16 bits
  EXPECT_FALSE(tim1.enable_pwm_output(0, 50.0F));
  EXPECT_FALSE(tim1.enable_pwm_output(5, 50.0F));
  EXPECT_FALSE(tim1.enable_compare_interrupt(0, 10.0F));
  EXPECT_FALSE(tim1.enable_compare_interrupt(5, 10.0F));
  EXPECT_FALSE(tim1.set_duty(5, 50.0F));
  EXPECT_FALSE(tim1.take_compare_flag(5));
  EXPECT_FALSE(tim1.take_capture(0).captured);
  EXPECT_FALSE(general.start_capture(0, CaptureEdges::rising, 1'000'000, mcu_clock_hz));
  EXPECT_FALSE(general.start_capture(5, CaptureEdges::rising, 1'000'000, mcu_clock_hz));
  EXPECT_FALSE(general.start_capture(1, CaptureEdges::rising, 0, mcu_clock_hz));
  EXPECT_FALSE(general.start_capture(1, CaptureEdges::rising, 2'000'000, mcu_clock_hz));    // /105: 0.5 % fast
  EXPECT_FALSE(general.start_capture(1, CaptureEdges::rising, 400'000'000, mcu_clock_hz));  // faster than its clock
  EXPECT_FALSE(general.start_capture(1, CaptureEdges::rising, 1'000, 66'000'000));          // /66,000
  EXPECT_EQ(registers, untouched);
}

}  // namespace
}  // namespace duet::stm32mp15
