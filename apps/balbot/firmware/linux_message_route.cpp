// The model's message channel to Linux ("ipc:app"), the same on every board: the application channel
// (robot_channels.hpp), which RPMsg carries on the STM32MP15 and a UART on the emulated Cortex-M4. Each board's
// routes (duet/hardware/board_routes.hpp) declare these.

#include <cstdint>
#include <span>

#include "duet/hardware/hardware.hpp"
#include "robot_channels.hpp"

namespace duet::hardware {

template <>
void ipc_send<ipc("app")>(std::span<const std::uint8_t> bytes) {
  balbot::firmware::send_to_linux(bytes);
}
template <>
void ipc_receive<ipc("app")>(std::span<std::uint8_t> bytes) {
  balbot::firmware::receive_from_linux(bytes);
}

}  // namespace duet::hardware
