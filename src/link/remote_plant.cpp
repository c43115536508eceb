#include "duet/link/remote_plant.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>

namespace duet::link {
namespace {

constexpr std::string_view plant_name = "the plant";

}  // namespace

RemotePlant::RemotePlant(std::unique_ptr<Stream> stream, const RemotePlantOptions& options)
    : stream_(std::move(stream)), channel_(*stream_, std::string{plant_name}), options_(options) {}

Result<std::unique_ptr<RemotePlant>> RemotePlant::connect(std::unique_ptr<Stream> stream,
                                                          const RemotePlantOptions& options) {
  std::unique_ptr<RemotePlant> plant{new RemotePlant{std::move(stream), options}};
  if (Status greeted = plant->greet(); !greeted) {
    plant->fail(Failure{greeted.error()});  // no BYE when the plant goes: there was no session
    return Failure{greeted.error()};
  }
  return plant;
}

Status RemotePlant::greet() {
  if (options_.base_period_ns == 0) {
    return Failure{"the link needs the firmware's base period: the plant's time is tick x base period"};
  }
  if (Status sent = channel_.send_hello({protocol_version, options_.mode, options_.base_period_ns}); !sent) {
    return sent;
  }
  auto answer = channel_.receive("HELLO_OK");
  if (!answer) return Failure{answer.error()};
  if (!answer.value()) return channel_.peer_failure("closed the link instead of answering HELLO");
  const ReceivedFrame frame = *answer.value();
  if (frame.kind != FrameKind::hello_ok) return unexpected(frame.kind, frame.payload, "HELLO_OK");
  HelloOk hello_ok;
  (void)parse(frame.payload, hello_ok);  // the decoder checked its one byte
  if (hello_ok.version != protocol_version) {
    return channel_.fail("the plant answered HELLO with link protocol version " + std::to_string(hello_ok.version) +
                         "; this firmware speaks version " + std::to_string(protocol_version) + " only");
  }
  return done();
}

RemotePlant::~RemotePlant() {
  if (usable()) (void)close();
}

Status RemotePlant::close() {
  if (!usable()) return status_;
  closed_ = true;
  if (Status said = channel_.send_empty(FrameKind::bye); !said) return said;
  return channel_.flush();
}

void RemotePlant::fail(Failure failure) {
  if (status_.ok()) status_ = std::move(failure);
}

Failure RemotePlant::unexpected(FrameKind kind, std::span<const std::uint8_t> payload, std::string_view awaiting) {
  if (kind == FrameKind::error) {
    ErrorText text;
    (void)parse(payload, text);
    return channel_.peer_failure("reported an error: " + std::string{text.text});
  }
  return channel_.fail("the plant sent " + std::string{kind_name(kind)} + " where the firmware awaited " +
                       std::string{awaiting});
}

void RemotePlant::advance(double time_s, const plant::RaiseInterrupt& raise) {
  if (!usable()) return;
  const double period_s = options_.base_period_ns * 1e-9;
  const double ticks = std::round(time_s / period_s);
  const auto tick = static_cast<std::uint64_t>(ticks >= 0 && ticks < 0x1p63 ? ticks : 0);
  if (tick_time_s(tick, options_.base_period_ns) != time_s) {
    std::ostringstream message;
    message << std::setprecision(17) << "advance(" << time_s << ") is no tick's time at the base period of "
            << options_.base_period_ns << " ns (tick x " << period_s
            << " s): the link carries tick numbers, and the plant computes each tick's time so";
    return fail(channel_.fail(message.str()));
  }
  if (options_.mode == LinkMode::real_time) pacer_.wait_until(time_s);
  if (Status sent = channel_.send_tick(tick); !sent) return fail(Failure{sent.error()});
  ++ticks_;
  serve_tick(raise);
}

void RemotePlant::serve_tick(const plant::RaiseInterrupt& raise) {
  constexpr std::string_view awaiting = "TICK_DONE or INTERRUPT";
  while (usable()) {
    auto received = channel_.receive(awaiting);
    if (!received) return fail(Failure{received.error()});
    if (!received.value()) return fail(channel_.peer_failure("closed the link in the middle of a tick"));
    const ReceivedFrame frame = *received.value();
    if (frame.kind == FrameKind::tick_done) return;
    if (frame.kind != FrameKind::interrupt) return fail(unexpected(frame.kind, frame.payload, awaiting));
    run_interrupt(frame.payload, raise);
  }
}

void RemotePlant::run_interrupt(std::span<const std::uint8_t> payload, const plant::RaiseInterrupt& raise) {
  Interrupt interrupt;
  if (const FrameError error = parse(payload, interrupt); error != FrameError::none) {
    return fail(channel_.fail("the plant sent a bad INTERRUPT (" + std::string{describe(error)} + ")"));
  }
  ++interrupts_;
  std::string name{interrupt.name};  // the frame's bytes are reused by the task's own reads
  if (raise) raise(name);
  if (!usable()) return;
  if (Status answered = channel_.send_empty(FrameKind::interrupt_done); !answered) fail(Failure{answered.error()});
}

void RemotePlant::write(std::string_view resource, std::span<const double> values) {
  if (!usable()) return;
  if (Status sent = channel_.send_write(resource, values); !sent) fail(channel_.fail(sent.error()));
}

void RemotePlant::read(std::string_view resource, std::span<double> values) {
  std::fill(values.begin(), values.end(), 0.0);
  if (!usable()) return;
  if (Status sent = channel_.send_read(resource, ElementType::f64, values.size()); !sent) {
    return fail(channel_.fail(sent.error()));
  }
  auto received = channel_.receive("VALUES");
  if (!received) return fail(Failure{received.error()});
  if (!received.value()) return fail(channel_.peer_failure("closed the link instead of answering READ"));
  const ReceivedFrame frame = *received.value();
  if (frame.kind != FrameKind::values) return fail(unexpected(frame.kind, frame.payload, "VALUES"));
  Values answer;
  if (const FrameError error = parse(frame.payload, answer); error != FrameError::none) {
    return fail(channel_.fail("the plant sent bad VALUES (" + std::string{describe(error)} + ")"));
  }
  if (answer.values.type() != ElementType::f64 || answer.values.size() != values.size()) {
    return fail(channel_.fail("the plant answered READ '" + std::string{resource} + "' of " +
                              std::to_string(values.size()) + " f64 values with " +
                              std::to_string(answer.values.size()) + " " +
                              std::string{element_type_name(answer.values.type())}));
  }
  answer.values.copy_to(values);
}

}  // namespace duet::link
