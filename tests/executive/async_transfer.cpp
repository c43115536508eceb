// An interrupt task writes 32-word samples through AsyncTransfer while the base rate, which it preempts, reads them
// slowly, word by word: no sample may arrive torn. The same traffic through a plain shared variable tears (about 300
// of 500 samples), which shows that the test would notice.

#include <array>
#include <cstdint>

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/cmsdk_dual_timer.hpp"
#include "duet/rt/executive.hpp"
#include "duet/rt/rate_transition.hpp"
#include "traced_port.hpp"

namespace {

namespace board = duet::mps2_an386;

struct Sample {
  std::array<std::uint32_t, 32> words;  // every word holds the sample's number
};

constexpr board::CmsdkDualTimer writer_timer{board::dual_timer_base};
constexpr std::uint32_t writer_period_cycles = 7'919;  // 317 us: prime, so it drifts across the reader's steps
constexpr std::uint32_t cycles_per_word = 150;         // 32 words: 192 us

duet::tests::TracedPort port;
duet::rt::AsyncTransfer<Sample> transfer;
Sample shared;  // the control: written and read with no protection
std::uint32_t written = 0;

struct Tally {
  std::uint32_t reads = 0;
  std::uint32_t torn = 0;
  std::uint32_t went_back = 0;
  std::uint32_t last = 0;
};
Tally through_transfer;
Tally through_shared;

void read_slowly(const Sample& sample, Tally& tally) {
  Sample copy{};
  for (std::size_t word = 0; word < copy.words.size(); ++word) {
    copy.words[word] = *static_cast<const volatile std::uint32_t*>(&sample.words[word]);
    const std::uint32_t start = port.cycles();
    while (port.cycles() - start < cycles_per_word) {
    }
  }
  ++tally.reads;
  for (std::uint32_t word : copy.words) {
    if (word != copy.words[0]) {
      ++tally.torn;
      break;
    }
  }
  if (copy.words[0] < tally.last) ++tally.went_back;
  tally.last = copy.words[0];
}

void reader_step() {
  read_slowly(transfer.read(), through_transfer);
  read_slowly(shared, through_shared);
}

void writer_task() {
  Sample sample;
  sample.words.fill(++written);
  transfer.write(sample);
  for (std::uint32_t& word : shared.words) *static_cast<volatile std::uint32_t*>(&word) = written;
}

void nothing() {}

constexpr duet::rt::Task tasks[] = {
    {.name = "reader", .priority = {2, 0}, .entry = reader_step},
    {.name = "writer",
     .kind = duet::rt::TaskKind::interrupt,
     .interrupt = board::dual_timer_interrupt,
     .priority = {1, 0},
     .entry = writer_task},
};
constexpr duet::rt::ModelDescription model{.name = "async transfer",
                                           .base_period_ns = 1'000'000,
                                           .tasks = tasks,
                                           .initialize = nothing,
                                           .terminate = nothing,
                                           .final_tick = 500};

duet::rt::Executive<duet::tests::TracedPort, 2> executive{model, port};

// How many samples tear through the plain variable depends on how long the code takes, so the report only says
// whether any did; the count through AsyncTransfer must be exactly zero.
void print_tally(std::string_view name, const Tally& tally) {
  duet::TextBuffer<128> line;
  line.append(name).append(": ").append(tally.reads).append(" reads, ");
  line.append(tally.torn == 0 ? "none" : "some").append(" torn, ");
  line.append(tally.went_back).append(" older than the one before\n");
  duet::cortex_m::console_write(line.view());
}

}  // namespace

DUET_MPS2_AN386_EXECUTIVE_HANDLERS(executive)
extern "C" void DUALTIMER_IRQHandler() {
  writer_timer.clear_interrupt();
  executive.on_interrupt_task(1);
}

int main() {
  board::initialize();
  duet::cortex_m::console_write("32-word samples written every 317 us by an interrupt, read in 192 us every 1 ms\n");
  writer_timer.start_periodic_interrupt(writer_period_cycles);
  const bool ran = duet::mps2_an386::run_model(executive, model);
  writer_timer.stop();
  if (!ran) return 1;

  print_tally("through AsyncTransfer", through_transfer);
  print_tally("through a plain variable", through_shared);
  const bool transfer_intact = through_transfer.torn == 0 && through_transfer.went_back == 0;
  const bool control_tore = through_shared.torn > 0;
  return transfer_intact && control_tore && through_transfer.reads == 500 ? 0 : 1;
}
