// The self-balancing robot's firmware on the emulated Cortex-M4 (processor in the loop): the generated model
// (apps/balbot/generated) on the executive, its hardware the simulated robot over the plant link (semihosting pipes,
// plant_link.hpp), XCP on UART0 and the application channel on UART1 (host_channels.cpp), and a console on UART3
// that says every second of model time how the executive is doing (status_report.hpp). README.md, "Processor in the
// loop", has the picture.
//
// Command line (QEMU's -semihosting-config arg=...): --link DIRECTORY [--duration SECONDS]. With a duration the model
// stops after
// the ticks `duet sim` runs for it (0 to duration / 1 ms), the session with the plant ends with BYE and QEMU exits
// with 0 if no task overran and the link held, 1 otherwise; without one it runs until QEMU is stopped.

#include <array>
#include <bit>
#include <cstdint>
#include <string_view>

#include "balbot.hpp"
#include "command_line.hpp"
#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/cortex_m/semihosting.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/cmsdk_uart.hpp"
#include "duet/mps2_an386/executive_port.hpp"
#include "duet/mps2_an386/executive_report.hpp"
#include "duet/rt/executive.hpp"
#include "robot_channels.hpp"
#include "robot_firmware.hpp"
#include "status_report.hpp"

namespace balbot::pil {
namespace {

namespace board = duet::mps2_an386;
namespace cortex_m = duet::cortex_m;
namespace rt = duet::rt;

constexpr unsigned console_uart = 3;
constexpr std::size_t task_capacity = std::size(balbot::tasks);

// The board's executive port, plus DAQ after every task and the console's report between ticks.
class RobotPort : public board::PlantLinkedPort {
 public:
  void task_finished(std::size_t task) { firmware::on_task_finished(task); }
  void idle();
};

rt::ModelDescription model = balbot::description;
RobotPort port;
rt::Executive<RobotPort, task_capacity> executive{model, port};
board::PlantLink link;
StatusReport report{model};

// The task each plant interrupt line runs (its index in the task table); lines without one run nothing.
constexpr std::uint8_t no_task = 0xFF;
std::array<std::uint8_t, board::device_interrupt_count> task_of_line = [] {
  std::array<std::uint8_t, board::device_interrupt_count> none{};
  none.fill(no_task);
  return none;
}();

// Spins, as the board's port does: under QEMU's -icount,sleep=off a core sleeping in WFI misses every other tick
// of the base timer (measured: 50,000 cycles of the 25 MHz timer per 1 ms tick instead of 25,000, so the core load
// read half of what it is). At shift=2 a millisecond is 250,000 instructions, most of them this loop's: QEMU
// translates a NOP to nothing but the count, so a round of 512 of them costs it about what the loop's few other
// instructions cost, and the idle millisecond far less wall time than a tight loop (0.33 ms; docs/LINK.md, "Pacing").
// The executive measures tasks by the timer, so the core load does not depend on what idling executes.
void RobotPort::idle() {
  report.between_ticks(executive);
  // Inline, so that a round needs no return (an indirect jump QEMU looks up in its tables: 0.5 to 0.75 of a
  // processor for QEMU's thread against 0.45 to 0.65 inline); written out rather than .rept, which GCC would count
  // as one instruction when it sizes the branches around it.
#define BALBOT_NOP8 "nop\n nop\n nop\n nop\n nop\n nop\n nop\n nop\n"
#define BALBOT_NOP64 BALBOT_NOP8 BALBOT_NOP8 BALBOT_NOP8 BALBOT_NOP8 BALBOT_NOP8 BALBOT_NOP8 BALBOT_NOP8 BALBOT_NOP8
  asm volatile(BALBOT_NOP64 BALBOT_NOP64 BALBOT_NOP64 BALBOT_NOP64 BALBOT_NOP64 BALBOT_NOP64 BALBOT_NOP64 BALBOT_NOP64);
#undef BALBOT_NOP64
#undef BALBOT_NOP8
}

// Every interrupt task comes from the plant, on a plant line, more urgent than the base rate: the plant link runs it
// while the base tick's handler waits for the plant (plant_link.hpp).
bool map_plant_interrupts(duet::TextBuffer<200>& problem) {
  for (std::size_t index = 0; index < model.tasks.size(); ++index) {
    const rt::Task& task = model.tasks[index];
    if (task.kind != rt::TaskKind::interrupt) continue;
    bool plant_line = false;
    for (const board::PlantInterrupt& interrupt : board::plant_interrupts)
      plant_line |= interrupt.line == task.interrupt;
    if (!plant_line) {
      problem.append("task ").append(task.name).append(" is not triggered by an interrupt of the plant");
      return false;
    }
    if (task.priority.group >= model.tasks[0].priority.group) {
      problem.append("task ").append(task.name).append(" must be more urgent than the base rate");
      return false;
    }
    task_of_line[task.interrupt] = static_cast<std::uint8_t>(index);
  }
  return true;
}

[[noreturn]] void fail(std::string_view problem, int exit_code) {
  cortex_m::console_write("error: ");
  cortex_m::console_write(problem);
  cortex_m::console_write("\n");
  cortex_m::halt(exit_code);
}

}  // namespace

board::PlantLink& plant_link() { return link; }

}  // namespace balbot::pil

namespace balbot::firmware {

std::uint32_t executive_cycles() { return pil::RobotPort::cycles(); }
void record_section(duet::rt::Ceiling ceiling, std::uint32_t cycles) { pil::executive.record_section(ceiling, cycles); }

}  // namespace balbot::firmware

using balbot::pil::executive;

extern "C" void TIMER0_IRQHandler() {
  duet::mps2_an386::ExecutivePort::acknowledge_base_tick();
  balbot::pil::host_channels_new_tick();
  if (executive.state() == duet::rt::ExecutiveState::running) {
    // duet sim's order: the plant moves to the tick's time (its interrupts run their tasks), then the tick's steps.
    balbot::pil::link.tick(executive.ticks());
    if (!balbot::pil::link.ok()) executive.request_stop(duet::rt::StopReason::external);
  }
  executive.on_base_tick();
}
extern "C" void Software1_IRQHandler() { executive.on_rate_interrupt(1); }
extern "C" void PlantInterrupt_IRQHandler() {
  const std::uint32_t line = duet::cortex_m::active_exception() - 16U;
  const std::uint8_t task = balbot::pil::task_of_line[line];
  if (task != balbot::pil::no_task) executive.on_interrupt_task(task);
}

int main() {
  using namespace balbot::pil;
  board::select_console(console_uart);
  board::initialize();

  std::array<char, 128> command_line_buffer{};
  const CommandLine arguments = parse_command_line(cortex_m::semihosting::command_line(command_line_buffer));
  if (!arguments.problem.view().empty()) fail(arguments.problem.view(), 2);
  // As duet sim counts them: ticks 0 to duration / period, so the model stops after the one past the last.
  if (arguments.duration_ms != 0) model.final_tick = arguments.duration_ms * 1'000'000ULL / model.base_period_ns + 1U;

  duet::TextBuffer<200> problem;
  if (!map_plant_interrupts(problem)) fail(problem.view(), 2);
  start_host_channels();
  report.started(arguments.duration_ms);
  if (!link.connect(arguments.to_plant, arguments.from_plant, model.base_period_ns)) fail(link.error(), 1);

  if (!board::run_model(executive, model)) fail("the model does not fit the board", 2);
  link.bye();
  report.ended(executive, link);
  // Where the model ended, as float bits: to compare with the same generated code on the PC.
  duet::TextBuffer<80> signals;
  signals.append("balbot-signals theta_bits=").append_hex(std::bit_cast<std::uint32_t>(balbot::signals.theta));
  signals.append(" y_bits=").append_hex(std::bit_cast<std::uint32_t>(balbot::signals.y)).append('\n');
  cortex_m::console_write(signals.view());
  const bool overran = board::total_overruns(executive, model) != 0;
  return link.ok() && !overran ? 0 : 1;
}
