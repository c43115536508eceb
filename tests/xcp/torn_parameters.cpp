// Tuning never tears: the main loop, as the XCP command handler would at the lowest priority, downloads an 8-word
// parameter group (all words equal) over and over while the model's 50 us base step checks that the words it reads
// are equal. Through the port's atomic write (interrupts masked for the copy) no step sees a torn group; with a plain
// copy, steps do.

#include <array>
#include <cstdint>

#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/cortex_m/masked_copy.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/executive_port.hpp"
#include "duet/rt/executive.hpp"
#include "duet/xcp/slave.hpp"

namespace {

namespace board = duet::mps2_an386;
using namespace duet::xcp;

struct ParameterGroup {
  std::uint32_t words[8];
};
ParameterGroup group{};
std::uint32_t torn_steps = 0;
std::uint32_t steps = 0;

void check_group() {
  const volatile ParameterGroup& seen = group;
  const std::uint32_t first = seen.words[0];
  for (std::size_t word = 1; word < std::size(seen.words); ++word) {
    if (seen.words[word] != first) {
      ++torn_steps;
      break;
    }
  }
  ++steps;
}
void nothing() {}

constexpr duet::rt::Task tasks[] = {{.name = "base", .priority = {1, 0}, .entry = check_group}};
constexpr duet::rt::ModelDescription model{
    .name = "torn parameters", .base_period_ns = 50'000, .tasks = tasks, .initialize = nothing, .terminate = nothing};
board::ExecutivePort port;
duet::rt::Executive<board::ExecutivePort, 1> executive{model, port};

// Downloads the group 1000 times through a slave whose writes go through `write`; returns the torn steps seen.
std::uint32_t hammer(AtomicWrite write) {
  const std::array regions{MemoryRegion{.name = "parameters",
                                        .address = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(&group)),
                                        .size = sizeof(group),
                                        .memory = reinterpret_cast<std::uint8_t*>(&group),
                                        .access = Access::read_write}};
  const SlaveConfiguration configuration{.memory = MemoryMap{regions}, .write_atomically = write};
  Slave slave{configuration};
  (void)slave.handle(std::array<std::uint8_t, 2>{0xFF, 0x00});
  torn_steps = 0;
  std::array<std::uint8_t, 8 + sizeof(group)> request{0xED, sizeof(group), 0, 0};
  for (std::size_t byte = 0; byte < 4; ++byte)
    request[4 + byte] = static_cast<std::uint8_t>(regions[0].address >> (8U * byte));
  for (std::uint32_t value = 1; value <= 1000; ++value) {
    for (std::size_t byte = 0; byte < sizeof(group); ++byte)
      request[8 + byte] = static_cast<std::uint8_t>(value >> (8U * (byte % 4)));
    if (slave.handle(request).front() != pid::response) return UINT32_MAX;
  }
  return torn_steps;
}

}  // namespace

DUET_MPS2_AN386_EXECUTIVE_HANDLERS(executive)

int main() {
  board::initialize();
  if (!board::ExecutivePort::configure(model) || executive.initialize() != duet::rt::TaskTableError::none) return 1;
  duet::cortex_m::enable_interrupts();
  if (!executive.begin()) return 1;
  const std::uint32_t torn_with_atomic_writes = hammer(duet::cortex_m::copy_with_interrupts_masked);
  const std::uint32_t torn_with_plain_writes = hammer(nullptr);
  executive.request_stop(duet::rt::StopReason::model);
  executive.end();
  executive.terminate();

  duet::TextBuffer<160> line;
  line.append("8-word group downloaded 1000 times under a 50 us step that checks it: ");
  line.append(torn_with_atomic_writes == 0 ? "no" : "SOME").append(" torn steps with atomic writes, ");
  line.append(torn_with_plain_writes == 0 ? "none" : "some").append(" with plain copies\n");
  duet::cortex_m::console_write(line.view());
  return torn_with_atomic_writes == 0 && torn_with_plain_writes > 0 && steps > 100 ? 0 : 1;
}
