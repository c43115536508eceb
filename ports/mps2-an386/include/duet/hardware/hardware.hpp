#pragma once
// The hardware interface generated code calls (docs/MODELS.md, "Hardware blocks"), on QEMU's mps2-an386: pins are
// the board's user LEDs LED0..LED7 (outputs, bits of the LED register). A pin the board does not have is a compile
// error where the generated code names it. Each port has a header of this name; CMake chooses which one a build sees.

#include <cstdint>
#include <string_view>

#include "duet/cortex_m/registers.hpp"
#include "duet/mps2_an386/board.hpp"

namespace duet::hardware {

struct Pin {
  std::uint32_t mask;
};

namespace detail {
// Not constexpr: reaching it in a constant evaluation is the compile error for a pin or interrupt the board lacks.
inline Pin no_such_pin_on_mps2_an386() { return {0}; }
}  // namespace detail

consteval Pin pin(std::string_view name) {
  if (name.size() == 4 && name.substr(0, 3) == "LED" && name[3] >= '0' && name[3] <= '7') {
    return {1U << static_cast<unsigned>(name[3] - '0')};
  }
  return detail::no_such_pin_on_mps2_an386();
}

// The device interrupt number of an interrupt a model's triggered subsystem names (the vector table's names without
// _IRQHandler); the executive's slower rates use Software1..4, so models trigger on the UARTs or the dual timer.
consteval std::uint16_t interrupt_number(std::string_view name) {
  constexpr struct {
    std::string_view name;
    unsigned number;
  } interrupts[] = {
      {"UART0_RX", mps2_an386::uart0_receive_interrupt}, {"UART0_TX", mps2_an386::uart0_transmit_interrupt},
      {"UART1_RX", mps2_an386::uart1_receive_interrupt}, {"UART1_TX", mps2_an386::uart1_transmit_interrupt},
      {"UART2_RX", mps2_an386::uart2_receive_interrupt}, {"UART2_TX", mps2_an386::uart2_transmit_interrupt},
      {"DUALTIMER", mps2_an386::dual_timer_interrupt}};
  for (const auto& interrupt : interrupts) {
    if (interrupt.name == name) return static_cast<std::uint16_t>(interrupt.number);
  }
  return static_cast<std::uint16_t>(detail::no_such_pin_on_mps2_an386().mask);
}

inline void gpio_write(Pin pin, bool level) {
  volatile std::uint32_t& leds = cortex_m::register32(mps2_an386::leds_register);
  leds = level ? (leds | pin.mask) : (leds & ~pin.mask);
}

inline bool gpio_read(Pin pin) { return (cortex_m::register32(mps2_an386::leds_register) & pin.mask) != 0; }

}  // namespace duet::hardware
