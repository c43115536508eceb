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

}  // namespace duet::hardware

#include "duet/hardware/by_plant_name.hpp"

namespace duet::hardware {

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
