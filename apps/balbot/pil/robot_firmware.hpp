#pragma once
// The robot's firmware on the emulated Cortex-M4 (processor in the loop): what its parts share. main.cpp runs the
// generated model on the executive against the simulated robot over the plant link (UART2); host_channels.cpp is
// XCP (UART0) and the application channel (UART1); robot_hardware.cpp routes the model's hardware calls.

#include <cstddef>
#include <cstdint>
#include <span>

#include "duet/app_channel/endpoint.hpp"
#include "duet/mps2_an386/plant_link.hpp"

namespace balbot::pil {

// The simulated robot.
duet::mps2_an386::PlantLink& plant_link();

// XCP on UART0 and the application channel on UART1, served by their UARTs' interrupts at the lowest priority.
void start_host_channels();
// After task `task` (its index in the task table) ran: DAQ samples its event.
void on_task_finished(std::size_t task);
// The model's message to Linux (IpcSend: theta, battery voltage, distance as little-endian floats): published on the
// application channel.
void send_to_linux(std::span<const double> message_bytes);
// The message Linux sent last (IpcReceive: P, I, D as little-endian floats), as the model reads it.
void receive_from_linux(std::span<double> message_bytes);

// The executive's account for the dashboard's Status page, on the application channel (from the background loop).
void publish_executive(const duet::app_channel::ExecutiveReport& report);

struct HostChannelCounters {
  std::uint32_t xcp_bytes_received;
  std::uint32_t xcp_bytes_sent;
  std::uint32_t application_bytes_received;
  std::uint32_t application_bytes_sent;
  std::uint32_t telemetry_dropped;
};
HostChannelCounters host_channel_counters();

}  // namespace balbot::pil
