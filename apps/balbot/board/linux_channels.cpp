// XCP and the application channel on the STM32MP15: the two rpmsg-tty channels of the link to Linux
// (/dev/ttyRPMSG0 and 1, which duet-bridge opens), carrying the protocols of firmware/robot_channels.cpp. The link's
// interrupt, IPCC_RX1 at the lowest priority, moves the bytes both ways; tasks queue and pend it.

#include "linux_channels.hpp"

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/cycle_counter.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/cortex_m/microsecond_clock.hpp"
#include "duet/hardware/hardware.hpp"
#include "duet/rpmsg/byte_channel.hpp"
#include "duet/stm32mp15/board.hpp"
#include "duet/stm32mp15/fault.hpp"
#include "duet/stm32mp15/linux_link.hpp"
#include "duet/stm32mp15/rcc.hpp"
#include "duet/stm32mp15/resource_table.hpp"
#include "robot_channels.hpp"

namespace balbot::board {
namespace {

namespace chip = duet::stm32mp15;
namespace cortex_m = duet::cortex_m;

constexpr unsigned lowest_priority = cortex_m::priority_levels - 1U;

duet::rpmsg::ByteChannel xcp_channel{firmware::xcp_transport()};
duet::rpmsg::ByteChannel application_channel{firmware::application_endpoint()};

// Linux's addresses are the M4's: MCU SRAM is at 0x10000000 for both cores.
std::uint8_t* linux_memory(std::uint64_t address) {
  return reinterpret_cast<std::uint8_t*>(static_cast<std::uintptr_t>(address));
}

chip::LinuxLink link{
    {&chip::resource_table, chip::Ipcc{}, linux_memory, &xcp_channel, &application_channel, chip::enter_safe_state}};

cortex_m::MicrosecondClock<chip::core_clock_hz> clock;

}  // namespace

void prepare_linux_channels() {
  chip::Rcc{}.enable(chip::clock::ipcc);
  cortex_m::set_interrupt_priority(chip::interrupt::ipcc_rx1, lowest_priority);
  cortex_m::enable_interrupt(chip::interrupt::ipcc_rx1);
}

bool poll_linux() {
  if (link.started()) return true;
  if (!link.try_start()) {
    static bool said = false;  // it is polled between every two ticks
    if (link.problem() == chip::LinkProblem::bad_vring && !said) {
      said = true;
      cortex_m::console_write("linux link: the resource table's vrings are not usable; waiting for Linux\n");
    }
    return false;
  }
  cortex_m::set_interrupt_pending(chip::interrupt::ipcc_rx1);  // serve() announces the channels there, not here
  cortex_m::console_write("linux link: up, XCP on ttyRPMSG0, application channel on ttyRPMSG1\n");
  return true;
}

}  // namespace balbot::board

namespace balbot::firmware {

void kick_xcp() { duet::cortex_m::set_interrupt_pending(duet::stm32mp15::interrupt::ipcc_rx1); }
void kick_application() { duet::cortex_m::set_interrupt_pending(duet::stm32mp15::interrupt::ipcc_rx1); }
std::uint32_t microseconds() { return board::clock.elapsed(duet::cortex_m::cycle_counter::now); }
void pend_gains_task() { duet::cortex_m::set_interrupt_pending(duet::hardware::interrupt_number("IPCC_RX1")); }

}  // namespace balbot::firmware

extern "C" void IPCC_RX1_IRQHandler() {
  balbot::board::link.serve();
  balbot::firmware::tell_the_model_of_new_gains();
}
