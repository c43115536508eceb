#pragma once
// The resources the robot's model uses, routed to the STM32MP15's peripherals (robot_peripherals.cpp defines each,
// firmware/linux_message_route.cpp the message to Linux; the port's duet/hardware/hardware.hpp includes this). A
// resource the model names that is not here does not compile.

#include <cstdint>
#include <span>

namespace duet::hardware {

template <>
void pwm_write<pwm("TIM1", 3)>(float percent);  // the right motor
template <>
void pwm_write<pwm("TIM1", 4)>(float percent);  // the left motor
template <>
CaptureReading capture_read<capture("TIM2", 1)>();  // the left hall encoder's A signal
template <>
CaptureReading capture_read<capture("TIM4", 4)>();  // the right one's
template <>
CaptureReading capture_read<capture("TIM5", 2)>();  // the ultrasonic echo
template <>
void spi_transfer<spi("SPI5")>(std::span<const std::uint8_t> bytes);  // the MPU6500
template <>
void spi_received<spi("SPI5")>(std::span<std::uint8_t> bytes);
template <>
void adc_start<adc("ADC1", 6)>(std::uint16_t count);  // the battery
template <>
void adc_samples<adc("ADC1", 6)>(std::span<std::uint16_t> samples);
template <>
void ipc_send<ipc("app")>(std::span<const std::uint8_t> bytes);  // the message to Linux
template <>
void ipc_receive<ipc("app")>(std::span<std::uint8_t> bytes);

}  // namespace duet::hardware
