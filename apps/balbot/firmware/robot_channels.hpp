#pragma once
// What the robot's firmware says to Linux, on every board: XCP (the model's parameters, its signals and the
// executive's account at the A2L's addresses, an event per task) and the application channel (theta, battery voltage
// and distance out, with what is in effect: the controller, the gains in use, whose they are, the robot's state; the
// PID's P, I, D and the controller in, which reach the model as the thesis' IPCC_RX1 message does). The board
// carries the bytes, on QEMU's UARTs (pil/) or on the STM32MP15's RPMsg ttys (board/), and supplies the functions
// marked so; robot_channels.cpp is the rest.

#include <cstddef>
#include <cstdint>
#include <span>

#include "duet/app_channel/endpoint.hpp"
#include "duet/rt/ceiling.hpp"
#include "duet/xcp/stream_transport.hpp"

namespace balbot::firmware {

// Supplied by the board.
void kick_xcp();               // XCP has queued bytes: pend the interrupt that sends them
void kick_application();       // so has the application channel
std::uint32_t microseconds();  // DAQ timestamps, in the A2L's unit; interrupt-safe
void pend_gains_task();        // the model's IPCC_RX1 task: new gains came from Linux
// The image's executive: its cycle count, and where a section the firmware times itself leaves its length
// (Executive::record_section), so that the longest reaches `duet sched` as blocking.
std::uint32_t executive_cycles();
void record_section(duet::rt::Ceiling ceiling, std::uint32_t cycles);

// For the board's lines: the protocols whose bytes they carry.
duet::xcp::StreamTransport& xcp_transport();
duet::app_channel::Endpoint& application_endpoint();
// After the application channel took bytes: a set from Linux that changed the gains tells the model.
void tell_the_model_of_new_gains();

// For the model and the executive.
// After task `task` (its index in the task table) ran: DAQ samples its event.
void on_task_finished(std::size_t task);
// The model's message to Linux (IpcSend: theta, battery voltage, distance, P, I, D in use as little-endian floats;
// the controller, whose settings, the robot's state as bytes), published on the application channel.
void send_to_linux(std::span<const std::uint8_t> message_bytes);
// The message Linux sent last (IpcReceive: P, I, D as little-endian floats, a byte 1 for the LQR), as the model reads
// it.
void receive_from_linux(std::span<std::uint8_t> message_bytes);
// The executive's account for the dashboard's Status page, on the application channel (from the background loop).
void publish_executive(const duet::app_channel::ExecutiveReport& report);

// What the channels lost so far, each counted where it was dropped.
struct ChannelLosses {
  std::uint32_t xcp_responses;      // responses that found the transmit queue full (a master that does not read)
  std::uint32_t daq_overloads;      // DAQ samples that did not fit the transmit queue
  std::uint32_t xcp_garbage_bytes;  // bytes the XCP decoder skipped to find the next frame
  std::uint32_t telemetry;          // telemetry samples that did not fit the application channel's queue
  std::uint32_t executive_reports;  // executive accounts that did not fit whole
  std::uint32_t answers;            // answers to parameter writes that did not fit
};
[[nodiscard]] ChannelLosses channel_losses();

}  // namespace balbot::firmware
