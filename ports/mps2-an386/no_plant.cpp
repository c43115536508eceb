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

[[gnu::weak]] void write(std::string_view resource, std::span<const double>) { no_plant(resource); }
[[gnu::weak]] void read(std::string_view resource, std::span<double>) { no_plant(resource); }

}  // namespace duet::hardware
