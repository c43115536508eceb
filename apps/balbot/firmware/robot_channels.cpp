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

// The transmit queues' lock: on the Cortex-M4 the interrupt mask, set inline (duet/base/section_lock.hpp).
constexpr xcp::QueueLock interrupt_lock{};

// The settings below are shared by the model's tasks that send and take the message (rate 10's IpcSend, IPCC_RX1's
// IpcReceive) and the application channel's handler, which every board runs at its lowest priority. A section at the
// ceiling of those tasks (Stack Resource Policy, duet/rt/ceiling.hpp) keeps them apart and never delays the more
// urgent ones: the IMU's chain, the PWM, the encoders, the echo, the battery. Timed, so that the longest is blocking
// for `duet sched`.
constexpr std::size_t settings_users[] = {duet::rt::task_index(balbot::description, "rate 10"),
                                          duet::rt::task_index(balbot::description, "IPCC_RX1")};
constexpr duet::rt::Ceiling settings_ceiling = duet::rt::ceiling(balbot::description, settings_users);

class SettingsSection {
 public:
  SettingsSection() = default;
  // Recorded before the mask is lifted (members are destroyed after the body).
  ~SettingsSection() { record_section(settings_ceiling, executive_cycles() - start_); }
  SettingsSection(const SettingsSection&) = delete;
  SettingsSection& operator=(const SettingsSection&) = delete;

 private:
  const cortex_m::PriorityCeiling masked_{settings_ceiling};
  const std::uint32_t start_ = executive_cycles();
};

// XCP: the model's slave as its generated code sizes it (balbot_xcp.hpp, the A2L's limits and addresses).
balbot::xcp::Slave slave{{.timestamp = microseconds,  // the A2L's unit
                          .write_atomically = cortex_m::copy_with_interrupts_masked,
                          .queue_lock = interrupt_lock}};
std::array<std::uint8_t, xcp::ethernet_framing.frame_size(balbot::xcp::max_cto)> xcp_decoder_buffer{};
std::array<std::uint8_t, balbot::xcp::max_dto> xcp_packet_buffer{};
xcp::StreamTransport transport{slave.protocol(),   slave.queue(),        xcp::ethernet_framing,
                               xcp_decoder_buffer, balbot::xcp::max_cto, xcp_packet_buffer};

// The application channel: what the thesis' Linux application shows (theta, battery voltage, distance) and sets
// (the PID's P, I, D), as the model sends and takes them, and what is in effect: the controller, P, I and D in use,
// whose they are (the calibration's or Linux's) and the robot's state.
struct RobotMessage {  // the model's message, as its BytePack lays it out
  float theta;
  float battery;
  float distance;
  float p_in_use;
  float i_in_use;
  float d_in_use;
  std::uint8_t controller;  // 0 PID, 1 LQR
  std::uint8_t gains_from;  // 0 calibration, 1 Linux
  std::uint8_t robot_state;
};
RobotMessage telemetry{};
struct Settings {  // the message to the model: P, I, D (the thesis') and the controller
  float p;
  float i;
  float d;
  std::uint8_t use_lqr;
};
constexpr std::size_t settings_bytes = 13;  // without the structure's padding
Settings settings{balbot::reference_parameters.P, balbot::reference_parameters.I, balbot::reference_parameters.D,
                  balbot::reference_parameters.use_lqr ? std::uint8_t{1} : std::uint8_t{0}};
Settings settings_sent = settings;  // what the model was last told
std::uint32_t telemetry_sample = 0;

constexpr const char* controller_names[] = {"PID", "LQR"};
constexpr const char* source_names[] = {"calibration", "Linux"};
constexpr const char* state_names[] = {"initialising", "balancing", "stopped"};
namespace limits = balbot::parameter_limits;
const app_channel::Item telemetry_items[] = {
    app_channel::item("theta", "deg", telemetry.theta, -90, 90),
    app_channel::item("battery", "V", telemetry.battery, 0, 12.6),
    app_channel::item("distance", "cm", telemetry.distance, 0, 400),
    app_channel::named_item("robot_state", telemetry.robot_state, state_names),
    app_channel::named_item("controller", telemetry.controller, controller_names),
    app_channel::named_item("gains_from", telemetry.gains_from, source_names),
    app_channel::item("p_gain", "1/deg", telemetry.p_in_use, limits::P.minimum, limits::P.maximum),
    app_channel::item("i_gain", "1/(deg s)", telemetry.i_in_use, limits::I.minimum, limits::I.maximum),
    app_channel::item("d_gain", "s/deg", telemetry.d_in_use, limits::D.minimum, limits::D.maximum)};
// The model's names, units and limits, as the A2L gives them to an XCP master.
const app_channel::Item setting_items[] = {
    app_channel::item("P", "1/deg", settings.p, limits::P.minimum, limits::P.maximum),
    app_channel::item("I", "1/(deg s)", settings.i, limits::I.minimum, limits::I.maximum),
    app_channel::item("D", "s/deg", settings.d, limits::D.minimum, limits::D.maximum),
    app_channel::named_item("use_lqr", settings.use_lqr, controller_names)};
const app_channel::Application application{"balbot", 10'000, telemetry_items, setting_items};
std::array<std::uint8_t, 4096> application_queue_storage{};
xcp::TransmitQueue application_queue{application_queue_storage, interrupt_lock};
std::array<std::uint8_t, app_channel::decoder_buffer_size> application_decoder_buffer{};
std::array<std::uint8_t, app_channel::max_packet> application_packet_buffer{};
app_channel::Endpoint endpoint{application, application_queue, interrupt_lock, application_decoder_buffer,
                               application_packet_buffer};

template <typename T>
void bytes_to(std::span<const std::uint8_t> bytes, T& value) {
  std::array<std::uint8_t, sizeof(T)> raw{};
  std::memcpy(raw.data(), bytes.data(), bytes.size() < raw.size() ? bytes.size() : raw.size());
  std::memcpy(&value, raw.data(), raw.size());
}

// Bit for bit, so that a NaN written over XCP counts as the same value each time.
bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }
bool same_bits(const Settings& a, const Settings& b) {
  return same_bits(a.p, b.p) && same_bits(a.i, b.i) && same_bits(a.d, b.d) && a.use_lqr == b.use_lqr;
}

// The channel's P, I, D and controller follow what the model uses, so that a write over XCP shows on Linux's side
// too. Not while a set from Linux is on its way to the model (it would be undone before it arrived).
void show_the_settings_in_use() {
  const Settings in_use{telemetry.p_in_use, telemetry.i_in_use, telemetry.d_in_use, telemetry.controller};
  std::array<bool, 4> changed{};
  {
    const SettingsSection masked;
    if (!same_bits(settings, settings_sent) || same_bits(settings, in_use)) return;
    changed = {!same_bits(settings.p, in_use.p), !same_bits(settings.i, in_use.i), !same_bits(settings.d, in_use.d),
               settings.use_lqr != in_use.use_lqr};
    settings = in_use;
    settings_sent = in_use;
  }
  for (std::size_t index = 0; index < changed.size(); ++index) {
    if (changed[index]) (void)endpoint.report(index);  // a full queue loses the report (counted with the answers)
  }
}

}  // namespace

xcp::StreamTransport& xcp_transport() { return transport; }
app_channel::Endpoint& application_endpoint() { return endpoint; }

void tell_the_model_of_new_gains() {
  {
    const SettingsSection masked;
    if (same_bits(settings, settings_sent)) return;
    settings_sent = settings;
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

void send_to_linux(std::span<const std::uint8_t> message_bytes) {
  bytes_to(message_bytes, telemetry);
  show_the_settings_in_use();
  endpoint.publish(telemetry_sample++);
  kick_application();
}

void receive_from_linux(std::span<std::uint8_t> message_bytes) {
  std::array<std::uint8_t, settings_bytes> raw{};
  {
    const SettingsSection masked;
    std::memcpy(raw.data(), &settings_sent, raw.size());
  }
  for (std::size_t k = 0; k < message_bytes.size(); ++k) message_bytes[k] = k < raw.size() ? raw[k] : 0;
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
