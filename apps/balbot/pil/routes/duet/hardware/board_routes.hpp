#pragma once
// The robot's message channel to Linux on the emulated Cortex-M4: the application channel on a UART that stands in
// for RPMsg (firmware/linux_message_route.cpp defines both; everything else the model uses is the simulated robot's,
// over the plant link).

#include <cstdint>
#include <span>

namespace duet::hardware {

template <>
void ipc_send<ipc("app")>(std::span<const std::uint8_t> bytes);
template <>
void ipc_receive<ipc("app")>(std::span<std::uint8_t> bytes);

}  // namespace duet::hardware
