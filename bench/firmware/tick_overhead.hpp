#pragma once
// Instructions the executive spends per base tick on the emulated Cortex-M4, measured without instrumenting the tick:
// two runs of the same length, one with N ticks and one with a single tick, count how often the idle loop goes round.
// The ticks' share of the time is the idle time the first run lost; one instruction is 2^shift virtual nanoseconds
// under QEMU's -icount shift=<shift>, so a run of N periods of P ns executes N * P / 2^shift instructions.

#include <cstdint>

#include "duet/mps2_an386/executive_port.hpp"
#include "duet/rt/executive.hpp"

namespace duet::bench {

// The board's port, with an idle loop that counts its rounds.
struct CountingPort : mps2_an386::ExecutivePort {
  void idle() { ++idle_rounds; }
  std::uint32_t idle_rounds = 0;
};

using CountingExecutive = rt::Executive<CountingPort, 1>;

// The executive whose base tick the board's timer interrupt runs now.
extern CountingExecutive* running_executive;

// Runs `model` on a fresh executive and returns how often the idle loop went round.
std::uint32_t idle_rounds_of(const rt::ModelDescription& model);

// Instructions per tick, in hundredths, of a model with base period `period_ns` whose base step is `step`, over
// `ticks` ticks, under -icount shift=`icount_shift` (one instruction is 2^shift virtual nanoseconds).
std::uint64_t hundredths_of_instructions_per_tick(std::uint32_t period_ns, std::uint32_t ticks, void (*step)(),
                                                  unsigned icount_shift = 0);

}  // namespace duet::bench
