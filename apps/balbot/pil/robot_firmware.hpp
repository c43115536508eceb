#pragma once
// The robot's firmware on the emulated Cortex-M4 (processor in the loop): what its parts share. main.cpp runs the
// generated model on the executive against the simulated robot over the plant link (UART2); host_channels.cpp
// carries XCP (UART0) and the application channel (UART1) of ../firmware/robot_channels.cpp; robot_hardware.cpp
// routes the model's hardware calls.

#include <cstdint>

#include "duet/mps2_an386/plant_link.hpp"
#include "robot_channels.hpp"

namespace balbot::pil {

// The simulated robot.
duet::mps2_an386::PlantLink& plant_link();

// XCP on UART0 and the application channel on UART1, served by their UARTs' interrupts at the lowest priority.
void start_host_channels();
// From the base tick's handler: the application channel may send its next tick's bytes.
void host_channels_new_tick();

struct HostChannelCounters {
  std::uint32_t xcp_bytes_received;
  std::uint32_t xcp_bytes_sent;
  std::uint32_t application_bytes_received;
  std::uint32_t application_bytes_sent;
  firmware::ChannelLosses lost;
};
HostChannelCounters host_channel_counters();

}  // namespace balbot::pil
