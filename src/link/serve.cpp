#include "duet/link/serve.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "duet/link/channel.hpp"
#include "duet/link/pacer.hpp"

namespace duet::link {
namespace {

// One firmware's session: a handler per kind of frame the firmware may send.
class Server {
 public:
  Server(plant::Plant& plant, Stream& stream, const ServeOptions& options, ServeSummary& summary)
      : plant_(plant),
        channel_(stream, "the firmware"),
        options_(options),
        raise_([this](std::string_view name) { raise(name); }),
        summary_(summary) {}

  Status run() {
    if (Status greeted = greet(); !greeted) return greeted;
    constexpr std::string_view awaiting = "WRITE, READ, TICK or BYE";
    for (;;) {
      auto received = channel_.receive(awaiting);
      if (!received) return Failure{received.error()};
      if (!received.value()) return done();  // the firmware went between frames: a run may end so
      const ReceivedFrame frame = *received.value();
      Status handled = done();
      switch (frame.kind) {
        case FrameKind::write: handled = on_write(frame.payload); break;
        case FrameKind::read: handled = on_read(frame.payload); break;
        case FrameKind::tick: handled = on_tick(frame.payload); break;
        case FrameKind::bye: summary_.said_bye = true; return done();
        default: handled = unexpected(frame, awaiting); break;
      }
      if (!handled) return handled;
    }
  }

 private:
  Status greet() {
    auto received = channel_.receive("HELLO");
    if (!received) return Failure{received.error()};
    if (!received.value()) return channel_.peer_failure("closed the link before saying HELLO");
    const ReceivedFrame frame = *received.value();
    if (frame.kind != FrameKind::hello) return unexpected(frame, "HELLO");
    if (const FrameError error = parse(frame.payload, summary_.hello); error != FrameError::none) {
      return channel_.fail("the firmware sent a bad HELLO (" + std::string{describe(error)} + ")");
    }
    if (summary_.hello.version != protocol_version) {
      return channel_.fail("the firmware speaks link protocol version " + std::to_string(summary_.hello.version) +
                           "; this plant speaks " + std::to_string(protocol_version));
    }
    if (Status answered = channel_.send_hello_ok({protocol_version}); !answered) return answered;
    return channel_.flush();
  }

  Status on_write(std::span<const std::uint8_t> payload) {
    Write write;
    if (const FrameError error = parse(payload, write); error != FrameError::none) {
      return channel_.fail("the firmware sent a bad WRITE (" + std::string{describe(error)} + ")");
    }
    values_.resize(write.values.size());
    write.values.copy_to(values_);
    ++summary_.writes;
    plant_.write(write.resource, values_);
    return done();
  }

  Status on_read(std::span<const std::uint8_t> payload) {
    Read read;
    if (const FrameError error = parse(payload, read); error != FrameError::none) {
      return channel_.fail("the firmware sent a bad READ (" + std::string{describe(error)} + ")");
    }
    if (read.count > max_read_values) {
      return channel_.fail("the firmware asked for " + std::to_string(read.count) + " values of '" +
                           std::string{read.resource} + "'; a VALUES frame holds at most " +
                           std::to_string(max_read_values));
    }
    values_.assign(read.count, 0.0);
    ++summary_.reads;
    plant_.read(read.resource, values_);
    return channel_.send_values(values_);
  }

  Status on_tick(std::span<const std::uint8_t> payload) {
    Tick tick;
    (void)parse(payload, tick);  // the decoder checked its one field's length
    if (!std::isfinite(tick.time_s)) return channel_.fail("the firmware sent a TICK whose time is not a number");
    ++summary_.ticks;
    summary_.last_tick_s = tick.time_s;
    if (options_.paced) {
      pacer_.wait_until(tick.time_s);
      summary_.pacing = pacer_.report();
    }
    plant_.advance(tick.time_s, raise_);
    if (failure_) return *failure_;
    return channel_.send_empty(FrameKind::tick_done);
  }

  // What the plant calls during advance(): the firmware runs the interrupt task, whose frames are served here.
  void raise(std::string_view name) {
    if (failure_) return;  // the link is gone; the plant finishes its advance() in vain
    if (Status sent = channel_.send_interrupt(name); !sent) {
      failure_ = channel_.fail("the plant raised an interrupt the link cannot carry: " + sent.error());
      return;
    }
    ++summary_.interrupts;
    const std::string awaiting = "WRITE, READ or INTERRUPT_DONE for interrupt '" + std::string{name} + "'";
    for (;;) {
      auto received = channel_.receive(awaiting);
      Status handled = done();
      if (!received) {
        handled = Failure{received.error()};
      } else if (!received.value()) {
        handled = channel_.peer_failure("closed the link during interrupt '" + std::string{name} + "'");
      } else {
        const ReceivedFrame frame = *received.value();
        if (frame.kind == FrameKind::interrupt_done) return;
        handled = frame.kind == FrameKind::write  ? on_write(frame.payload)
                  : frame.kind == FrameKind::read ? on_read(frame.payload)
                                                  : unexpected(frame, awaiting);
      }
      if (!handled) {
        failure_ = Failure{handled.error()};
        return;
      }
    }
  }

  // The firmware's ERROR, or a frame out of place.
  Status unexpected(const ReceivedFrame& frame, std::string_view awaiting) {
    if (frame.kind == FrameKind::error) {
      ErrorText text;
      (void)parse(frame.payload, text);
      return channel_.peer_failure("reported an error: " + std::string{text.text});
    }
    return channel_.fail("the firmware sent " + std::string{kind_name(frame.kind)} + " where the plant awaited " +
                         std::string{awaiting});
  }

  plant::Plant& plant_;
  Channel channel_;
  ServeOptions options_;
  Pacer pacer_;
  plant::RaiseInterrupt raise_;
  std::vector<double> values_;
  ServeSummary& summary_;
  std::optional<Failure> failure_;
};

}  // namespace

Status serve(plant::Plant& plant, Stream& stream, const ServeOptions& options, ServeSummary& summary) {
  summary = {};
  return Server{plant, stream, options, summary}.run();
}

Result<ServeSummary> serve(plant::Plant& plant, Stream& stream, const ServeOptions& options) {
  ServeSummary summary;
  if (Status served = serve(plant, stream, options, summary); !served) return Failure{served.error()};
  return summary;
}

}  // namespace duet::link
