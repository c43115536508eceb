// Generated code that uses every resource the robot's board routes: compiles.
#include "duet/hardware/hardware.hpp"

void step() {
  namespace hardware = duet::hardware;
  hardware::pwm_write<hardware::pwm("TIM1", 3)>(50.0F);
  hardware::pwm_write<hardware::pwm("TIM1", 4)>(50.0F);
  [[maybe_unused]] const hardware::CaptureReading left = hardware::capture_read<hardware::capture("TIM2", 1)>();
  const std::uint8_t bytes[] = {0x3B, 0};
  hardware::spi_transfer<hardware::spi("SPI5")>(bytes);
  std::uint8_t received[2]{};
  hardware::spi_received<hardware::spi("SPI5")>(received);
  hardware::adc_start<hardware::adc("ADC1", 6)>(100);
  std::uint16_t samples[100]{};
  hardware::adc_samples<hardware::adc("ADC1", 6)>(samples);
  hardware::ipc_send<hardware::ipc("app")>(bytes);
}
