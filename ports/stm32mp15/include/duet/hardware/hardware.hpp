#pragma once
// The hardware interface generated code calls (docs/MODELS.md, "Hardware blocks"), on the STM32MP15's Cortex-M4.
// Pins by port and number ("PA12", "PH11") go straight to the GPIO registers; a pin the chip lacks is a compile error.
// Interrupts by the vector table's names (RM0436's: "EXTI8", "DMA2_Stream2", ...), and two by the names the thesis'
// models use: "TIM1" is TIM1's capture/compare interrupt (its PWM blocks raise it once per period), and "IPCC_RX1"
// is the line the link to Linux pends when the application's message has arrived (the chip's own IPCC_RX1 carries
// every RPMsg message and belongs to the link, duet/stm32mp15/linux_link.hpp).
//
// The peripherals behind the other resources (duet/hardware/resources.hpp: a PWM channel, an SPI bus, ...) are the
// application's board configuration: which DMA stream, which buffers. It routes each resource its model uses by
// declaring the typed call for it in its duet/hardware/board_routes.hpp (an explicit specialization: apps/balbot/board/
// routes) and defining it with this port's drivers. A resource it does not route reaches the templates below, which
// do not compile: the board cannot silently lack what the model uses. Values travel in their own types; nothing here
// compares names or converts doubles at run time. Each port has a header of this name; CMake chooses which one a
// build sees.

#include <cstdint>
#include <span>
#include <string_view>

#include "duet/hardware/resources.hpp"
#include "duet/stm32mp15/board.hpp"
#include "duet/stm32mp15/gpio.hpp"

namespace duet::hardware {

struct Pin {
  std::uint8_t port;  // 0 is GPIOA
  std::uint8_t number;
};

namespace detail {
// Not constexpr: reaching it in a constant evaluation is the compile error for a pin the chip lacks.
inline Pin no_such_pin_on_stm32mp15() { return {}; }
}  // namespace detail

// "PA0" .. "PK15".
consteval Pin pin(std::string_view name) {
  if (name.size() < 3 || name.size() > 4 || name[0] != 'P' || name[1] < 'A' || name[1] > 'K') {
    return detail::no_such_pin_on_stm32mp15();
  }
  unsigned number = 0;
  for (const char digit : name.substr(2)) {
    if (digit < '0' || digit > '9') return detail::no_such_pin_on_stm32mp15();
    number = number * 10 + static_cast<unsigned>(digit - '0');
  }
  if (number > 15 || (name.size() == 4 && name[2] == '0')) return detail::no_such_pin_on_stm32mp15();
  return {static_cast<std::uint8_t>(name[1] - 'A'), static_cast<std::uint8_t>(number)};
}

consteval std::uint16_t interrupt_number(std::string_view name) {
  if (name == "TIM1") return stm32mp15::interrupt::tim1_capture_compare;
  if (name == "IPCC_RX1") return stm32mp15::application_message_interrupt;
  return static_cast<std::uint16_t>(stm32mp15::interrupt_by_name(name));
}

namespace detail {
template <auto resource>
inline constexpr bool routed_by_the_board = false;  // a specialization in board_routes.hpp is the routing
}  // namespace detail

template <PwmChannel channel>
void pwm_write(float) {
  static_assert(detail::routed_by_the_board<channel>, "the board routes no such PWM channel: see board_routes.hpp");
}
template <CaptureChannel channel>
CaptureReading capture_read() {
  static_assert(detail::routed_by_the_board<channel>, "the board routes no such capture channel: see board_routes.hpp");
  return {};
}
template <SpiBus bus>
void spi_transfer(std::span<const std::uint8_t>) {
  static_assert(detail::routed_by_the_board<bus>, "the board routes no such SPI bus: see board_routes.hpp");
}
template <SpiBus bus>
void spi_received(std::span<std::uint8_t>) {
  static_assert(detail::routed_by_the_board<bus>, "the board routes no such SPI bus: see board_routes.hpp");
}
template <AdcInput input>
void adc_start(std::uint16_t) {
  static_assert(detail::routed_by_the_board<input>, "the board routes no such ADC input: see board_routes.hpp");
}
template <AdcInput input>
void adc_samples(std::span<std::uint16_t>) {
  static_assert(detail::routed_by_the_board<input>, "the board routes no such ADC input: see board_routes.hpp");
}
template <ExtiLine line>
bool exti_level() {
  static_assert(detail::routed_by_the_board<line>, "the board routes no such EXTI line: see board_routes.hpp");
  return false;
}
template <IpcChannel channel>
void ipc_send(std::span<const std::uint8_t>) {
  static_assert(detail::routed_by_the_board<channel>, "the board routes no such IPC channel: see board_routes.hpp");
}
template <IpcChannel channel>
void ipc_receive(std::span<std::uint8_t>) {
  static_assert(detail::routed_by_the_board<channel>, "the board routes no such IPC channel: see board_routes.hpp");
}

inline void gpio_write(const Pin& pin, bool level) {
  stm32mp15::GpioPort{stm32mp15::gpio_base(pin.port)}.set(pin.number, level);
}
inline bool gpio_read(const Pin& pin) { return stm32mp15::GpioPort{stm32mp15::gpio_base(pin.port)}.read(pin.number); }

}  // namespace duet::hardware

// The application's routes, if it has any (an image whose model uses only pins needs none).
#if __has_include("duet/hardware/board_routes.hpp")
#include "duet/hardware/board_routes.hpp"
#endif
