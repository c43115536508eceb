// The model's hardware calls on the emulated Cortex-M4: the message to and from Linux ("ipc:app") goes over the
// application channel, as IPCC and RPMsg carry it on the board; everything else is the simulated robot's, over the
// plant link.

#include <string_view>

#include "duet/hardware/hardware.hpp"
#include "robot_channels.hpp"
#include "robot_firmware.hpp"

namespace duet::hardware {
namespace {

constexpr std::string_view linux_channel = "ipc:app";

}  // namespace

void write(std::string_view resource, std::span<const double> values) {
  if (resource == linux_channel) {
    balbot::firmware::send_to_linux(values);
  } else {
    balbot::pil::plant_link().write(resource, values);
  }
}

void read(std::string_view resource, std::span<double> values) {
  if (resource == linux_channel) {
    balbot::firmware::receive_from_linux(values);
  } else {
    balbot::pil::plant_link().read(resource, values);
  }
}

}  // namespace duet::hardware
