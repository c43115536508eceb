#pragma once
// The resource table Linux's remoteproc reads from the firmware's ELF before it starts the Cortex-M4: one RPMsg
// virtio device with two vrings (their addresses filled in by Linux) and a trace buffer whose text appears in
// /sys/kernel/debug/remoteproc/remoteproc0/trace0. Little-endian, packed (all fields are 32-bit words but four
// bytes of the vdev entry). It lives in a section of its own, `.resource_table`, which start-up code leaves alone:
// Linux writes the vrings' addresses and the vdev's status into it, in the M4's memory, before the core runs.

#include <cstddef>
#include <cstdint>

namespace duet::stm32mp15 {

inline constexpr std::uint32_t resource_carveout = 0;
inline constexpr std::uint32_t resource_trace = 2;
inline constexpr std::uint32_t resource_vdev = 3;
inline constexpr std::uint32_t virtio_id_rpmsg = 7;
inline constexpr std::uint32_t rpmsg_feature_name_service = 1U << 0U;
inline constexpr std::uint8_t virtio_status_driver_ok = 0x04;
inline constexpr std::uint32_t address_any = 0xFFFF'FFFF;
inline constexpr std::uint32_t vring_entries = 16;
inline constexpr std::uint32_t vring_align = 16;
inline constexpr std::size_t trace_buffer_size = 2048;

struct VdevResource {
  std::uint32_t type;
  std::uint32_t id;
  std::uint32_t notify_id;
  std::uint32_t device_features;
  std::uint32_t driver_features;  // what Linux accepted: read it, not device_features
  std::uint32_t config_length;
  std::uint8_t status;  // Linux sets DRIVER_OK when its side of the rings is ready
  std::uint8_t vring_count;
  std::uint8_t reserved[2];
};

struct VringResource {
  std::uint32_t device_address;  // ANY in the image; Linux writes where it put the ring
  std::uint32_t align;
  std::uint32_t entries;
  std::uint32_t notify_id;  // the IPCC channel that signals this ring
  std::uint32_t reserved;
};

struct TraceResource {
  std::uint32_t type;
  std::uint32_t device_address;
  std::uint32_t length;
  std::uint32_t reserved;
  char name[32];
};

struct ResourceTable {
  std::uint32_t version;
  std::uint32_t count;
  std::uint32_t reserved[2];
  std::uint32_t offsets[2];
  VdevResource vdev;
  VringResource vrings[2];  // vring0: the M4 sends; vring1: the M4 receives
  TraceResource trace;
};

// Each entry starts with its type (Linux's struct fw_rsc_hdr), then Linux's fw_rsc_vdev (24 bytes), fw_rsc_trace (44).
static_assert(sizeof(VdevResource) == 4 + 24 && sizeof(VringResource) == 20 && sizeof(TraceResource) == 4 + 44,
              "the sizes of Linux's struct fw_rsc_vdev, fw_rsc_vdev_vring and fw_rsc_trace, with their type");
static_assert(offsetof(ResourceTable, vdev) == 24 && offsetof(ResourceTable, trace) == 24 + 28 + 2 * 20,
              "entries where the offsets say; no padding");
static_assert(sizeof(ResourceTable) <= 1024, "Linux maps the table with a fixed size of 1 KB");

// The firmware's table (resource_table.cpp), in `.resource_table`; volatile because Linux writes it.
extern volatile ResourceTable resource_table;
// The trace buffer's text, a ring that wraps; the table's trace entry points at it.
extern char trace_buffer[trace_buffer_size];

}  // namespace duet::stm32mp15
