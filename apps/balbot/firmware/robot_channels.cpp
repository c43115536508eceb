// The robot's XCP slave and application channel, the same on every board (robot_channels.hpp). Commands are handled
// where the board's line delivers their bytes, below every task; tasks only queue (DAQ samples, telemetry) and kick.

#include "robot_channels.hpp"

#include <array>
#include <bit>
#include <cstring>

#include "balbot.hpp"
#include "balbot_xcp.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/cortex_m/masked_copy.hpp"

namespace balbot::firmware {
namespace {

namespace cortex_m = duet::cortex_m;
namespace xcp = duet::xcp;
namespace app_channel = duet::app_channel;

constexpr xcp::QueueLock interrupt_lock{cortex_m::mask_interrupts, cortex_m::restore_interrupts};

// XCP: the model's slave as its generated code sizes it (balbot_xcp.hpp, the A2L's limits and addresses).
balbot::xcp::Slave slave{{.timestamp = microseconds,  // the A2L's unit
                          .write_atomically = cortex_m::copy_with_interrupts_masked,
                          .queue_lock = interrupt_lock}};
std::array<std::uint8_t, xcp::ethernet_framing.frame_size(balbot::xcp::max_cto)> xcp_decoder_buffer{};
std::array<std::uint8_t, balbot::xcp::max_dto> xcp_packet_buffer{};
xcp::StreamTransport transport{slave.protocol(),   slave.queue(),        xcp::ethernet_framing,
                               xcp_decoder_buffer, balbot::xcp::max_cto, xcp_packet_buffer};

// The application channel: what the thesis' Linux application shows (theta, battery voltage, distance) and sets
// (the PID's P, I, D), as the model sends and takes them.
struct RobotMessage {
  float theta;
  float battery;
  float distance;
};
RobotMessage telemetry{};
struct Gains {
  float p;
  float i;
  float d;
};
Gains gains{balbot::reference_parameters.P, balbot::reference_parameters.I, balbot::reference_parameters.D};
Gains gains_sent = gains;  // what the model was last told
std::uint32_t telemetry_sample = 0;

const app_channel::Item telemetry_items[] = {app_channel::item("theta", "deg", telemetry.theta, -90, 90),
                                             app_channel::item("battery", "V", telemetry.battery, 0, 12.6),
                                             app_channel::item("distance", "cm", telemetry.distance, 0, 400)};
const app_channel::Item gain_items[] = {app_channel::item("P", "", gains.p, 0, 1),
                                        app_channel::item("I", "", gains.i, 0, 1),
                                        app_channel::item("D", "", gains.d, 0, 1)};
const app_channel::Application application{"balbot", 10'000, telemetry_items, gain_items};
std::array<std::uint8_t, 4096> application_queue_storage{};
xcp::TransmitQueue application_queue{application_queue_storage, interrupt_lock};
std::array<std::uint8_t, app_channel::decoder_buffer_size> application_decoder_buffer{};
std::array<std::uint8_t, app_channel::max_packet> application_packet_buffer{};
app_channel::Endpoint endpoint{application, application_queue, interrupt_lock, application_decoder_buffer,
                               application_packet_buffer};

template <typename T>
void bytes_to(std::span<const double> bytes, T& value) {
  std::array<std::uint8_t, sizeof(T)> raw{};
  for (std::size_t k = 0; k < raw.size() && k < bytes.size(); ++k) raw[k] = static_cast<std::uint8_t>(bytes[k]);
  std::memcpy(&value, raw.data(), raw.size());
}

}  // namespace

xcp::StreamTransport& xcp_transport() { return transport; }
app_channel::Endpoint& application_endpoint() { return endpoint; }

void tell_the_model_of_new_gains() {
  const bool changed = std::bit_cast<std::uint32_t>(gains.p) != std::bit_cast<std::uint32_t>(gains_sent.p) ||
                       std::bit_cast<std::uint32_t>(gains.i) != std::bit_cast<std::uint32_t>(gains_sent.i) ||
                       std::bit_cast<std::uint32_t>(gains.d) != std::bit_cast<std::uint32_t>(gains_sent.d);
  if (!changed) return;
  {
    const cortex_m::InterruptMask masked;
    gains_sent = gains;
  }
  pend_gains_task();
}

void on_task_finished(std::size_t task) {
  slave.protocol().on_event(static_cast<std::uint16_t>(task));
  if (slave.queue().free_bytes() != slave.queue().capacity()) kick_xcp();
}

void publish_executive(const app_channel::ExecutiveReport& report) {
  (void)endpoint.publish_executive(report);  // a full queue loses this second's account (counted): the next comes
  kick_application();
}

void send_to_linux(std::span<const double> message_bytes) {
  bytes_to(message_bytes, telemetry);
  endpoint.publish(telemetry_sample++);
  kick_application();
}

void receive_from_linux(std::span<double> message_bytes) {
  std::array<std::uint8_t, sizeof(Gains)> raw{};
  {
    const cortex_m::InterruptMask masked;
    std::memcpy(raw.data(), &gains_sent, raw.size());
  }
  for (std::size_t k = 0; k < message_bytes.size(); ++k) message_bytes[k] = k < raw.size() ? raw[k] : 0.0;
}

ChannelLosses channel_losses() {
  return {.xcp_responses = transport.responses_dropped(),
          .daq_overloads = slave.protocol().overloads(),
          .xcp_garbage_bytes = static_cast<std::uint32_t>(transport.dropped_bytes()),
          .telemetry = endpoint.samples_dropped(),
          .executive_reports = endpoint.reports_dropped(),
          .answers = endpoint.answers_dropped()};
}

}  // namespace balbot::firmware
