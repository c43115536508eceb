#include "duet/link/serve.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "duet/blocks/convert.hpp"
#include "duet/link/channel.hpp"
#include "duet/link/pacer.hpp"
#include "duet/support/number_text.hpp"

namespace duet::link {
namespace {

// Calls `run` with a value of the C++ type of `type` (bool, std::uint8_t, ..., double), for a template to take.
template <typename Run>
auto with_element_type(ElementType type, Run&& run) {
  switch (type) {
    case ElementType::boolean: return run(bool{});
    case ElementType::u8: return run(std::uint8_t{});
    case ElementType::u16: return run(std::uint16_t{});
    case ElementType::u32: return run(std::uint32_t{});
    case ElementType::f32: return run(float{});
    case ElementType::f64: break;
  }
  return run(double{});
}

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
      if (!summary_.plant_stop.empty()) return done();
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
                           "; this plant speaks version " + std::to_string(protocol_version) + " only");
    }
    if (summary_.hello.base_period_ns == 0) {
      return channel_.fail("the firmware's HELLO gives a base period of 0 ns: the plant's time is tick x base period");
    }
    const double base_period_s = static_cast<double>(summary_.hello.base_period_ns) * 1e-9;
    if (Status started = plant_.start(base_period_s); !started) {
      return channel_.fail("the plant cannot start: " + started.error());
    }
    if (Status answered = channel_.send_hello_ok({protocol_version}); !answered) return answered;
    return channel_.flush();
  }

  // The plant takes doubles: each element becomes one as the interpreter converts it (duet::blocks::convert), so that
  // the plant sees the numbers `duet sim` gives it.
  Status on_write(std::span<const std::uint8_t> payload) {
    Write write;
    if (const FrameError error = parse(payload, write); error != FrameError::none) {
      return channel_.fail("the firmware sent a bad WRITE (" + std::string{describe(error)} + ")");
    }
    values_.resize(write.values.size());
    with_element_type(write.values.type(), [&]<typename T>(T) {
      for (std::size_t k = 0; k < values_.size(); ++k) values_[k] = blocks::convert<double>(write.values.at<T>(k));
    });
    ++summary_.writes;
    plant_.write(write.resource, values_);
    return done();
  }

  // The plant answers in doubles, which go back in the type the firmware asked for, converted as the interpreter
  // converts them: saturated, NaN to 0, rounded to nearest for f32.
  Status on_read(std::span<const std::uint8_t> payload) {
    Read read;
    if (const FrameError error = parse(payload, read); error != FrameError::none) {
      return channel_.fail("the firmware sent a bad READ (" + std::string{describe(error)} + ")");
    }
    if (read.count > max_read_count(read.type)) {
      return channel_.fail("the firmware asked for " + std::to_string(read.count) + " " +
                           std::string{element_type_name(read.type)} + " values of '" + std::string{read.resource} +
                           "'; a VALUES frame holds at most " + std::to_string(max_read_count(read.type)));
    }
    values_.assign(read.count, 0.0);
    ++summary_.reads;
    plant_.read(read.resource, values_);
    return with_element_type(read.type, [&]<typename T>(T) {
      // std::vector<bool> holds no span: a plain array of the type instead.
      const std::unique_ptr<T[]> converted{new T[values_.size()]};
      for (std::size_t k = 0; k < values_.size(); ++k) converted[k] = blocks::convert<T>(values_[k]);
      return channel_.send_values(std::span<const T>{converted.get(), values_.size()});
    });
  }

  Status on_tick(std::span<const std::uint8_t> payload) {
    Tick tick;
    (void)parse(payload, tick);  // the decoder checked its one field's length
    const double time_s = tick_time_s(tick.tick, summary_.hello.base_period_ns);
    ++summary_.ticks;
    summary_.last_tick_s = time_s;
    if (options_.paced) {
      pacer_.wait_until(time_s);
      summary_.pacing = pacer_.report();
    }
    plant_.advance(time_s, raise_);
    if (failure_) return *failure_;
    if (const std::optional<plant::Plant::Halt> halt = plant_.halted()) return halted(*halt, time_s);
    return channel_.send_empty(FrameKind::tick_done);
  }

  // The plant cannot go on (an imported FMU that failed or asked to stop): the firmware is told with ERROR, the only
  // ending a plant can give a tick. A failure fails the session; a request to stop ends it, kept in the summary.
  Status halted(const plant::Plant::Halt& halt, double time_s) {
    const std::string at = "at t = " + shortest_text(time_s) + " s: " + halt.reason;
    if (halt.failed) return channel_.fail("the plant failed " + at);
    summary_.plant_stop = "the plant asked to stop " + at;
    (void)channel_.fail(summary_.plant_stop);
    return done();
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
