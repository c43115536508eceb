#pragma once
// The slave's outgoing packets: a bounded byte ring of [length u16][packet] records, filled by several producers that
// may preempt each other (tasks sampling DAQ at different interrupt priorities, the command handler) and emptied by
// one consumer (the transport). Producers write under a lock (masked interrupts on the Cortex-M4, a mutex on
// the PC) and never wait for the consumer: what does not fit is refused, whole, and the caller counts it. The
// consumer copies packets out without the lock.

#include <atomic>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

#include "duet/base/section_lock.hpp"
#include "duet/base/shared_order.hpp"

namespace duet::xcp {

// The lock around a producer's write: the interrupt mask on the Cortex-M4, the program's functions elsewhere.
using QueueLock = SectionLock;

// The little-endian fields and the record header, written through the derived appender's u8().
template <typename Appender>
class FieldAppender {
 public:
  Appender& u16(std::uint16_t value) {
    return self().u8(static_cast<std::uint8_t>(value)).u8(static_cast<std::uint8_t>(value >> 8U));
  }
  Appender& u32(std::uint32_t value) {
    return u16(static_cast<std::uint16_t>(value)).u16(static_cast<std::uint16_t>(value >> 16U));
  }
  // Starts the record of a packet of `size` bytes; the caller then writes exactly that many.
  Appender& packet(std::size_t size) { return self().u16(static_cast<std::uint16_t>(size)); }

 private:
  Appender& self() { return static_cast<Appender&>(*this); }
};

class TransmitQueue {
 public:
  static constexpr std::size_t record_header = 2;

  // Writes the bytes of the packets a producer adds, wrapping round the ring as needed.
  class Appender : public FieldAppender<Appender> {
   public:
    Appender(std::span<std::uint8_t> ring, std::size_t position) : ring_(ring), position_(position) {}
    Appender& u8(std::uint8_t value) {
      ring_[position_] = value;
      position_ = position_ + 1 == ring_.size() ? 0 : position_ + 1;
      return *this;
    }
    // Copies in at most two runs, before and after the ring's end.
    Appender& bytes(const std::uint8_t* values, std::size_t count) {
      const std::size_t to_end = ring_.size() - position_;
      const std::size_t first = count < to_end ? count : to_end;
      std::memcpy(ring_.data() + position_, values, first);
      std::memcpy(ring_.data(), values + first, count - first);
      position_ = count < to_end ? position_ + count : count - first;
      return *this;
    }

   private:
    std::span<std::uint8_t> ring_;
    std::size_t position_;
  };

  // The same for records that lie in one piece, the usual case: plain stores, no wrap checks.
  class LinearAppender : public FieldAppender<LinearAppender> {
   public:
    explicit LinearAppender(std::uint8_t* at) : at_(at) {}
    // Single stores where the compiler would otherwise store the bytes apart (the Cortex-M4 stores unaligned).
    LinearAppender& u16(std::uint16_t value) { return little_endian(value); }
    LinearAppender& u32(std::uint32_t value) { return little_endian(value); }
    LinearAppender& u8(std::uint8_t value) {
      *at_++ = value;
      return *this;
    }
    LinearAppender& bytes(const std::uint8_t* values, std::size_t count) {
      switch (count) {  // constant sizes become single loads and stores
        case 1: *at_ = *values; break;
        case 2: std::memcpy(at_, values, 2); break;
        case 4: std::memcpy(at_, values, 4); break;
        case 8: std::memcpy(at_, values, 8); break;
        default: std::memcpy(at_, values, count); break;
      }
      at_ += count;
      return *this;
    }

   private:
    template <typename Word>
    LinearAppender& little_endian(Word value) {
      if constexpr (std::endian::native == std::endian::little) {
        std::memcpy(at_, &value, sizeof value);
        at_ += sizeof value;
        return *this;
      } else {
        for (std::size_t byte = 0; byte < sizeof value; ++byte) u8(static_cast<std::uint8_t>(value >> (8U * byte)));
        return *this;
      }
    }

    std::uint8_t* at_;
  };

  TransmitQueue(std::span<std::uint8_t> storage, QueueLock lock) : ring_(storage), lock_(lock) {}

  // Adds packets whose records take `record_bytes` in all (each packet's size + record_header) if they fit with
  // `headroom` bytes to spare; `fill(out)` writes exactly those records through `out`, an Appender or, when the
  // records lie in one piece, a LinearAppender (so `fill` takes `auto&`). False, with nothing added, otherwise.
  // Interrupt-safe; never waits.
  template <typename Fill>
  bool push(std::size_t record_bytes, std::size_t headroom, Fill&& fill) {
    const std::uint32_t saved = lock_.lock();
    const std::size_t head = head_.load(std::memory_order_relaxed);
    const std::size_t used = head - load_acquire(tail_);
    const bool fits = record_bytes + headroom <= ring_.size() - used;
    if (fits) {
      const std::size_t position = head % ring_.size();
      if (position + record_bytes <= ring_.size()) {
        LinearAppender appender{ring_.data() + position};
        fill(appender);
      } else {
        Appender appender{ring_, position};
        fill(appender);
      }
      store_release(head_, head + record_bytes);
    }
    lock_.unlock(saved);
    return fits;
  }

  // Copies the oldest packet into `packet` and removes it; returns its size, 0 if the queue is empty. A packet larger
  // than `packet` is removed and reported as 0 bytes long (a programming error: size the buffer for MAX_DTO).
  std::size_t pop(std::span<std::uint8_t> packet);

  [[nodiscard]] bool empty() const { return load_acquire(head_) == tail_.load(std::memory_order_relaxed); }
  [[nodiscard]] std::size_t capacity() const { return ring_.size(); }
  // Bytes a producer could add now (a snapshot: the consumer may free more meanwhile).
  [[nodiscard]] std::size_t free_bytes() const {
    return ring_.size() - (head_.load(std::memory_order_relaxed) - load_acquire(tail_));
  }

 private:
  std::span<std::uint8_t> ring_;
  QueueLock lock_;
  // Positions grow without bound (modulo the ring's size when used); head_ moves under the lock, tail_ only by pop.
  std::atomic<std::size_t> head_{0};
  std::atomic<std::size_t> tail_{0};
};

}  // namespace duet::xcp
