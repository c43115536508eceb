// The M4's link to Linux on the PC: a resource table as remoteproc fills it, a Linux side in shared memory that
// behaves as rpmsg_virtio does, and the IPCC as a fake register file. The link waits for DRIVER_OK, announces XCP
// then the application channel as rpmsg-tty, carries bytes both ways, answers Linux's shutdown request after
// the outputs are safe, and survives a detach, however early Linux rings for its next session.
#include "duet/stm32mp15/linux_link.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "duet/xcp/framing.hpp"
#include "duet/xcp/stream_transport.hpp"
#include "linux_side.hpp"
#include "recording_protocol.hpp"

namespace duet::stm32mp15 {
namespace {

using rpmsg::testing::buffer_at;
using rpmsg::testing::LinuxSide;
using rpmsg::testing::RecordingProtocol;
using rpmsg::testing::vring1_at;

int safe_states = 0;
void enter_safe_state() { ++safe_states; }

class LinuxLinkTest : public ::testing::Test {
 protected:
  LinuxLinkTest() {
    table.vdev.status = 0;
    table.vrings[0] = {address_any, 16, 16, 0, 0};
    table.vrings[1] = {address_any, 16, 16, 1, 0};
    safe_states = 0;
  }

  // What remoteproc and rpmsg_virtio do before the M4 can talk: the rings placed, the driver ready.
  void linux_is_ready() {
    table.vrings[0].device_address = 0;  // offsets into the shared memory; 0 is where LinuxSide put vring0
    table.vrings[1].device_address = static_cast<std::uint32_t>(vring1_at);
    table.vdev.status = 0x07;  // ACKNOWLEDGE | DRIVER | DRIVER_OK
  }
  // Linux rings `channel` for the M4.
  void ring(unsigned channel) { ipcc_register(Ipcc::c1toc2sr) |= 1U << channel; }
  std::uint32_t& ipcc_register(std::uint32_t offset) { return ipcc_registers[offset / 4]; }
  // IPCC_RX1 as the NVIC sees it: the receive interrupt on, a doorbell rung and not masked.
  bool receive_interrupt_raised() {
    return (ipcc_register(Ipcc::c2cr) & Ipcc::receive_interrupt) != 0 &&
           (ipcc_register(Ipcc::c1toc2sr) & ~ipcc_register(Ipcc::c2mr) & Ipcc::all_channels) != 0;
  }
  // A session up, then Linux detaches (remoteproc's detach) and the link acknowledges.
  void attach_then_detach() {
    linux_is_ready();
    ASSERT_TRUE(link.try_start());
    link.serve();
    linux_side.receive();
    ipcc_register(Ipcc::c1toc2sr) = 1U << ipcc_channel::detach;
    link.serve();
    ASSERT_FALSE(link.started());
    ipcc_register(Ipcc::c1toc2sr) = 0;  // what the acknowledgement does on the chip
    table.vdev.status = 0;              // Linux resets the device before attaching again
    ASSERT_FALSE(link.try_start());
  }

  LinuxSide linux_side;
  ResourceTable table{};
  std::array<std::uint32_t, 8> ipcc_registers{};
  RecordingProtocol xcp, application;
  rpmsg::ByteChannel xcp_channel{xcp}, application_channel{application};
  // The fake table is not where LinuxSide's memory is: vring addresses are offsets into it, as buffer addresses are.
  LinuxLink link{{&table, Ipcc{reinterpret_cast<std::uintptr_t>(ipcc_registers.data())},
                  [](std::uint64_t address) { return buffer_at(address); }, &xcp_channel, &application_channel,
                  enter_safe_state}};
};

TEST_F(LinuxLinkTest, WaitsForLinuxsDriverWithoutTouchingTheIpcc) {
  ipcc_registers.fill(0xAAAA'AAAA);
  for (int poll = 0; poll < 3; ++poll) EXPECT_FALSE(link.try_start());
  EXPECT_FALSE(link.started());
  EXPECT_EQ(link.problem(), LinkProblem::waiting_for_linux);
  EXPECT_EQ(ipcc_register(Ipcc::c2cr), 0xAAAA'AAAAU);
  link.serve();  // an early doorbell interrupt does nothing
  EXPECT_TRUE(linux_side.receive().empty());
}

TEST_F(LinuxLinkTest, RefusesRingsLinuxDidNotPlace) {
  table.vdev.status = 0x07;
  EXPECT_FALSE(link.try_start());
  EXPECT_EQ(link.problem(), LinkProblem::bad_vring);
  linux_is_ready();
  table.vrings[1].entries = 12;  // not a power of two
  EXPECT_FALSE(link.try_start());
  table.vrings[1].entries = 16;
  EXPECT_TRUE(link.try_start());
  EXPECT_TRUE(linux_side.receive().empty());  // nothing announced until the doorbell's interrupt serves
  EXPECT_EQ(link.problem(), LinkProblem::none);
}

TEST_F(LinuxLinkTest, AnnouncesXcpThenTheApplicationChannel) {
  linux_is_ready();
  ASSERT_TRUE(link.try_start());
  link.serve();  // the doorbell's interrupt, which the board pends once the link is up
  EXPECT_EQ(ipcc_register(Ipcc::c2cr), Ipcc::receive_interrupt);
  EXPECT_EQ(ipcc_register(Ipcc::c2mr), 0x3F'0030U);  // channels 0-3 unmasked for receiving, every transmit masked
  const auto announcements = linux_side.receive();
  ASSERT_EQ(announcements.size(), 2U);
  for (std::size_t channel = 0; channel < 2; ++channel) {
    EXPECT_EQ(announcements[channel].destination, rpmsg::name_service_address);
    EXPECT_EQ(announcements[channel].source, rpmsg::first_local_address + channel);
    EXPECT_EQ(std::string(reinterpret_cast<const char*>(announcements[channel].payload.data())), "rpmsg-tty");
  }
  EXPECT_EQ(ipcc_register(Ipcc::c2scr), 1U << 16);  // vring0's doorbell rung for Linux
}

TEST_F(LinuxLinkTest, CarriesBytesBothWaysOnEachChannel) {
  linux_is_ready();
  ASSERT_TRUE(link.try_start());
  link.serve();  // the doorbell's interrupt, which the board pends once the link is up
  linux_side.receive();
  ASSERT_TRUE(linux_side.send(0x500, LinuxLink::xcp_address, {0xFF, 0x00}));    // CONNECT
  ASSERT_TRUE(linux_side.send(0x501, LinuxLink::application_address, {0x81}));  // describe
  ring(ipcc_channel::vring1);
  link.serve();
  EXPECT_EQ(xcp.received, (std::vector<std::uint8_t>{0xFF, 0x00}));
  EXPECT_EQ(application.received, (std::vector<std::uint8_t>{0x81}));
  EXPECT_EQ(ipcc_register(Ipcc::c2scr), 1U << (16 + ipcc_channel::vring1));  // Linux told its buffers are back

  xcp.queued = {0xFF, 0x10};
  application.queued = {0x01, 0x02, 0x03};
  link.serve();
  const auto messages = linux_side.receive();
  ASSERT_EQ(messages.size(), 2U);
  EXPECT_EQ(messages[0].destination, 0x500U);
  EXPECT_EQ(messages[0].payload, (std::vector<std::uint8_t>{0xFF, 0x10}));
  EXPECT_EQ(messages[1].destination, 0x501U);
  EXPECT_EQ(messages[1].payload, (std::vector<std::uint8_t>{0x01, 0x02, 0x03}));
}

TEST_F(LinuxLinkTest, ShutdownMakesTheOutputsSafeThenAcknowledges) {
  linux_is_ready();
  ASSERT_TRUE(link.try_start());
  link.serve();  // the doorbell's interrupt, which the board pends once the link is up
  ring(ipcc_channel::shutdown);
  link.serve();
  EXPECT_EQ(safe_states, 1);
  EXPECT_EQ(link.shutdown_requests(), 1U);
  EXPECT_EQ(ipcc_register(Ipcc::c2scr), 1U << ipcc_channel::shutdown);
}

TEST_F(LinuxLinkTest, AfterADetachANewSessionStartsWhenLinuxAttachesAgain) {
  linux_is_ready();
  ASSERT_TRUE(link.try_start());
  link.serve();
  linux_side.receive();
  ASSERT_TRUE(linux_side.send(0x500, LinuxLink::xcp_address, {1}));
  ring(ipcc_channel::vring1);
  link.serve();
  ASSERT_EQ(xcp.received.size(), 1U);

  ipcc_register(Ipcc::c1toc2sr) = 1U << ipcc_channel::detach;
  link.serve();
  EXPECT_FALSE(link.started());
  EXPECT_EQ(link.detaches(), 1U);
  EXPECT_EQ(ipcc_register(Ipcc::c2scr), 1U << ipcc_channel::detach);  // acknowledged
  ipcc_register(Ipcc::c1toc2sr) = 0;
  xcp.queued = {0xAA};
  link.serve();  // the rings are no longer the link's: nothing is sent
  EXPECT_TRUE(linux_side.receive().empty());
  EXPECT_FALSE(link.try_start());  // DRIVER_OK still set: the session Linux left

  // Linux attaches again: it resets the device, sets up rings and buffers anew, and sets DRIVER_OK.
  table.vdev.status = 0;
  EXPECT_FALSE(link.try_start());
  LinuxSide attached_again;
  table.vdev.status = 0x07;
  ASSERT_TRUE(link.try_start());
  link.serve();
  EXPECT_EQ(attached_again.receive().size(), 2U);             // both channels announced again
  EXPECT_EQ(xcp_channel.bytes_dropped_without_reader(), 1U);  // queued for the old session: nobody to read it
  ASSERT_TRUE(attached_again.send(0x600, LinuxLink::xcp_address, {2}));  // Linux's new endpoint
  ring(ipcc_channel::vring1);
  link.serve();
  xcp.queued = {0xBB};
  link.serve();
  const auto answers = attached_again.receive();
  ASSERT_EQ(answers.size(), 1U);
  EXPECT_EQ(answers[0].destination, 0x600U);  // learnt anew, not the old session's 0x500
}

TEST_F(LinuxLinkTest, LinuxsFirstDoorbellAfterADetachNeitherHoldsTheInterruptNorIsLost) {
  attach_then_detach();
  // Linux attaches again and rings at once: rpmsg_virtio offers its receive buffers (vring0) as soon as DRIVER_OK is
  // set, and IPCC_RX1 runs before the background loop gets to try_start().
  LinuxSide attached_again;
  table.vdev.status = 0x07;
  ring(ipcc_channel::vring0);
  ASSERT_TRUE(receive_interrupt_raised());
  ipcc_register(Ipcc::c2scr) = 0;
  link.serve();
  EXPECT_FALSE(receive_interrupt_raised());   // masked: the interrupt ends, the background loop runs
  EXPECT_EQ(ipcc_register(Ipcc::c2scr), 0U);  // not acknowledged: kept for the session that serves it
  EXPECT_TRUE(attached_again.receive().empty());

  ASSERT_TRUE(link.try_start());
  EXPECT_TRUE(receive_interrupt_raised());  // unmasked for the new session: the kept doorbell interrupts again
  link.serve();
  EXPECT_EQ(attached_again.receive().size(), 2U);    // into the buffers it offered: both channels announced again
  EXPECT_EQ(ipcc_register(Ipcc::c2mr), 0x3F'0030U);  // served, so unmasked
  ipcc_register(Ipcc::c1toc2sr) = 0;                 // what the acknowledgement does on the chip

  ASSERT_TRUE(attached_again.send(0x600, LinuxLink::xcp_address, {0x42}));  // and the next doorbell interrupts
  ring(ipcc_channel::vring1);
  EXPECT_TRUE(receive_interrupt_raised());
  link.serve();
  EXPECT_EQ(xcp.received.back(), 0x42);
}

TEST_F(LinuxLinkTest, AShutdownRungWhileTheLinkIsDownIsServedByTheNextSession) {
  attach_then_detach();
  LinuxSide attached_again;
  table.vdev.status = 0x07;
  ring(ipcc_channel::shutdown);  // Linux attached and stops the core at once
  link.serve();
  EXPECT_FALSE(receive_interrupt_raised());
  EXPECT_EQ(safe_states, 0);  // the link is down: served once the session is up
  ASSERT_TRUE(link.try_start());
  EXPECT_TRUE(receive_interrupt_raised());
  link.serve();
  EXPECT_EQ(safe_states, 1);
  EXPECT_EQ(link.shutdown_requests(), 1U);
}

// The firmware's XCP slave behind the link, as the robot's firmware has it: a master's CONNECT and SHORT_UPLOAD go in
// as Linux's tty writes, the framed answers come back in Linux's receive buffers.
TEST_F(LinuxLinkTest, AnXcpMasterTalksToTheSlaveThroughTheRings) {
  using Bytes = std::vector<std::uint8_t>;
  std::array<std::uint8_t, 4> signals{0x11, 0x22, 0x33, 0x44};
  const std::array regions{xcp::MemoryRegion{.name = "signals", .address = 0x100, .size = 4, .memory = signals.data()}};
  std::array<std::uint8_t, 256> queue_storage{};
  xcp::TransmitQueue queue{queue_storage, {}};
  const xcp::SlaveConfiguration configuration{
      .memory = xcp::MemoryMap{regions}, .max_cto = 8, .max_dto = 8, .queue = &queue};
  xcp::Slave slave{configuration};
  std::array<std::uint8_t, 16> decoder_buffer{};
  std::array<std::uint8_t, 8> packet_buffer{};
  xcp::StreamTransport transport{slave, queue, xcp::ethernet_framing, decoder_buffer, 8, packet_buffer};
  rpmsg::ByteChannel slave_channel{transport};
  LinuxLink xcp_link{{&table, Ipcc{reinterpret_cast<std::uintptr_t>(ipcc_registers.data())},
                      [](std::uint64_t address) { return buffer_at(address); }, &slave_channel, &application_channel,
                      enter_safe_state}};
  const auto frame = [](std::uint16_t counter, const Bytes& packet) {
    Bytes bytes(xcp::ethernet_framing.frame_size(packet.size()));
    xcp::write_frame(xcp::ethernet_framing, bytes, counter, packet);
    return bytes;
  };
  linux_is_ready();
  ASSERT_TRUE(xcp_link.try_start());
  xcp_link.serve();
  linux_side.receive();  // the announcements

  Bytes commands = frame(0, {0xFF, 0x00});                                          // CONNECT
  const Bytes upload = frame(1, {0xF4, 0x04, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00});  // SHORT_UPLOAD 4 at 0x100
  commands.insert(commands.end(), upload.begin(), upload.end());
  ASSERT_TRUE(linux_side.send(0x500, LinuxLink::xcp_address, commands));
  ring(ipcc_channel::vring1);
  xcp_link.serve();

  Bytes answers;
  for (const auto& message : linux_side.receive()) {
    EXPECT_EQ(message.destination, 0x500U);
    answers.insert(answers.end(), message.payload.begin(), message.payload.end());
  }
  Bytes expected = frame(0, {0xFF, 0x01, 0x80, 0x08, 0x08, 0x00, 0x01, 0x01});  // CAL/PAG, no DAQ here
  const Bytes data = frame(1, {0xFF, 0x11, 0x22, 0x33, 0x44});
  expected.insert(expected.end(), data.begin(), data.end());
  EXPECT_EQ(answers, expected);
}

}  // namespace
}  // namespace duet::stm32mp15
