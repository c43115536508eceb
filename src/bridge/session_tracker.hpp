#pragma once
// What the relay knows of the XCP session from the packets it passes: whether the slave is connected, which
// commands still wait for their answer and whose that answer is, and how long answers took.
//
// XCP has one outstanding command at a time, so at most one of the master's commands waits: a new command means the
// master gave up on the one before (counted as unanswered). A command that will get no answer waits for nothing: the
// first packets of a block-mode DOWNLOAD (master block mode: only the last DOWNLOAD_NEXT is answered) and anything
// but CONNECT while the slave is disconnected (a disconnected slave answers CONNECT only). Answers pair with the
// commands that wait, oldest first; an answer nothing waits for still goes to the master.
//
// When the master goes away, the answers its commands wait for are owed to nobody, as is the answer to the DISCONNECT
// the relay then sends on its behalf. While answers are owed the relay holds the next master's commands back, or it
// could not tell their answers from the owed ones; an owed answer that has not come after the tracker's patience is
// given up (the slave was not connected after all).

#include <atomic>
#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>

namespace duet::bridge {

class SessionTracker {
 public:
  using Clock = std::chrono::steady_clock;
  // Far longer than a slave takes to answer DISCONNECT, far shorter than a master waits for an answer (XCP's T1,
  // typically 1 s): a master held back meanwhile still gets its answer in time.
  static constexpr std::chrono::milliseconds default_owed_answer_patience{200};

  explicit SessionTracker(std::chrono::milliseconds owed_answer_patience = default_owed_answer_patience)
      : owed_answer_patience_(owed_answer_patience) {}

  struct Figures {
    std::uint64_t responses = 0;  // answers to the master's commands, paired with them: their latency is measured
    std::uint64_t commands_unanswered = 0;
    double latency_total_us = 0;
    double latency_max_us = 0;
  };

  // Where a packet from the slave goes, and for an answer to one of the master's commands, which command it answers.
  struct Delivery {
    bool to_master = true;
    std::optional<std::uint8_t> answers_command;
  };

  // A command of the master's on its way to the slave; returns whether the slave will answer it.
  bool master_command(std::span<const std::uint8_t> packet, Clock::time_point now);
  // The master went away; returns whether the slave's session needs ending on its behalf (then relay_disconnect()).
  bool master_gone(Clock::time_point now);
  // The relay's own DISCONNECT, on its way to the slave.
  void relay_disconnect(Clock::time_point now);
  Delivery slave_packet(std::span<const std::uint8_t> packet, Clock::time_point now);
  // A new channel: a slave that has just started (or the same one, which the next answers will tell).
  void channel_reset();

  [[nodiscard]] bool owes_answers() const { return owed_until_.has_value(); }
  // When owed answers will be given up; give_up_owed_answers() then.
  [[nodiscard]] std::optional<Clock::time_point> owed_until() const { return owed_until_; }
  // Gives up owed answers whose time is up; returns whether it did (then nothing is owed any more).
  bool give_up_owed_answers(Clock::time_point now);
  // From any thread (the relay's status is read by others).
  [[nodiscard]] Figures figures() const;

 private:
  struct Awaited {
    std::uint8_t command = 0;
    Clock::time_point sent{};
    bool for_master = true;  // false: owed to nobody (a master that left, or the relay itself)
  };

  void forget_master_command();
  void measure(const Awaited& answered, Clock::time_point now);

  std::chrono::milliseconds owed_answer_patience_;
  bool slave_connected_ = false;
  // Oldest first; at most two: one of the master's, or one of a master that left and the relay's DISCONNECT (the
  // next master's commands are held back while answers are owed).
  std::deque<Awaited> awaited_;
  std::optional<Clock::time_point> owed_until_;
  std::atomic<std::uint64_t> responses_{0}, commands_unanswered_{0};
  std::atomic<double> latency_total_us_{0}, latency_max_us_{0};
};

}  // namespace duet::bridge
