#include "duet/hardware/resources.hpp"

#include <gtest/gtest.h>

#include <type_traits>

namespace duet::hardware {
namespace {

TEST(HardwareResources, NumbersFromTheChipsNames) {
  constexpr PwmChannel right_motor = pwm("TIM1", 3);
  EXPECT_EQ(right_motor.timer, 1);
  EXPECT_EQ(right_motor.channel, 3);
  constexpr CaptureChannel echo = capture("TIM17", 2);
  EXPECT_EQ(echo.timer, 17);
  EXPECT_EQ(echo.channel, 2);
  EXPECT_EQ(spi("SPI5").number, 5);
  constexpr AdcInput battery = adc("ADC2", 19);
  EXPECT_EQ(battery.adc, 2);
  EXPECT_EQ(battery.channel, 19);
  EXPECT_EQ(exti("EXTI0").line, 0);
  EXPECT_EQ(exti("EXTI15").line, 15);
  EXPECT_EQ(ipc("app").view(), "app");
}

// The names the interpreter gives the simulated plant (src/model/interpreter.cpp, hardware_resource).
TEST(HardwareResources, ThePlantsNames) {
  EXPECT_EQ(plant_name(pwm("TIM1", 3)).view(), "pwm:TIM1/3");
  EXPECT_EQ(plant_name(capture("TIM12", 4)).view(), "capture:TIM12/4");
  EXPECT_EQ(plant_name(spi("SPI5")).view(), "spi:SPI5");
  EXPECT_EQ(plant_name(adc("ADC1", 6)).view(), "adc:ADC1/6");
  EXPECT_EQ(plant_name(adc("ADC1", 16)).view(), "adc:ADC1/16");
  EXPECT_EQ(plant_name(exti("EXTI10")).view(), "exti:EXTI10");
  EXPECT_EQ(plant_name(ipc("telemetry_out")).view(), "ipc:telemetry_out");
}

// Resources are template arguments: equal ones are the same argument, different ones are not.
template <auto resource>
struct Routed {};
TEST(HardwareResources, AreTemplateArguments) {
  EXPECT_TRUE((std::is_same_v<Routed<pwm("TIM1", 3)>, Routed<PwmChannel{1, 3}>>));
  EXPECT_FALSE((std::is_same_v<Routed<pwm("TIM1", 3)>, Routed<pwm("TIM1", 4)>>));
  EXPECT_FALSE((std::is_same_v<Routed<pwm("TIM1", 3)>, Routed<capture("TIM1", 3)>>));
  EXPECT_TRUE((std::is_same_v<Routed<ipc("app")>, Routed<ipc("app")>>));
  EXPECT_FALSE((std::is_same_v<Routed<ipc("app")>, Routed<ipc("ap")>>));
}

}  // namespace
}  // namespace duet::hardware
