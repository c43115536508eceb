#pragma once
// The plant's side of the link (docs/LINK.md): answers one firmware over a stream until it says BYE or the stream
// ends. HELLO first (answered HELLO_OK); then WRITE goes to plant.write, READ to plant.read and back as VALUES, and
// TICK(t) to plant.advance(t, raise), whose raise(name) sends INTERRUPT and serves the interrupt task's WRITE and
// READ frames until INTERRUPT_DONE; TICK_DONE ends the tick. The plant does not know it is remote, nor whether the
// firmware runs in lock-step or in real time.

#include <cstdint>

#include "duet/link/frame.hpp"
#include "duet/link/stream.hpp"
#include "duet/plant/plant.hpp"
#include "duet/support/result.hpp"

namespace duet::link {

struct ServeSummary {
  Hello hello;  // what the firmware said it is
  std::uint64_t ticks = 0;
  std::uint64_t interrupts = 0;
  std::uint64_t writes = 0;
  std::uint64_t reads = 0;
  bool said_bye = false;  // false: the stream ended without BYE
};

// Blocks until the firmware is done, each wait up to the stream's timeout. A frame that makes no sense here, a
// timeout or a stream cut in the middle of a frame or of a tick is a failure, of which the firmware is told with an
// ERROR frame; an ERROR from the firmware is a failure too.
[[nodiscard]] Result<ServeSummary> serve(plant::Plant& plant, Stream& stream);

}  // namespace duet::link
