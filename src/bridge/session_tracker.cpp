#include "session_tracker.hpp"

#include <algorithm>

#include "duet/xcp/protocol.hpp"

namespace duet::bridge {
namespace {

constexpr std::uint8_t code(xcp::Command command) { return static_cast<std::uint8_t>(command); }

// A DOWNLOAD or DOWNLOAD_NEXT that announces more data than it carries (`F0 n data...`, n elements of one byte:
// duet's slave has byte granularity) is followed by more of its block, and the slave answers only the block's end.
bool continues_block(std::span<const std::uint8_t> packet) {
  const std::uint8_t command = packet[0];
  if (command != code(xcp::Command::download) && command != code(xcp::Command::download_next)) return false;
  return packet.size() >= 2 && packet[1] > packet.size() - 2;
}

}  // namespace

bool SessionTracker::master_command(std::span<const std::uint8_t> packet, Clock::time_point now) {
  forget_master_command();  // a new command: the master no longer waits for the one before
  const bool answered = (slave_connected_ || packet[0] == code(xcp::Command::connect)) && !continues_block(packet);
  if (answered) awaited_.push_back({.command = packet[0], .sent = now, .for_master = true});
  return answered;
}

bool SessionTracker::master_gone(Clock::time_point now) {
  bool connecting = false;  // its CONNECT may still open a session that nobody would end
  for (Awaited& awaited : awaited_) {
    if (!awaited.for_master) continue;
    connecting = connecting || awaited.command == code(xcp::Command::connect);
    awaited.for_master = false;
    owed_until_ = now + owed_answer_patience_;
  }
  return slave_connected_ || connecting;
}

void SessionTracker::relay_disconnect(Clock::time_point now) {
  awaited_.push_back({.command = code(xcp::Command::disconnect), .sent = now, .for_master = false});
  owed_until_ = now + owed_answer_patience_;
  slave_connected_ = false;  // as far as the relay can end it; should it not answer, it was not connected either
}

SessionTracker::Delivery SessionTracker::slave_packet(std::span<const std::uint8_t> packet, Clock::time_point now) {
  const std::uint8_t pid = packet[0];
  if (pid == xcp::pid::event) {
    if (packet.size() >= 2 && packet[1] == static_cast<std::uint8_t>(xcp::EventCode::session_terminated)) {
      slave_connected_ = false;
    }
    return {};
  }
  if (pid != xcp::pid::response && pid != xcp::pid::error) return {};  // DAQ and service requests
  const bool positive = pid == xcp::pid::response;
  if (awaited_.empty()) {
    // Nothing waits (a session older than the relay's watch, or slave block mode's further answers); still, only a
    // connected slave answers positively.
    if (positive) slave_connected_ = true;
    return {};
  }
  const Awaited answered = awaited_.front();
  awaited_.pop_front();
  if (answered.for_master) measure(answered, now);  // the latency masters see
  if (positive) slave_connected_ = answered.command != code(xcp::Command::disconnect);
  const bool wrong_key = !positive && answered.command == code(xcp::Command::unlock) && packet.size() >= 2 &&
                         packet[1] == static_cast<std::uint8_t>(xcp::Error::access_locked);
  if (wrong_key) slave_connected_ = false;  // the standard's slave ends the session on a wrong key
  if (answered.for_master) return {.to_master = true, .answers_command = answered.command};
  if (std::none_of(awaited_.begin(), awaited_.end(), [](const Awaited& awaited) { return !awaited.for_master; })) {
    owed_until_.reset();
  }
  return {.to_master = false};
}

void SessionTracker::channel_reset() {
  commands_unanswered_ += awaited_.size();
  awaited_.clear();
  owed_until_.reset();
  slave_connected_ = false;
}

bool SessionTracker::give_up_owed_answers(Clock::time_point now) {
  if (!owed_until_ || now < *owed_until_) return false;
  commands_unanswered_ += std::erase_if(awaited_, [](const Awaited& awaited) { return !awaited.for_master; });
  owed_until_.reset();
  return true;
}

SessionTracker::Figures SessionTracker::figures() const {
  return {.responses = responses_,
          .commands_unanswered = commands_unanswered_,
          .latency_total_us = latency_total_us_,
          .latency_max_us = latency_max_us_};
}

void SessionTracker::forget_master_command() {
  const auto waiting =
      std::find_if(awaited_.begin(), awaited_.end(), [](const Awaited& awaited) { return awaited.for_master; });
  if (waiting == awaited_.end()) return;
  awaited_.erase(waiting);
  ++commands_unanswered_;
}

void SessionTracker::measure(const Awaited& answered, Clock::time_point now) {
  const double latency = std::chrono::duration<double, std::micro>(now - answered.sent).count();
  latency_total_us_ = latency_total_us_ + latency;
  if (latency > latency_max_us_) latency_max_us_ = latency;
  ++responses_;
}

}  // namespace duet::bridge
