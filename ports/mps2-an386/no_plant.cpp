// The plant's resources in an image without a plant link: reaching one is a mistake that halts with a message
// naming it. Weak: an image with a link (apps/balbot/pil) defines the real ones.

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/hardware/hardware.hpp"

namespace duet::hardware {
namespace {

[[noreturn]] void no_plant(std::string_view resource) {
  cortex_m::console_write("error: this image has no plant link, but its model reached ");
  cortex_m::console_write(resource);
  cortex_m::console_write("\n");
  cortex_m::halt(1);
}

}  // namespace

// Pin writes wait in their buffer until a link sends them: without one, the image halts once the buffer is full.
[[gnu::weak]] void plant_pin_writes_full() { no_plant(plant_pin_writes.pins[0]->resource_name()); }
[[gnu::weak]] void plant_write(std::string_view resource, std::span<const std::uint8_t>) { no_plant(resource); }
[[gnu::weak]] void plant_write(std::string_view resource, std::span<const std::uint16_t>) { no_plant(resource); }
[[gnu::weak]] void plant_write(std::string_view resource, std::span<const float>) { no_plant(resource); }
[[gnu::weak]] void plant_read(std::string_view resource, std::span<bool>) { no_plant(resource); }
[[gnu::weak]] void plant_read(std::string_view resource, std::span<std::uint8_t>) { no_plant(resource); }
[[gnu::weak]] void plant_read(std::string_view resource, std::span<std::uint16_t>) { no_plant(resource); }
[[gnu::weak]] void plant_read(std::string_view resource, std::span<std::uint32_t>) { no_plant(resource); }

}  // namespace duet::hardware
