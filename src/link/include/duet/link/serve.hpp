#pragma once
// The plant's side of the link (docs/LINK.md): answers one firmware over a stream until it says BYE or the stream
// ends. HELLO first (answered HELLO_OK); then WRITE goes to plant.write, READ to plant.read and back as VALUES, and
// TICK(t) to plant.advance(t, raise), whose raise(name) sends INTERRUPT and serves the interrupt task's WRITE and
// READ frames until INTERRUPT_DONE; TICK_DONE ends the tick. The plant does not know it is remote, nor whether the
// firmware runs in lock-step or in real time. The server may pace the session itself (ServeOptions::paced) when the
// firmware cannot: firmware on an emulator with a virtual clock runs as fast as the emulator goes.

#include <cstdint>
#include <string>

#include "duet/link/frame.hpp"
#include "duet/link/pacer.hpp"
#include "duet/link/stream.hpp"
#include "duet/plant/plant.hpp"
#include "duet/support/result.hpp"

namespace duet::link {

struct ServeOptions {
  // Real time kept by the plant: each TICK(t) waits until the wall clock reaches t, counted from the first TICK
  // (Pacer), before the plant advances; the firmware waits for TICK_DONE meanwhile. A TICK that comes after its
  // time is served at once; ServeSummary::pacing says how late each went.
  bool paced = false;
};

struct ServeSummary {
  Hello hello;  // what the firmware said it is
  std::uint64_t ticks = 0;
  std::uint64_t interrupts = 0;
  std::uint64_t writes = 0;
  std::uint64_t reads = 0;
  double last_tick_s = 0;  // the time of the last TICK: how far the session went
  bool said_bye = false;   // false: the stream ended without BYE
  // Why the plant ended the session, when it asked to stop (an imported FMU's request); empty otherwise.
  std::string plant_stop;
  // Paced sessions: how late the TICKs went, and whether the firmware could have kept real time (Pacer).
  PacingReport pacing;
};

// Blocks until the firmware is done, each wait up to the stream's timeout. A frame that makes no sense here, a
// timeout or a stream cut in the middle of a frame or of a tick is a failure, of which the firmware is told with an
// ERROR frame; an ERROR from the firmware is a failure too.
[[nodiscard]] Result<ServeSummary> serve(plant::Plant& plant, Stream& stream, const ServeOptions& options = {});
// The same, with the counts kept in `summary` as the session goes: what a session that failed, or was cut by
// stopping the firmware, got to.
[[nodiscard]] Status serve(plant::Plant& plant, Stream& stream, const ServeOptions& options, ServeSummary& summary);

}  // namespace duet::link
