#pragma once
// The Cortex-M4's link to Linux: RPMsg over the two vrings that Linux's remoteproc placed and described in the
// resource table, rung through the IPCC, carrying two rpmsg-tty channels: XCP (announced first, so Linux's
// /dev/ttyRPMSG0) and the application channel (/dev/ttyRPMSG1). The M4 starts before Linux's RPMsg driver is ready,
// so the link comes up later, from the background loop (try_start), while the executive already runs the model:
// control never waits for Linux. Then one interrupt, IPCC_RX1 at the lowest priority, does all the link's work
// (serve): messages in, queued bytes out, Linux's shutdown and detach requests. Tasks only queue and pend it.
// After a detach the link waits for Linux to attach again and starts a new session.

#include <cstdint>

#include "duet/rpmsg/byte_channel.hpp"
#include "duet/rpmsg/device.hpp"
#include "duet/rpmsg/vring.hpp"
#include "duet/stm32mp15/ipcc.hpp"
#include "duet/stm32mp15/resource_table.hpp"

namespace duet::stm32mp15 {

struct LinuxLinkConfiguration {
  volatile ResourceTable* table;
  Ipcc ipcc;
  // Linux's addresses (vrings, buffers) as the M4 sees them: the same on the chip; an offset in the PC's tests.
  std::uint8_t* (*memory_at)(std::uint64_t address);
  rpmsg::ByteChannel* xcp;
  rpmsg::ByteChannel* application;
  // Linux stops the M4 (echo stop > .../remoteproc0/state): the outputs to their safe state before we acknowledge,
  // after which Linux holds the core in reset.
  void (*on_shutdown)();
};

enum class LinkProblem : std::uint8_t { none, waiting_for_linux, bad_vring };

class LinuxLink {
 public:
  static constexpr std::uint32_t xcp_address = rpmsg::first_local_address;
  static constexpr std::uint32_t application_address = rpmsg::first_local_address + 1;
  // The IPCC channels the link listens to, a bit each.
  static constexpr std::uint32_t link_channels = 1U << ipcc_channel::vring0 | 1U << ipcc_channel::vring1 |
                                                 1U << ipcc_channel::shutdown | 1U << ipcc_channel::detach;

  // One link per image: the vrings' doorbell reaches it without a context.
  explicit LinuxLink(const LinuxLinkConfiguration& configuration);

  // From the background loop until it returns true: once Linux's driver has set DRIVER_OK, takes the vrings where
  // the table says and starts the IPCC. Never waits. Then serve() announces both channels: the caller pends its
  // interrupt, so that serve() never runs twice at once. After Linux detached, false again until it has reset the
  // device (DRIVER_OK cleared) and set it up anew.
  bool try_start();
  [[nodiscard]] bool started() const { return started_; }
  [[nodiscard]] LinkProblem problem() const { return problem_; }

  // IPCC_RX1's handler (and whoever pends it to send): doorbells taken, Linux's messages handed to the channels'
  // protocols, what they queued sent as far as Linux has buffers. A doorbell is masked while it waits to be served:
  // while the link is down, until try_start() starts the next session.
  void serve();

  [[nodiscard]] std::uint32_t shutdown_requests() const { return shutdown_requests_; }
  [[nodiscard]] std::uint32_t detaches() const { return detaches_; }

 private:
  static void ring(unsigned vring);
  [[nodiscard]] rpmsg::DeviceConfiguration device_configuration();

  LinuxLinkConfiguration configuration_;
  rpmsg::DeviceVring transmit_;
  rpmsg::DeviceVring receive_;
  rpmsg::Endpoint endpoints_[2]{};  // each session's, from try_start
  rpmsg::Device device_;
  volatile bool started_ = false;  // the background loop sets it, the doorbell's handler reads it
  bool detached_ = false;          // Linux detached: wait for its reset of the device before the next session
  LinkProblem problem_ = LinkProblem::waiting_for_linux;
  std::uint32_t shutdown_requests_ = 0;
  std::uint32_t detaches_ = 0;
};

}  // namespace duet::stm32mp15
