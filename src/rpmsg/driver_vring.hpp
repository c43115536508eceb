#pragma once
// For tests: the driver's side of a vring, as Linux's virtio_ring keeps it: it owns the descriptors, offers buffers
// in the avail ring and collects them from the used ring. Addresses are offsets into the test's shared memory.

#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "duet/rpmsg/vring.hpp"

namespace duet::rpmsg::testing {

class DriverVring {
 public:
  DriverVring(std::uint8_t* memory, VringLayout layout) : base_(memory), layout_(layout) {
    std::memset(memory, 0, layout.size());
    for (std::uint16_t index = 0; index < layout.num; ++index) free_.push_back(index);
  }

  // Offers a buffer of `length` bytes at `address`; false when every descriptor is out (the device keeps them).
  bool offer(std::uint64_t address, std::uint32_t length, std::uint16_t flags = 0) {
    if (free_.empty()) return false;
    const std::uint16_t head = free_.back();
    free_.pop_back();
    std::uint8_t* descriptor = base_ + 16U * head;
    std::memcpy(descriptor, &address, 8);
    std::memcpy(descriptor + 8, &length, 4);
    std::memcpy(descriptor + 12, &flags, 2);
    const std::uint16_t slot = static_cast<std::uint16_t>(avail_idx_ & (layout_.num - 1U));
    std::memcpy(base_ + layout_.avail_offset() + 4U + 2U * slot, &head, 2);
    ++avail_idx_;
    std::memcpy(base_ + layout_.avail_offset() + 2U, &avail_idx_, 2);
    addresses_.resize(layout_.num);
    addresses_[head] = address;
    return true;
  }

  struct Used {
    std::uint64_t address;
    std::uint32_t length;
  };
  // The next buffer the device handed back.
  std::optional<Used> collect() {
    std::uint16_t used_idx = 0;
    std::memcpy(&used_idx, base_ + layout_.used_offset() + 2U, 2);
    if (used_idx == last_used_) return std::nullopt;
    const std::uint16_t slot = static_cast<std::uint16_t>(last_used_ & (layout_.num - 1U));
    std::uint32_t id = 0;
    std::uint32_t length = 0;
    std::memcpy(&id, base_ + layout_.used_offset() + 4U + 8U * slot, 4);
    std::memcpy(&length, base_ + layout_.used_offset() + 8U + 8U * slot, 4);
    ++last_used_;
    const auto head = static_cast<std::uint16_t>(id);
    free_.push_back(head);
    return Used{addresses_.at(head), length};
  }

  void set_no_interrupt(bool quiet) {
    const std::uint16_t flags = quiet ? avail_no_interrupt : 0;
    std::memcpy(base_ + layout_.avail_offset(), &flags, 2);
  }
  // Starts the indices at `start`, as a ring that has run for a while (to cross the 16-bit wrap quickly).
  void start_indices_at(std::uint16_t start) {
    avail_idx_ = start;
    last_used_ = start;
    std::memcpy(base_ + layout_.avail_offset() + 2U, &start, 2);
    std::memcpy(base_ + layout_.used_offset() + 2U, &start, 2);
  }

 private:
  std::uint8_t* base_;
  VringLayout layout_;
  std::vector<std::uint16_t> free_;
  std::vector<std::uint64_t> addresses_;
  std::uint16_t avail_idx_ = 0;
  std::uint16_t last_used_ = 0;
};

}  // namespace duet::rpmsg::testing
