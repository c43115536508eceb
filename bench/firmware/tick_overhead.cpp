#include "tick_overhead.hpp"

namespace duet::bench {

CountingExecutive* running_executive = nullptr;

namespace {
void nothing() {}
}  // namespace

std::uint32_t idle_rounds_of(const rt::ModelDescription& model) {
  CountingPort port;
  CountingExecutive executive{model, port};
  running_executive = &executive;
  const bool ran = mps2_an386::run_model(executive, model);
  running_executive = nullptr;
  return ran ? port.idle_rounds : 0;
}

std::uint64_t hundredths_of_instructions_per_tick(std::uint32_t period_ns, std::uint32_t ticks, void (*step)(),
                                                  unsigned icount_shift) {
  const rt::Task many[] = {{.name = "base", .priority = {1, 0}, .entry = step}};
  const rt::ModelDescription many_ticks{.name = "many ticks",
                                        .base_period_ns = period_ns,
                                        .tasks = many,
                                        .initialize = nothing,
                                        .terminate = nothing,
                                        .final_tick = ticks};
  const rt::ModelDescription one_tick{.name = "one tick",
                                      .base_period_ns = period_ns * ticks,
                                      .tasks = many,
                                      .initialize = nothing,
                                      .terminate = nothing,
                                      .final_tick = 1};
  const std::uint64_t busy_rounds = idle_rounds_of(many_ticks);
  const std::uint64_t idle_rounds = idle_rounds_of(one_tick);
  if (idle_rounds <= busy_rounds) return 0;
  const std::uint64_t instructions = (static_cast<std::uint64_t>(period_ns) * ticks) >> icount_shift;
  // lost rounds * (instructions per round) / (ticks - 1): the single tick of the second run costs one tick too.
  return (idle_rounds - busy_rounds) * instructions * 100U / idle_rounds / (ticks - 1U);
}

}  // namespace duet::bench
