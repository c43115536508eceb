#pragma once
// The typed hardware calls (duet/hardware/hardware.hpp) for a port whose resources are a simulated plant's: each goes
// to the plant by the plant's name for it, as doubles, converted as the interpreter converts them
// (duet::blocks::convert), so that generated code and `duet sim` give the plant the same numbers and take the same
// back. The PC's port includes it (QEMU's plant link carries the types themselves), after declaring the two calls
// it comes to:
//
//   void write(std::string_view resource, std::span<const double> values);
//   void read(std::string_view resource, std::span<double> values);
//
// An IPC channel is not the plant's on every port, so each port says where it goes.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "duet/blocks/convert.hpp"
#include "duet/hardware/resources.hpp"

namespace duet::hardware {

namespace detail {
// The most values one call moves: an SPI transfer, a sequence of ADC samples.
inline constexpr std::size_t max_plant_values = 128;

template <typename Element>
void write_as_doubles(std::string_view resource, std::span<const Element> elements) {
  double values[max_plant_values];
  const std::size_t count = elements.size() < max_plant_values ? elements.size() : max_plant_values;
  for (std::size_t k = 0; k < count; ++k) values[k] = static_cast<double>(elements[k]);
  write(resource, {values, count});
}
template <typename Element>
void read_as(std::string_view resource, std::span<Element> elements) {
  double values[max_plant_values];
  const std::size_t count = elements.size() < max_plant_values ? elements.size() : max_plant_values;
  read(resource, {values, count});
  for (std::size_t k = 0; k < count; ++k) elements[k] = blocks::convert<Element>(values[k]);
}
}  // namespace detail

template <PwmChannel channel>
void pwm_write(float percent) {
  const double value = percent;
  write(plant_name(channel).view(), {&value, 1});
}

template <CaptureChannel channel>
CaptureReading capture_read() {
  double values[2]{};
  read(plant_name(channel).view(), values);
  return {blocks::convert<std::uint32_t>(values[0]), blocks::convert<bool>(values[1])};
}

template <SpiBus bus>
void spi_transfer(std::span<const std::uint8_t> bytes) {
  detail::write_as_doubles(plant_name(bus).view(), bytes);
}
template <SpiBus bus>
void spi_received(std::span<std::uint8_t> bytes) {
  detail::read_as(plant_name(bus).view(), bytes);
}

template <AdcInput input>
void adc_start(std::uint16_t count) {
  const double value = count;
  write(plant_name(input).view(), {&value, 1});
}
template <AdcInput input>
void adc_samples(std::span<std::uint16_t> samples) {
  detail::read_as(plant_name(input).view(), samples);
}

template <ExtiLine line>
bool exti_level() {
  double value = 0;
  read(plant_name(line).view(), {&value, 1});
  return blocks::convert<bool>(value);
}

}  // namespace duet::hardware
