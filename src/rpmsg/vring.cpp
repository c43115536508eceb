#include "duet/rpmsg/vring.hpp"

#include <atomic>

#include "little_endian.hpp"

namespace duet::rpmsg {
namespace {

// Shared memory: read and write each field with one access the compiler may neither merge nor cache.
std::uint16_t read16(const volatile std::uint16_t* field) { return *field; }

}  // namespace

DeviceVring::DeviceVring(void* memory, VringLayout layout)
    : base_(reinterpret_cast<std::uintptr_t>(memory)), layout_(layout) {
  // A ring that was in use before (the firmware restarted) goes on from where the device left it, which had handed
  // back everything it took; a new one (zeroed by remoteproc) starts at 0.
  used_ = read16(used_u16(1));
  last_avail_ = used_;
}

volatile std::uint16_t* DeviceVring::avail_u16(std::size_t index) const {
  return reinterpret_cast<volatile std::uint16_t*>(base_ + layout_.avail_offset() + 2U * index);
}
volatile std::uint16_t* DeviceVring::used_u16(std::size_t index) const {
  return reinterpret_cast<volatile std::uint16_t*>(base_ + layout_.used_offset() + 2U * index);
}

std::uint16_t DeviceVring::offered() const { return static_cast<std::uint16_t>(read16(avail_u16(1)) - last_avail_); }

std::optional<DeviceVring::Buffer> DeviceVring::take() {
  if (offered() == 0) return std::nullopt;
  std::atomic_thread_fence(std::memory_order_acquire);  // the ring entry and the descriptor after the index
  const std::uint16_t slot = static_cast<std::uint16_t>(last_avail_ & (layout_.num - 1U));
  const std::uint16_t head = read16(avail_u16(2U + slot));
  ++last_avail_;
  if (head >= layout_.num) return Buffer{head, 0, 0};  // a driver's mistake: hand it back empty
  const auto* descriptor = reinterpret_cast<const volatile std::uint8_t*>(base_ + 16U * head);
  const std::uint64_t address =
      little_endian::get32(descriptor) | static_cast<std::uint64_t>(little_endian::get32(descriptor + 4)) << 32U;
  const std::uint32_t length = little_endian::get32(descriptor + 8);
  const std::uint16_t flags = little_endian::get16(descriptor + 12);
  if ((flags & descriptor_next) != 0) return Buffer{head, 0, 0};
  return Buffer{head, address, length};
}

void DeviceVring::give_back(std::uint16_t head, std::uint32_t written) {
  const std::uint16_t slot = static_cast<std::uint16_t>(used_ & (layout_.num - 1U));
  auto* entry = reinterpret_cast<volatile std::uint8_t*>(base_ + layout_.used_offset() + 4U + 8U * slot);
  little_endian::put32(entry, head);
  little_endian::put32(entry + 4, written);
  std::atomic_thread_fence(std::memory_order_release);  // the entry before the index that publishes it
  ++used_;
  *used_u16(1) = used_;
}

bool DeviceVring::driver_wants_interrupt() const {
  std::atomic_thread_fence(std::memory_order_seq_cst);  // our used.idx is visible before we read the driver's flags
  return (read16(avail_u16(0)) & avail_no_interrupt) == 0;
}

}  // namespace duet::rpmsg
