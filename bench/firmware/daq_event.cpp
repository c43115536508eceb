// Benchmark: the XCP slave's cost per DAQ event on the emulated Cortex-M4 (QEMU -icount shift=0, one instruction per
// virtual nanosecond): one DAQ list of 16 four-byte entries with a timestamp, sampled 10,000 times into a transmit
// queue locked by masking interrupts, as the firmware does. Issue #23 asks for at most 200 instructions per event (387
// before it); the benchmark checks that. Exits with 1 above it.

#include <array>
#include <cstdint>

#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/cmsdk_timer.hpp"
#include "duet/xcp/slave.hpp"

namespace {

namespace board = duet::mps2_an386;
using namespace duet::xcp;

constexpr board::CmsdkTimer clock{board::timer1_base};
constexpr std::uint32_t events = 10'000;
constexpr std::uint64_t target_instructions = 200;
constexpr std::uint32_t nanoseconds_per_cycle = 1'000'000'000U / board::peripheral_clock_hz;

std::uint32_t now() { return ~clock.value(); }

std::array<std::uint32_t, 16> signals{};
std::array<DaqList, 1> lists{};
std::array<Odt, 1> odts{};
std::array<OdtEntry, 16> entries{};
std::array<EventChannel, 1> channels{EventChannel{.name = "step"}};
// Room for every sample, so that the timed loop measures sampling alone, not a consumer.
std::array<std::uint8_t, events * 72 + 1024> queue_storage{};
TransmitQueue queue{queue_storage, {}};  // on the Cortex-M4 the lock is the interrupt mask

template <typename... Bytes>
void send(Slave& slave, Bytes... bytes) {
  const std::array<std::uint8_t, sizeof...(Bytes)> request{static_cast<std::uint8_t>(bytes)...};
  (void)slave.handle(request);
}

}  // namespace

int main() {
  board::initialize();
  clock.start_free_running();
  const auto address = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(signals.data()));
  const std::array regions{MemoryRegion{.name = "signals",
                                        .address = address,
                                        .size = sizeof(signals),
                                        .memory = reinterpret_cast<std::uint8_t*>(signals.data())}};
  const SlaveConfiguration configuration{.memory = MemoryMap{regions},
                                         .events = channels,
                                         .daq = {lists, odts, entries},
                                         .queue = &queue,
                                         .timestamp = now};
  Slave slave{configuration};
  send(slave, 0xFF, 0x00);
  send(slave, 0xD6);
  send(slave, 0xD5, 0, 1, 0);
  send(slave, 0xD4, 0, 0, 0, 1);
  send(slave, 0xD3, 0, 0, 0, 0, 16);
  send(slave, 0xE2, 0, 0, 0, 0, 0);
  for (std::uint32_t entry = 0; entry < 16; ++entry) {
    const std::uint32_t at = address + 4 * entry;
    send(slave, 0xE1, 0xFF, 4, 0, static_cast<std::uint8_t>(at), static_cast<std::uint8_t>(at >> 8U),
         static_cast<std::uint8_t>(at >> 16U), static_cast<std::uint8_t>(at >> 24U));
  }
  send(slave, 0xE0, 0x10, 0, 0, 0, 0, 1, 0);  // timestamps, event 0, prescaler 1
  send(slave, 0xDE, 1, 0, 0);

  // The loop alone, then the loop with sampling: the difference is the sampling.
  const std::uint32_t empty_start = now();
  for (std::uint32_t event = 0; event < events; ++event) asm volatile("" ::: "memory");
  const std::uint32_t empty_cycles = now() - empty_start;
  const std::uint32_t start = now();
  for (std::uint32_t event = 0; event < events; ++event) {
    slave.on_event(0);
    asm volatile("" ::: "memory");
  }
  const std::uint32_t cycles = now() - start - empty_cycles;
  const std::uint64_t instructions = static_cast<std::uint64_t>(cycles) * nanoseconds_per_cycle / events;

  std::array<std::uint8_t, 128> packet{};
  std::uint32_t packets = 0;
  while (queue.pop(packet) == 1 + 4 + 64) ++packets;
  duet::TextBuffer<192> line;
  line.append("DAQ event, one list of 16 x 4 bytes with timestamp: ").append(instructions);
  line.append(" instructions per event over ").append(events).append(" events (").append(packets);
  line.append(" samples queued, ").append(slave.overloads()).append(" overloads; target <= 200)\n");
  duet::cortex_m::console_write(line.view());
  return packets == events && instructions <= target_instructions ? 0 : 1;
}
