#pragma once
// The hardware interface generated code calls (docs/MODELS.md, "Hardware blocks"), on the PC: every resource goes to
// the plant the simulation connected, by name ("gpio:LED0", "pwm:TIM1/1", ...) and as doubles, as the interpreter's
// hardware blocks do, so that generated code and `duet sim` see the same plant; every resource is routed. The typed
// calls convert as the interpreter does (duet::blocks::convert), so both give the plant the same numbers. Each port
// has a header of this name; CMake chooses which one a build sees.

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "duet/blocks/convert.hpp"
#include "duet/hardware/resources.hpp"

namespace duet::plant {
class Plant;
}

namespace duet::hardware {

struct Pin {
  std::string_view name;
};
constexpr Pin pin(std::string_view name) { return {name}; }

// The lock-step port raises interrupt tasks by their place in the task table, not by an interrupt number.
constexpr std::uint16_t interrupt_number(std::string_view) { return 0; }

// The plant the hardware calls reach (none: writes are dropped, reads give 0). Not thread-safe: set it before the
// model runs.
void connect(plant::Plant* plant);

// A resource by the plant's name, as doubles: what the typed calls below come to, and what PlantInput and
// PlantOutput blocks use directly.
void write(std::string_view resource, std::span<const double> values);
void read(std::string_view resource, std::span<double> values);

namespace detail {
// The values of one call as the plant takes them, as many as the resource's elements, in a buffer each thread keeps:
// a simulated robot's step makes a dozen calls, none of which should allocate.
inline std::span<double> plant_values(std::size_t count) {
  thread_local std::vector<double> values;
  if (values.size() < count) values.resize(count);
  return std::span{values}.first(count);
}

template <typename Element>
void write_as_doubles(std::string_view resource, std::span<const Element> elements) {
  const std::span<double> values = plant_values(elements.size());
  for (std::size_t k = 0; k < elements.size(); ++k) values[k] = static_cast<double>(elements[k]);
  write(resource, values);
}
template <typename Element>
void read_as(std::string_view resource, std::span<Element> elements) {
  const std::span<double> values = plant_values(elements.size());
  read(resource, values);
  for (std::size_t k = 0; k < elements.size(); ++k) elements[k] = blocks::convert<Element>(values[k]);
}
}  // namespace detail

// The typed calls generated code makes (docs/MODELS.md, "Hardware blocks"): each resource by the plant's name for
// it, converted to and from doubles as the interpreter converts them, so that generated code and `duet sim` give the
// plant the same numbers and take the same back.
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

template <IpcChannel channel>
void ipc_send(std::span<const std::uint8_t> bytes) {
  detail::write_as_doubles(plant_name(channel).view(), bytes);
}
template <IpcChannel channel>
void ipc_receive(std::span<std::uint8_t> bytes) {
  detail::read_as(plant_name(channel).view(), bytes);
}

// A pin's resource name, "gpio:" and the pin's, in a buffer on the stack: a step writes pins every tick, and building
// a std::string each time was a tenth of a simulated robot's tick.
class PinResource {
 public:
  explicit PinResource(Pin pin) {
    constexpr std::string_view prefix = "gpio:";
    const std::size_t length = std::min(pin.name.size(), sizeof text_ - prefix.size());
    prefix.copy(text_, prefix.size());
    pin.name.copy(text_ + prefix.size(), length);
    size_ = prefix.size() + length;
  }
  [[nodiscard]] std::string_view name() const { return {text_, size_}; }

 private:
  char text_[64]{};
  std::size_t size_ = 0;
};

inline void gpio_write(Pin pin, bool level) {
  const double value = level ? 1.0 : 0.0;
  write(PinResource{pin}.name(), {&value, 1});
}
inline bool gpio_read(Pin pin) {
  double value = 0;
  read(PinResource{pin}.name(), {&value, 1});
  return value != 0.0;
}

}  // namespace duet::hardware
