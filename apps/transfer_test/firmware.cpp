// The thesis' XCP transfer test on the emulated Cortex-M4: the model transfer_test.yaml as duet gen generated it
// (generated/), stepped every 1 ms by the executive on the board's timer, with its XCP slave on UART0 (the channel
// duet-bridge relays, as /dev/ttyRPMSG0 on the board). The master is the PC's: `transfer_test --connect` through the
// bridge downloads the table, starts DAQ and the play-out, and checks what comes back (main.cpp, run_on_qemu.sh).
//
// The console (UART3, as in the robot's firmware) gets every second of model time what the executive is doing, in
// the key=value lines `duet pil` reads:
//
//   duet-status time_s=1.000 ticks=1000 busy_ppm=1234 overruns=0
//   duet-task index=0 name=rate_1 activations=1000 overruns=0 min_cycles=... mean_cycles=... max_cycles=...
//   duet-channels xcp_received=... xcp_sent=...
//
// It runs until QEMU is stopped.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/cortex_m/masked_copy.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/cmsdk_uart.hpp"
#include "duet/mps2_an386/executive_port.hpp"
#include "duet/mps2_an386/executive_report.hpp"
#include "duet/mps2_an386/uart_line.hpp"
#include "duet/rt/executive.hpp"
#include "duet/xcp/slave.hpp"
#include "duet/xcp/stream_transport.hpp"
#include "transfer_test.hpp"
#include "transfer_test_xcp.hpp"

namespace {

namespace board = duet::mps2_an386;
namespace cortex_m = duet::cortex_m;
namespace rt = duet::rt;
namespace xcp = duet::xcp;

constexpr unsigned console_uart = 3;

// XCP: the model's slave as its generated code sizes it (one DAQ list, a queue for the whole play-out).
transfer_test::xcp::Slave slave{{.timestamp = board::ExecutivePort::executive_microseconds,  // the A2L's unit
                                 .write_atomically = cortex_m::copy_with_interrupts_masked}};
std::array<std::uint8_t, xcp::ethernet_framing.frame_size(transfer_test::xcp::max_cto)> xcp_decoder_buffer{};
std::array<std::uint8_t, transfer_test::xcp::max_dto> xcp_packet_buffer{};
xcp::StreamTransport xcp_transport{
    slave.protocol(), slave.queue(), xcp::ethernet_framing, xcp_decoder_buffer, transfer_test::xcp::max_cto,
    xcp_packet_buffer};
board::UartLine<xcp::StreamTransport> xcp_line{board::CmsdkUart{board::uart0_base}, board::uart0_receive_interrupt,
                                               board::uart0_transmit_interrupt};

// The board's executive port, plus DAQ after every task and the console's report between ticks. Idles by spinning,
// as the board's port does: under -icount a WFI would merge timer interrupts.
class TransferTestPort : public board::ExecutivePort {
 public:
  void task_finished(std::size_t task) {
    slave.protocol().on_event(static_cast<std::uint16_t>(task));
    if (slave.queue().free_bytes() != slave.queue().capacity()) xcp_line.kick();
  }
  void idle();
};

constexpr std::size_t task_capacity = std::size(transfer_test::tasks);
const rt::ModelDescription& model = transfer_test::description;
TransferTestPort port;
rt::Executive<TransferTestPort, task_capacity> executive{model, port};

// The console's lines, every second of model time.
class StatusReport {
 public:
  void between_ticks() {
    if (executive.ticks() < next_report_) return;
    next_report_ += ticks_per_report;
    report();
  }

 private:
  static constexpr std::uint64_t ticks_per_report = 1'000'000'000U / transfer_test::description.base_period_ns;

  void report() {
    board::write_executive_report(executive, model);
    line_.clear();
    line_.append("duet-channels xcp_received=").append(xcp_line.bytes_received());
    line_.append(" xcp_sent=").append(xcp_line.bytes_sent());
    emit();
  }

  void emit() {
    line_.append('\n');
    cortex_m::console_write(line_.view());
  }

  duet::TextBuffer<200> line_;
  std::uint64_t next_report_ = ticks_per_report;
};
StatusReport report;

void TransferTestPort::idle() { report.between_ticks(); }

}  // namespace

DUET_MPS2_AN386_EXECUTIVE_HANDLERS(executive)
extern "C" void UART0_RX_IRQHandler() { xcp_line.serve(xcp_transport); }
extern "C" void UART0_TX_IRQHandler() { xcp_line.serve(xcp_transport); }

int main() {
  board::select_console(console_uart);
  board::initialize();
  xcp_line.start();
  cortex_m::console_write("transfer test: XCP on UART0, the 1 ms step on timer0\n");
  if (!board::run_model(executive, model)) {
    cortex_m::console_write("error: the model does not fit the board\n");
    return 2;
  }
  return 0;
}
