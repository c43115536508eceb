// XCP on UART0 and the application channel on UART1: the two RPMsg ttys of the board, which QEMU's first two -serial
// options stand in for (the bridge opens them as it opens /dev/ttyRPMSG0 and 1). Each UART's receive and transmit
// interrupts, at the lowest priority, move its bytes both ways for the protocols of firmware/robot_channels.cpp.

#include "balbot.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/cmsdk_uart.hpp"
#include "duet/mps2_an386/executive_port.hpp"
#include "duet/mps2_an386/uart_line.hpp"
#include "robot_channels.hpp"
#include "robot_firmware.hpp"

namespace balbot::pil {
namespace {

namespace board = duet::mps2_an386;

board::UartLine<duet::xcp::StreamTransport> xcp_line{board::CmsdkUart{board::uart0_base},
                                                     board::uart0_receive_interrupt, board::uart0_transmit_interrupt};
board::UartLine<duet::app_channel::Endpoint> application_line{
    board::CmsdkUart{board::uart1_base}, board::uart1_receive_interrupt, board::uart1_transmit_interrupt};

}  // namespace

void start_host_channels() {
  xcp_line.start();
  // The executive's account each second is some 460 bytes, the telemetry some 25 every 10 ms: 64 bytes a tick
  // spread the account over 8 ticks (sent at once it cost its tick 1 to 1.5 ms of wall time). XCP is not limited:
  // DAQ of 16 signals alone sends 73 bytes a tick.
  application_line.limit_per_tick(64);
  application_line.start();
}

void host_channels_new_tick() { application_line.new_tick(); }

HostChannelCounters host_channel_counters() {
  return {xcp_line.bytes_received(), xcp_line.bytes_sent(), application_line.bytes_received(),
          application_line.bytes_sent(), firmware::channel_losses()};
}

}  // namespace balbot::pil

namespace balbot::firmware {

void kick_xcp() { pil::xcp_line.kick(); }
void kick_application() { pil::application_line.kick(); }
std::uint32_t microseconds() { return duet::mps2_an386::ExecutivePort::executive_microseconds(); }
void pend_gains_task() { duet::cortex_m::set_interrupt_pending(duet::hardware::interrupt_number("IPCC_RX1")); }

}  // namespace balbot::firmware

extern "C" void UART0_RX_IRQHandler() { balbot::pil::xcp_line.serve(balbot::firmware::xcp_transport()); }
extern "C" void UART0_TX_IRQHandler() { balbot::pil::xcp_line.serve(balbot::firmware::xcp_transport()); }
extern "C" void UART1_RX_IRQHandler() {
  balbot::pil::application_line.serve(balbot::firmware::application_endpoint());
  balbot::firmware::tell_the_model_of_new_gains();
}
extern "C" void UART1_TX_IRQHandler() { balbot::pil::application_line.serve(balbot::firmware::application_endpoint()); }
