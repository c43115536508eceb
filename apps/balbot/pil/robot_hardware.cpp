// The model's hardware calls on the emulated Cortex-M4: everything but the message to and from Linux
// (firmware/linux_message_route.cpp) is the simulated robot's, over the plant link.

#include <cstdint>
#include <span>
#include <string_view>

#include "duet/hardware/hardware.hpp"
#include "robot_firmware.hpp"

namespace duet::hardware {

void plant_pin_writes_full() { balbot::pil::plant_link().send_pin_writes(); }
void plant_write(std::string_view resource, std::span<const std::uint8_t> bytes) {
  balbot::pil::plant_link().write(resource, bytes);
}
void plant_write(std::string_view resource, std::span<const std::uint16_t> counts) {
  balbot::pil::plant_link().write(resource, counts);
}
void plant_write(std::string_view resource, std::span<const float> values) {
  balbot::pil::plant_link().write(resource, values);
}
void plant_read(std::string_view resource, std::span<bool> levels) { balbot::pil::plant_link().read(resource, levels); }
void plant_read(std::string_view resource, std::span<std::uint8_t> bytes) {
  balbot::pil::plant_link().read(resource, bytes);
}
void plant_read(std::string_view resource, std::span<std::uint16_t> samples) {
  balbot::pil::plant_link().read(resource, samples);
}
void plant_read(std::string_view resource, std::span<std::uint32_t> counts) {
  balbot::pil::plant_link().read(resource, counts);
}

}  // namespace duet::hardware
