#include "duet/stm32mp15/linux_link.hpp"

#include <atomic>
#include <bit>

namespace duet::stm32mp15 {
namespace {

const LinuxLinkConfiguration* doorbells = nullptr;  // the link's, for Device's notify, which has no context

// A ring as Linux described it: where it put it, and a size and alignment our vring code can take.
bool usable(const volatile VringResource& ring) {
  const std::uint32_t entries = ring.entries;
  return ring.device_address != address_any && entries != 0 && entries <= 0x8000 && std::has_single_bit(entries) &&
         std::has_single_bit(static_cast<std::uint32_t>(ring.align));
}

}  // namespace

LinuxLink::LinuxLink(const LinuxLinkConfiguration& configuration)
    : configuration_(configuration), device_(device_configuration()) {
  doorbells = &configuration_;
}

rpmsg::DeviceConfiguration LinuxLink::device_configuration() {
  return {&transmit_, &receive_, configuration_.memory_at, ring, endpoints_};
}

void LinuxLink::ring(unsigned vring) {
  // A doorbell still ringing from last time covers this one: Linux takes every used buffer when it answers.
  (void)doorbells->ipcc.ring(doorbells->table->vrings[vring].notify_id);
}

bool LinuxLink::try_start() {
  if (started_) return true;
  volatile ResourceTable& table = *configuration_.table;
  const bool driver_ok = (table.vdev.status & virtio_status_driver_ok) != 0;
  if (detached_) {
    if (driver_ok) return false;  // still the session Linux left: wait for its reset of the device
    detached_ = false;
  }
  if (!driver_ok) return false;
  if (!usable(table.vrings[0]) || !usable(table.vrings[1])) {
    problem_ = LinkProblem::bad_vring;
    return false;
  }
  const auto layout = [](const volatile VringResource& ring) {
    return rpmsg::VringLayout{static_cast<std::uint16_t>(ring.entries), ring.align};
  };
  transmit_ = rpmsg::DeviceVring{configuration_.memory_at(table.vrings[0].device_address), layout(table.vrings[0])};
  receive_ = rpmsg::DeviceVring{configuration_.memory_at(table.vrings[1].device_address), layout(table.vrings[1])};
  // A new session (the first, or after Linux detached): announced again, and Linux's endpoints learnt again.
  endpoints_[0] = configuration_.xcp->endpoint("rpmsg-tty", xcp_address);
  endpoints_[1] = configuration_.application->endpoint("rpmsg-tty", application_address);
  device_ = rpmsg::Device{device_configuration()};
  // The IPCC is reset at the first session only: after a detach, what Linux rang while the link was down (masked by
  // serve()) is kept, so that the doorbells of the new session, a shutdown request among them, are served once
  // unmasked below.
  if (detaches_ == 0) configuration_.ipcc.start();
  problem_ = LinkProblem::none;
  std::atomic_signal_fence(std::memory_order_release);  // the rings are set up before serve() may use them
  started_ = true;
  // After started_: a doorbell that serve() masks from here on is served when it interrupts again. serve() may mask
  // a channel between this read and write of C2MR; the write unmasks it again, and its doorbell interrupts again.
  configuration_.ipcc.unmask_receive(link_channels);
  return true;
}

void LinuxLink::serve() {
  const Ipcc& ipcc = configuration_.ipcc;
  // Each doorbell taken is masked until it is served (as ST's HAL does). While the link is down after a detach,
  // Linux's first doorbell of its next session may come before try_start() has taken the new rings: unmasked, its
  // flag would hold IPCC_RX1 pending for ever and starve the background loop that runs try_start().
  ipcc.mask_receive(ipcc.pending());
  if (!started_) return;  // try_start() unmasks them for the next session
  // Every doorbell of the link, those masked while it was down included.
  const std::uint32_t rung = ipcc.rung() & link_channels;
  if ((rung & 1U << ipcc_channel::detach) != 0) {
    // Linux lets the M4 run on without it (remoteproc's detach) and tears its RPMsg devices down: the rings are no
    // longer ours to use. The next session starts once Linux has reset the device and set DRIVER_OK again; the
    // doorbells stay masked until then.
    started_ = false;
    detached_ = true;
    ++detaches_;
    ipcc.acknowledge(ipcc_channel::detach);
    return;
  }
  // Acknowledged before the rings are read, so that a message Linux adds meanwhile rings again.
  for (const unsigned channel : {ipcc_channel::vring0, ipcc_channel::vring1}) {
    if ((rung & 1U << channel) != 0) ipcc.acknowledge(channel);
  }
  (void)device_.announce();  // what it has not announced yet, if Linux has buffers for it; nothing once done
  device_.receive();
  configuration_.xcp->pump(device_, endpoints_[0]);
  configuration_.application->pump(device_, endpoints_[1]);
  if ((rung & 1U << ipcc_channel::shutdown) != 0) {
    ++shutdown_requests_;
    configuration_.on_shutdown();
    ipcc.acknowledge(ipcc_channel::shutdown);  // Linux waits up to 500 ms for this, then resets the core
  }
  ipcc.unmask_receive(rung);  // served: a doorbell rung again since its acknowledgement interrupts at once
}

}  // namespace duet::stm32mp15
