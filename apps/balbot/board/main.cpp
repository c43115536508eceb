// The self-balancing robot's firmware on the STM32MP15's Cortex-M4: the generated model (apps/balbot/generated),
// the same as on the PC and on QEMU, on the executive at TIM7's 1 ms, its hardware the robot's peripherals
// (robot_peripherals.cpp), XCP and the application channel over RPMsg to Linux (linux_channels.cpp), a log in the
// remoteproc trace buffer. Control starts at once; the link to Linux comes up when Linux's RPMsg driver is ready.
// docs/BOARD.md has the bring-up steps. None of it has run on silicon yet.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "account_publisher.hpp"
#include "balbot.hpp"
#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/rt/executive.hpp"
#include "duet/stm32mp15/board.hpp"
#include "duet/stm32mp15/executive_port.hpp"
#include "duet/stm32mp15/fault.hpp"
#include "linux_channels.hpp"
#include "robot_channels.hpp"
#include "robot_peripherals.hpp"

namespace balbot::board {
namespace {

namespace chip = duet::stm32mp15;
namespace cortex_m = duet::cortex_m;
namespace rt = duet::rt;

constexpr std::size_t task_capacity = std::size(balbot::tasks);

// The board's executive port, plus DAQ after every task and, between ticks, the link to Linux and the account.
class RobotPort : public chip::ExecutivePort {
 public:
  void task_finished(std::size_t task) { firmware::on_task_finished(task); }
  void idle();
};

const rt::ModelDescription& model = balbot::description;
RobotPort port;
rt::Executive<RobotPort, task_capacity> executive{model, port};
firmware::AccountPublisher account{model};
std::uint64_t next_account_tick = 0;

void RobotPort::idle() {
  (void)firmware::microseconds();  // at least once per wrap of the cycle counter (20.5 s), DAQ or not
  if (poll_linux() && executive.ticks() >= next_account_tick) {
    next_account_tick = executive.ticks() + 1'000'000'000U / model.base_period_ns;  // every second of model time
    account.publish(executive, chip::core_clock_hz);
  }
  ExecutivePort::idle();
}

// The index of the model's task that interrupt `name` triggers (its place in the task table); a name the model has no
// task of is a compile error (rt::task_index): every interrupt task of the robot's model has its handler here.
consteval std::size_t task_of(std::string_view name) { return rt::task_index(balbot::description, name); }
constexpr std::size_t pwm_task = task_of("TIM1"), left_hall_task = task_of("TIM2"), right_hall_task = task_of("TIM4"),
                      echo_task = task_of("TIM5"), imu_task = task_of("EXTI8"), spi_sent_task = task_of("DMA2_Stream3"),
                      spi_received_task = task_of("DMA2_Stream2"), adc_task = task_of("DMA2_Stream4"),
                      gains_task = task_of("IPCC_RX1");

void report_last_fault() {
  const auto fault = chip::take_last_fault();
  if (!fault) return;
  duet::TextBuffer<160> line;
  line.append("balbot: the last run ended in fault: exception ").append(fault->exception);
  line.append(" pc ").append_hex(fault->pc).append(" lr ").append_hex(fault->lr);
  line.append(" cfsr ").append_hex(fault->cfsr).append(" hfsr ").append_hex(fault->hfsr);
  if (fault->stack_overflow != 0) line.append(" (stack overflow)");
  line.append(" faults ").append(fault->count).append('\n');
  cortex_m::console_write(line.view());
}

[[noreturn]] void fail(std::string_view problem) {
  chip::enter_safe_state();
  cortex_m::console_write("balbot: ");
  cortex_m::console_write(problem);
  cortex_m::console_write("\n");
  cortex_m::halt(1);
}

// SPI5's own interrupt ends a transfer that an overrun stopped short (spi.hpp): at the priority of the model's
// receive task, whose transfer it is. After ExecutivePort::configure, which sets the priority grouping.
void enable_spi_error_interrupt() {
  const rt::Task& receive = model.tasks[spi_received_task];
  cortex_m::set_interrupt_priority(
      chip::interrupt::spi5,
      cortex_m::grouped_priority(receive.priority.group, receive.priority.sub, model.sub_priority_bits));
  cortex_m::enable_interrupt(chip::interrupt::spi5);
}

// The interrupt task `task` runs if its handler's peripheral says the event was the model's.
void run_if(bool event, std::size_t task) {
  if (event) executive.on_interrupt_task(task);
}

}  // namespace
}  // namespace balbot::board

namespace balbot::firmware {

std::uint32_t executive_cycles() { return board::port.cycles(); }
void record_section(duet::rt::Ceiling ceiling, std::uint32_t cycles) {
  board::executive.record_section(ceiling, cycles);
}

}  // namespace balbot::firmware

DUET_STM32MP15_EXECUTIVE_HANDLERS(balbot::board::executive)

using balbot::board::run_if;

extern "C" void TIM1_CC_IRQHandler() { run_if(balbot::board::on_pwm_period(), balbot::board::pwm_task); }
extern "C" void TIM2_IRQHandler() { run_if(balbot::board::on_left_hall(), balbot::board::left_hall_task); }
extern "C" void TIM4_IRQHandler() { run_if(balbot::board::on_right_hall(), balbot::board::right_hall_task); }
extern "C" void TIM5_IRQHandler() { run_if(balbot::board::on_echo_edge(), balbot::board::echo_task); }
extern "C" void EXTI8_IRQHandler() { run_if(balbot::board::on_imu_data_ready(), balbot::board::imu_task); }
extern "C" void DMA2_Stream3_IRQHandler() { run_if(balbot::board::on_spi_transmitted(), balbot::board::spi_sent_task); }
extern "C" void DMA2_Stream2_IRQHandler() {
  run_if(balbot::board::on_spi_received(), balbot::board::spi_received_task);
}
extern "C" void SPI5_IRQHandler() { balbot::board::on_spi_error(); }
extern "C" void DMA2_Stream4_IRQHandler() { run_if(balbot::board::on_adc_samples(), balbot::board::adc_task); }
static_assert(duet::stm32mp15::application_message_interrupt == duet::stm32mp15::spare_interrupts[2],
              "the model's IPCC_RX1 task runs on the spare line whose handler is Software2");
extern "C" void Software2_IRQHandler() { run_if(true, balbot::board::gains_task); }

int main() {
  using namespace balbot::board;
  cortex_m::console_write("balbot: starting on the STM32MP15's Cortex-M4\n");
  report_last_fault();
  if (!start_peripherals()) fail("a peripheral refused its set-up");
  prepare_linux_channels();
  if (!chip::ExecutivePort::configure(model)) fail("the model does not fit the board");
  enable_spi_error_interrupt();
  if (executive.initialize() != rt::TaskTableError::none) fail("the model's task table is wrong");
  cortex_m::enable_interrupts();
  executive.run();  // until Linux stops the core: the model has no final tick here
  executive.terminate();
  chip::enter_safe_state();
  return 0;
}
