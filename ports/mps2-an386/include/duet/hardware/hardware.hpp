#pragma once
// The hardware interface generated code calls (docs/MODELS.md, "Hardware blocks"), on QEMU's mps2-an386. The board's
// user LEDs LED0..LED7 are pins of its own (bits of the LED register). Everything else a model names is the simulated
// plant's, reached over the virtual-hardware link (duet/mps2_an386/plant_link.hpp, docs/LINK.md): other pins by
// name ("gpio:PA12"), the resources ("pwm:TIM1/3", "spi:SPI5", ...) through plant_read() and plant_write() in their
// own types (bytes, counts, a float duty: no double on the firmware's side), and the plant's
// interrupts ("EXTI8", "TIM1", ...) on lines of the board that are wired to nothing. Each port has a header of this
// name; CMake chooses which one a build sees.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "duet/cortex_m/interrupts.hpp"
#include "duet/cortex_m/registers.hpp"
#include "duet/hardware/resources.hpp"
#include "duet/mps2_an386/board.hpp"

namespace duet::hardware {

// A board pin (mask != 0) or a plant pin, whose resource name is prepared at compile time.
struct Pin {
  std::uint32_t mask = 0;
  char resource[32]{};
  std::uint8_t resource_size = 0;

  [[nodiscard]] constexpr std::string_view resource_name() const { return {resource, resource_size}; }
};

namespace detail {
// Not constexpr: reaching it in a constant evaluation is the compile error for a pin or interrupt the board lacks.
inline Pin no_such_pin_on_mps2_an386() { return {}; }
}  // namespace detail

consteval Pin pin(std::string_view name) {
  Pin pin;
  if (name.size() == 4 && name.substr(0, 3) == "LED" && name[3] >= '0' && name[3] <= '7') {
    pin.mask = 1U << static_cast<unsigned>(name[3] - '0');
    return pin;
  }
  constexpr std::string_view prefix = "gpio:";
  if (name.empty() || name.size() > sizeof pin.resource - prefix.size()) return detail::no_such_pin_on_mps2_an386();
  prefix.copy(pin.resource, prefix.size());
  name.copy(pin.resource + prefix.size(), name.size());
  pin.resource_size = static_cast<std::uint8_t>(prefix.size() + name.size());
  return pin;
}

// The device interrupt number of an interrupt a model's triggered subsystem names (the vector table's names without
// _IRQHandler, or an interrupt of the simulated plant); the executive's slower rates use Software1..4.
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
  for (const mps2_an386::PlantInterrupt& interrupt : mps2_an386::plant_interrupts) {
    if (interrupt.name == name) return static_cast<std::uint16_t>(interrupt.line);
  }
  return static_cast<std::uint16_t>(detail::no_such_pin_on_mps2_an386().mask);
}

// The plant's pins as their levels are written, in order, until the plant link next talks to the plant and sends them
// as WRITE frames before anything else (PlantLink::send_pin_writes): a pin write is a few stores, as a board's is one
// to its GPIO's output register, and it reaches the plant no later than a WRITE frame would (those too wait for the
// link's next exchange). Interrupt tasks write pins too, so an entry is added with interrupts masked.
struct PlantPinWrites {
  static constexpr std::size_t capacity = 16;
  const Pin* pins[capacity];
  bool levels[capacity];
  std::size_t count;
};
inline PlantPinWrites plant_pin_writes{};

// The plant's resources by the plant's names, each in the type its typed call below moves, and the pin writes once
// they fill their buffer: what an image with a plant link defines (apps/balbot/pil: PlantLink's WRITE and READ). An
// image without one that reaches them halts with a message saying so (no_plant.cpp).
void plant_pin_writes_full();
void plant_write(std::string_view resource, std::span<const std::uint8_t> bytes);
void plant_write(std::string_view resource, std::span<const std::uint16_t> counts);
void plant_write(std::string_view resource, std::span<const float> values);
void plant_read(std::string_view resource, std::span<bool> levels);
void plant_read(std::string_view resource, std::span<std::uint8_t> bytes);
void plant_read(std::string_view resource, std::span<std::uint16_t> samples);
void plant_read(std::string_view resource, std::span<std::uint32_t> counts);

namespace detail {
template <auto resource>
inline constexpr bool routed_by_the_board = false;  // a specialization in board_routes.hpp is the routing
}  // namespace detail

// A message channel to the application core is the image's own (the robot's goes over a UART that stands in for
// RPMsg): it routes each in its duet/hardware/board_routes.hpp, as the STM32MP15's board configuration does. One it
// does not route does not compile.
template <IpcChannel channel>
void ipc_send(std::span<const std::uint8_t>) {
  static_assert(detail::routed_by_the_board<channel>, "the image routes no such IPC channel: see board_routes.hpp");
}
template <IpcChannel channel>
void ipc_receive(std::span<std::uint8_t>) {
  static_assert(detail::routed_by_the_board<channel>, "the image routes no such IPC channel: see board_routes.hpp");
}

inline void gpio_write(const Pin& pin, bool level) {
  if (pin.mask != 0) {
    volatile std::uint32_t& leds = cortex_m::register32(mps2_an386::leds_register);
    leds = level ? (leds | pin.mask) : (leds & ~pin.mask);
    return;
  }
  const std::uint32_t saved_primask = cortex_m::mask_interrupts();
  PlantPinWrites& writes = plant_pin_writes;
  if (writes.count == PlantPinWrites::capacity) [[unlikely]]
    plant_pin_writes_full();
  writes.pins[writes.count] = &pin;
  writes.levels[writes.count] = level;
  ++writes.count;
  cortex_m::restore_interrupts(saved_primask);
}

inline bool gpio_read(const Pin& pin) {
  if (pin.mask != 0) return (cortex_m::register32(mps2_an386::leds_register) & pin.mask) != 0;
  bool level = false;
  plant_read(pin.resource_name(), std::span<bool>{&level, 1});
  return level;
}

// The typed calls, by the plant's names for the resources (resources.hpp).
template <PwmChannel channel>
void pwm_write(float percent) {
  plant_write(plant_name(channel).view(), std::span<const float>{&percent, 1});
}

// The plant gives a capture as [count, rising (1 or 0)]: both read as u32, the edge true when not 0 (the same as the
// interpreter's conversion of the plant's 1 or 0 to bool).
template <CaptureChannel channel>
CaptureReading capture_read() {
  std::uint32_t values[2]{};
  plant_read(plant_name(channel).view(), std::span<std::uint32_t>{values});
  return {values[0], values[1] != 0};
}

template <SpiBus bus>
void spi_transfer(std::span<const std::uint8_t> bytes) {
  plant_write(plant_name(bus).view(), bytes);
}
template <SpiBus bus>
void spi_received(std::span<std::uint8_t> bytes) {
  plant_read(plant_name(bus).view(), bytes);
}

template <AdcInput input>
void adc_start(std::uint16_t count) {
  plant_write(plant_name(input).view(), std::span<const std::uint16_t>{&count, 1});
}
template <AdcInput input>
void adc_samples(std::span<std::uint16_t> samples) {
  plant_read(plant_name(input).view(), samples);
}

template <ExtiLine line>
bool exti_level() {
  bool level = false;
  plant_read(plant_name(line).view(), std::span<bool>{&level, 1});
  return level;
}

}  // namespace duet::hardware

// The image's routes, if it has any.
#if __has_include("duet/hardware/board_routes.hpp")
#include "duet/hardware/board_routes.hpp"
#endif
