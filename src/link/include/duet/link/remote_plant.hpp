#pragma once
// A plant in another process that looks exactly like one in this process: the firmware's side of the link
// (docs/LINK.md). write() and read() travel as WRITE and READ frames of f64 elements (a read waits for its VALUES);
// advance(t) sends TICK with the number of the tick whose time t is (tick_time_s), and serves what the plant sends back
// until TICK_DONE: for each INTERRUPT it calls raise(name), which runs the firmware's interrupt task there and then
// (its own writes and reads go over the link in the middle of the tick), and answers INTERRUPT_DONE. In lock-step a run
// through a RemotePlant is the run against the same plant in this process, bit for bit.
//
// The Plant interface has no way to fail, so the first failure (the plant gone, silent, or saying ERROR; a frame
// that makes no sense) is kept: from then on every call does nothing (reads give zeros), and ok() and error() say
// what happened. Check them after a run, or after each tick to stop early. Not thread-safe: one thread (or handlers
// that never run at once, as the executive's) calls a RemotePlant; every call may block up to the stream's timeout.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "duet/link/channel.hpp"
#include "duet/link/frame.hpp"
#include "duet/link/pacer.hpp"
#include "duet/link/stream.hpp"
#include "duet/plant/plant.hpp"
#include "duet/support/result.hpp"

namespace duet::link {

struct RemotePlantOptions {
  LinkMode mode = LinkMode::lock_step;
  // The firmware's base period, told to the plant in HELLO: the plant's time is a TICK's number times it. Not 0.
  std::uint32_t base_period_ns = 0;
};

class RemotePlant : public plant::Plant {
 public:
  // Says HELLO over `stream` and waits for HELLO_OK.
  [[nodiscard]] static Result<std::unique_ptr<RemotePlant>> connect(std::unique_ptr<Stream> stream,
                                                                    const RemotePlantOptions& options = {});
  // Says BYE, unless the link failed or close() was called.
  ~RemotePlant() override;

  // `time_s` must be a tick's time as tick_time_s computes it (what the executive's base ticks give); another
  // time fails the link, since a TICK carries only the tick's number.
  void advance(double time_s, const plant::RaiseInterrupt& raise) override;
  void write(std::string_view resource, std::span<const double> values) override;
  void read(std::string_view resource, std::span<double> values) override;

  // Says BYE and sends what is gathered; the link is done after that (calls do nothing).
  Status close();

  [[nodiscard]] bool ok() const { return status_.ok(); }
  // Precondition: !ok().
  [[nodiscard]] const std::string& error() const { return status_.error(); }
  [[nodiscard]] const Status& status() const { return status_; }

  [[nodiscard]] std::uint64_t ticks() const { return ticks_; }
  [[nodiscard]] std::uint64_t interrupts() const { return interrupts_; }
  [[nodiscard]] const Channel& channel() const { return channel_; }
  // Real time: the ticks whose time had passed when they were due (the firmware or the plant too slow).
  [[nodiscard]] const Pacer& pacer() const { return pacer_; }

 private:
  RemotePlant(std::unique_ptr<Stream> stream, const RemotePlantOptions& options);
  Status greet();  // HELLO, and HELLO_OK back
  [[nodiscard]] bool usable() const { return status_.ok() && !closed_; }
  void fail(Failure failure);
  // Serves what the plant sends during a tick, up to TICK_DONE.
  void serve_tick(const plant::RaiseInterrupt& raise);
  void run_interrupt(std::span<const std::uint8_t> payload, const plant::RaiseInterrupt& raise);
  // The peer's ERROR, or a frame out of place, as a failure.
  Failure unexpected(FrameKind kind, std::span<const std::uint8_t> payload, std::string_view awaiting);

  std::unique_ptr<Stream> stream_;
  Channel channel_;
  RemotePlantOptions options_;
  Status status_ = done();
  bool closed_ = false;
  Pacer pacer_;
  std::uint64_t ticks_ = 0;
  std::uint64_t interrupts_ = 0;
  std::string interrupt_name_;  // the INTERRUPT's name outlives its frame: raise() receives frames of its own
};

}  // namespace duet::link
