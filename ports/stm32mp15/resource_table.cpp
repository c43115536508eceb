#include "duet/stm32mp15/resource_table.hpp"

namespace duet::stm32mp15 {

char trace_buffer[trace_buffer_size];

// Initialised statically: Linux reads it from the ELF file, before any of our code has run.
[[gnu::section(".resource_table"), gnu::used]] volatile ResourceTable resource_table = {
    .version = 1,
    .count = 2,
    .reserved = {0, 0},
    .offsets = {offsetof(ResourceTable, vdev), offsetof(ResourceTable, trace)},
    .vdev = {.type = resource_vdev,
             .id = virtio_id_rpmsg,
             .notify_id = 0,
             .device_features = rpmsg_feature_name_service,
             .driver_features = 0,
             .config_length = 0,
             .status = 0,
             .vring_count = 2,
             .reserved = {0, 0}},
    .vrings =
        {{.device_address = address_any, .align = vring_align, .entries = vring_entries, .notify_id = 0, .reserved = 0},
         {.device_address = address_any,
          .align = vring_align,
          .entries = vring_entries,
          .notify_id = 1,
          .reserved = 0}},
    .trace = {.type = resource_trace,
              .device_address = reinterpret_cast<std::uintptr_t>(trace_buffer),  // an address constant: a relocation
              .length = trace_buffer_size,
              .reserved = 0,
              .name = "cm4_log"},
};

}  // namespace duet::stm32mp15
