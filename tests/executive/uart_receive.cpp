// A UART's receive interrupt runs an interrupt task: every byte that arrives on UART0 is taken by the task, and a
// newline makes the model ask the executive to stop. The text comes from the test's input file on QEMU's stdin.

#include <array>
#include <cstddef>

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/cmsdk_uart.hpp"
#include "duet/rt/executive.hpp"
#include "traced_port.hpp"

namespace {

namespace board = duet::mps2_an386;

duet::tests::TracedPort port;
std::array<char, 64> received{};
std::size_t received_count = 0;

void receive_byte();
void nothing() {}

constexpr duet::rt::Task tasks[] = {
    {.name = "base", .priority = {2, 0}, .entry = nothing},
    {.name = "uart0 receive",
     .kind = duet::rt::TaskKind::interrupt,
     .interrupt = board::uart0_receive_interrupt,
     .priority = {1, 0},
     .entry = receive_byte},
};
// The final tick only bounds a run whose input never comes; the newline stops it long before.
constexpr duet::rt::ModelDescription model{.name = "uart receive",
                                           .base_period_ns = 1'000'000,
                                           .tasks = tasks,
                                           .initialize = nothing,
                                           .terminate = nothing,
                                           .final_tick = 60'000};

duet::rt::Executive<duet::tests::TracedPort, 2> executive{model, port};

void receive_byte() {
  char byte = 0;
  while (board::console_uart().read(byte)) {
    if (byte == '\n') {
      executive.request_stop(duet::rt::StopReason::model);
    } else if (received_count < received.size()) {
      received[received_count++] = byte;
    }
  }
}

}  // namespace

DUET_MPS2_AN386_EXECUTIVE_HANDLERS(executive)
extern "C" void UART0_RX_IRQHandler() { executive.on_interrupt_task(1); }

int main() {
  board::initialize();
  board::console_uart().enable_receive_interrupt();
  if (!duet::mps2_an386::run_model(executive, model)) return 1;

  duet::TextBuffer<128> line;
  line.append("received '").append(std::string_view{received.data(), received_count}).append("', stopped by ");
  line.append(executive.stop_reason() == duet::rt::StopReason::model ? "the model" : "something else").append('\n');
  duet::cortex_m::console_write(line.view());
  return executive.stop_reason() == duet::rt::StopReason::model ? 0 : 1;
}
