#pragma once
// A virtio split virtqueue (a "vring") seen from the device side, which the Cortex-M4 is for Linux's remoteproc:
// the driver (Linux) offers buffers in the avail ring, the device takes them, fills or reads them and hands them
// back in the used ring. Legacy layout, as remoteproc places it at the resource table's address: `num` descriptors
// {u64 address, u32 length, u16 flags, u16 next}, the avail ring {u16 flags, u16 idx, u16 ring[num], u16
// used_event}, then, aligned up to `align`, the used ring {u16 flags, u16 idx, {u32 id, u32 length}[num], u16
// avail_event}. All little-endian, as both the M4 and the A7 are. Freestanding; the rings are memory the other core
// writes too, so every shared field is read and written through volatile accesses, ordered by fences (DMB on the M4).

#include <cstddef>
#include <cstdint>
#include <optional>

namespace duet::rpmsg {

inline constexpr std::uint16_t descriptor_next = 1;
inline constexpr std::uint16_t descriptor_write = 2;
inline constexpr std::uint16_t avail_no_interrupt = 1;
inline constexpr std::uint16_t used_no_notify = 1;

struct VringLayout {
  std::uint16_t num;    // entries, a power of two
  std::uint32_t align;  // of the used ring

  [[nodiscard]] constexpr std::size_t descriptors_size() const { return 16U * num; }
  [[nodiscard]] constexpr std::size_t avail_offset() const { return descriptors_size(); }
  [[nodiscard]] constexpr std::size_t used_offset() const {
    const std::size_t avail_end = avail_offset() + 2U * (3U + num);
    return (avail_end + align - 1U) / align * align;
  }
  [[nodiscard]] constexpr std::size_t size() const { return used_offset() + 2U * 3U + 8U * num; }
};

static_assert(VringLayout{16, 16}.avail_offset() == 256 && VringLayout{16, 16}.used_offset() == 304,
              "the layout remoteproc gives a ring of 16 entries aligned to 16");

class DeviceVring {
 public:
  struct Buffer {
    std::uint16_t head;     // the descriptor's index, to hand back
    std::uint64_t address;  // the driver's address of the buffer
    std::uint32_t length;
  };

  DeviceVring() = default;
  // `memory`: where the ring lies, as the resource table says (remoteproc has set it to zero).
  DeviceVring(void* memory, VringLayout layout);

  // The next buffer the driver offered, if any. A chained descriptor is refused: RPMsg buffers are single.
  [[nodiscard]] std::optional<Buffer> take();
  // Hands a buffer back; `written` is how many bytes the device wrote into it (0 for one it only read).
  void give_back(std::uint16_t head, std::uint32_t written);
  // Whether the driver asked not to be interrupted for used buffers (it polls, or is busy).
  [[nodiscard]] bool driver_wants_interrupt() const;
  // Buffers offered and not taken yet.
  [[nodiscard]] std::uint16_t offered() const;

  [[nodiscard]] bool valid() const { return base_ != 0; }

 private:
  [[nodiscard]] volatile std::uint16_t* avail_u16(std::size_t index) const;
  [[nodiscard]] volatile std::uint16_t* used_u16(std::size_t index) const;

  std::uintptr_t base_ = 0;  // an address, not a byte pointer: the ring's fields are 16- and 32-bit words
  VringLayout layout_{1, 1};
  std::uint16_t last_avail_ = 0;  // the driver's avail.idx we have taken up to
  std::uint16_t used_ = 0;        // our used.idx
};

}  // namespace duet::rpmsg
