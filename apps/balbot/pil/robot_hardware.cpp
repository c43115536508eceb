// The model's hardware calls on the emulated Cortex-M4: everything but the message to and from Linux
// (firmware/linux_message_route.cpp) is the simulated robot's, over the plant link.

#include <span>
#include <string_view>

#include "duet/hardware/hardware.hpp"
#include "robot_firmware.hpp"

namespace duet::hardware {

void write(std::string_view resource, std::span<const double> values) {
  balbot::pil::plant_link().write(resource, values);
}
void read(std::string_view resource, std::span<double> values) { balbot::pil::plant_link().read(resource, values); }

}  // namespace duet::hardware
