#pragma once
// The STM32MP15's Cortex-M4 (numbers from ST's CMSIS device header and RM0436): its clocks, and its device
// interrupts by name and number (the M4's exception number is 16 + these).

#include <array>
#include <iterator>
#include <string_view>

namespace duet::stm32mp15 {

// The M4 runs at the clock that the boot loader and Linux configured: 209 MHz on the STM32MP157C-DK2.
inline constexpr unsigned core_clock_hz = 209'000'000;
// Clocks duet assumes and does not set (docs/BOARD.md, "Clocks"): the timers' input clock (APB1 and APB2 timers at
// the MCU clock on the DK2), the ADCs' kernel clock (the 24 MHz HSE, ADC12's reset choice being per_ck from it on
// the DK2's device tree) and the HSE crystal's rate. SPI5's kernel clock is read from RCC at start-up (rcc.hpp).
inline constexpr unsigned timer_clock_hz = 209'000'000;
inline constexpr unsigned adc_kernel_clock_hz = 24'000'000;
inline constexpr unsigned hse_clock_hz = 24'000'000;
inline constexpr unsigned device_interrupt_count = 150;

// Every device interrupt with a peripheral, by its name in RM0436's NVIC table (ST's CMSIS names without _IRQn):
// the vector table's handlers are these names with _IRQHandler. The numbers missing (4, 99, 143, 148) are wired to
// nothing.
struct NamedInterrupt {
  std::string_view name;
  unsigned number;
};
inline constexpr NamedInterrupt named_interrupts[] = {
    {"WWDG1", 0},          {"PVD_AVD", 1},       {"TAMP", 2},          {"RTC_WKUP_ALARM", 3}, {"RCC", 5},
    {"EXTI0", 6},          {"EXTI1", 7},         {"EXTI2", 8},         {"EXTI3", 9},          {"EXTI4", 10},
    {"DMA1_Stream0", 11},  {"DMA1_Stream1", 12}, {"DMA1_Stream2", 13}, {"DMA1_Stream3", 14},  {"DMA1_Stream4", 15},
    {"DMA1_Stream5", 16},  {"DMA1_Stream6", 17}, {"ADC1", 18},         {"FDCAN1_IT0", 19},    {"FDCAN2_IT0", 20},
    {"FDCAN1_IT1", 21},    {"FDCAN2_IT1", 22},   {"EXTI5", 23},        {"TIM1_BRK", 24},      {"TIM1_UP", 25},
    {"TIM1_TRG_COM", 26},  {"TIM1_CC", 27},      {"TIM2", 28},         {"TIM3", 29},          {"TIM4", 30},
    {"I2C1_EV", 31},       {"I2C1_ER", 32},      {"I2C2_EV", 33},      {"I2C2_ER", 34},       {"SPI1", 35},
    {"SPI2", 36},          {"USART1", 37},       {"USART2", 38},       {"USART3", 39},        {"EXTI10", 40},
    {"RTC_TIMESTAMP", 41}, {"EXTI11", 42},       {"TIM8_BRK", 43},     {"TIM8_UP", 44},       {"TIM8_TRG_COM", 45},
    {"TIM8_CC", 46},       {"DMA1_Stream7", 47}, {"FMC", 48},          {"SDMMC1", 49},        {"TIM5", 50},
    {"SPI3", 51},          {"UART4", 52},        {"UART5", 53},        {"TIM6", 54},          {"TIM7", 55},
    {"DMA2_Stream0", 56},  {"DMA2_Stream1", 57}, {"DMA2_Stream2", 58}, {"DMA2_Stream3", 59},  {"DMA2_Stream4", 60},
    {"ETH1", 61},          {"ETH1_WKUP", 62},    {"FDCAN_CAL", 63},    {"EXTI6", 64},         {"EXTI7", 65},
    {"EXTI8", 66},         {"EXTI9", 67},        {"DMA2_Stream5", 68}, {"DMA2_Stream6", 69},  {"DMA2_Stream7", 70},
    {"USART6", 71},        {"I2C3_EV", 72},      {"I2C3_ER", 73},      {"USBH_OHCI", 74},     {"USBH_EHCI", 75},
    {"EXTI12", 76},        {"EXTI13", 77},       {"DCMI", 78},         {"CRYP1", 79},         {"HASH1", 80},
    {"FPU", 81},           {"UART7", 82},        {"UART8", 83},        {"SPI4", 84},          {"SPI5", 85},
    {"SPI6", 86},          {"SAI1", 87},         {"LTDC", 88},         {"LTDC_ER", 89},       {"ADC2", 90},
    {"SAI2", 91},          {"QUADSPI", 92},      {"LPTIM1", 93},       {"CEC", 94},           {"I2C4_EV", 95},
    {"I2C4_ER", 96},       {"SPDIF_RX", 97},     {"OTG", 98},          {"IPCC_RX0", 100},     {"IPCC_TX0", 101},
    {"DMAMUX1_OVR", 102},  {"IPCC_RX1", 103},    {"IPCC_TX1", 104},    {"CRYP2", 105},        {"HASH2", 106},
    {"I2C5_EV", 107},      {"I2C5_ER", 108},     {"GPU", 109},         {"DFSDM1_FLT0", 110},  {"DFSDM1_FLT1", 111},
    {"DFSDM1_FLT2", 112},  {"DFSDM1_FLT3", 113}, {"SAI3", 114},        {"DFSDM1_FLT4", 115},  {"TIM15", 116},
    {"TIM16", 117},        {"TIM17", 118},       {"TIM12", 119},       {"MDIOS", 120},        {"EXTI14", 121},
    {"MDMA", 122},         {"DSI", 123},         {"SDMMC2", 124},      {"HSEM_IT2", 125},     {"DFSDM1_FLT5", 126},
    {"EXTI15", 127},       {"nCTIIRQ1", 128},    {"nCTIIRQ2", 129},    {"TIM13", 130},        {"TIM14", 131},
    {"DAC", 132},          {"RNG1", 133},        {"RNG2", 134},        {"I2C6_EV", 135},      {"I2C6_ER", 136},
    {"SDMMC3", 137},       {"LPTIM2", 138},      {"LPTIM3", 139},      {"LPTIM4", 140},       {"LPTIM5", 141},
    {"ETH1_LPI", 142},     {"MPU_SEV", 144},     {"RCC_WAKEUP", 145},  {"SAI4", 146},         {"DTS", 147},
    {"WAKEUP_PIN", 149}};
static_assert(
    [] {
      unsigned lowest_next = 0;
      for (const NamedInterrupt& interrupt : named_interrupts) {
        if (interrupt.number < lowest_next || interrupt.number >= device_interrupt_count) return false;
        lowest_next = interrupt.number + 1;
      }
      return std::size(named_interrupts) == device_interrupt_count - 4;
    }(),
    "named_interrupts must list each number once, in order");

namespace detail {
// Not constexpr: reaching it in a constant evaluation is the compile error for a name the chip has no interrupt of.
inline unsigned no_such_interrupt_on_stm32mp15() { return 0; }
}  // namespace detail

// The number of the device interrupt `name` (one of named_interrupts, e.g. "TIM1_UP"), at compile time.
consteval unsigned interrupt_by_name(std::string_view name) {
  for (const NamedInterrupt& interrupt : named_interrupts) {
    if (interrupt.name == name) return interrupt.number;
  }
  return detail::no_such_interrupt_on_stm32mp15();
}

// The table against the numbers of RM0436's text, a source apart from the header the table follows.
static_assert(
    []() consteval {
      constexpr struct {
        std::string_view name;
        unsigned number;
      } facts[] = {{"ADC1", 18},         {"TIM1_UP", 25},   {"TIM1_CC", 27}, {"TIM2", 28},         {"TIM4", 30},
                   {"TIM5", 50},         {"TIM6", 54},      {"TIM7", 55},    {"DMA2_Stream2", 58}, {"DMA2_Stream3", 59},
                   {"DMA2_Stream4", 60}, {"SPI5", 85},      {"ADC2", 90},    {"DMAMUX1_OVR", 102}, {"IPCC_RX1", 103},
                   {"IPCC_TX1", 104},    {"HSEM_IT2", 125}, {"EXTI0", 6},    {"EXTI1", 7},         {"EXTI2", 8},
                   {"EXTI3", 9},         {"EXTI4", 10},     {"EXTI5", 23},   {"EXTI6", 64},        {"EXTI7", 65},
                   {"EXTI8", 66},        {"EXTI9", 67},     {"EXTI10", 40},  {"EXTI11", 42},       {"EXTI12", 76},
                   {"EXTI13", 77},       {"EXTI14", 121},   {"EXTI15", 127}};
      for (const auto& [name, number] : facts) {
        if (interrupt_by_name(name) != number) return false;
      }
      return true;
    }(),
    "named_interrupts disagrees with the facts' interrupt numbers");

// The lines duet's own code names.
namespace interrupt {
inline constexpr unsigned tim1_capture_compare = interrupt_by_name("TIM1_CC");
inline constexpr unsigned tim2 = interrupt_by_name("TIM2");
inline constexpr unsigned tim7 = interrupt_by_name("TIM7");
inline constexpr unsigned exti8 = interrupt_by_name("EXTI8");
inline constexpr unsigned spi5 = interrupt_by_name("SPI5");
inline constexpr unsigned ipcc_rx1 = interrupt_by_name("IPCC_RX1");
inline constexpr unsigned hsem_it2 = interrupt_by_name("HSEM_IT2");
}  // namespace interrupt

// Lines that nothing the M4 can see ever raises, for software to pend (cortex_m::set_interrupt_pending): the
// executive's slower rates and the RPMsg transport's hand-over of the application's messages. Their handlers are
// Software0_IRQHandler to Software4_IRQHandler, in this order (vector_table.cpp), as on mps2-an386.
// A peripheral's line reaches the M4's NVIC whichever core owns the peripheral, so no line of a peripheral Linux may
// use (Ethernet, SDMMC, USB, IPCC_RX0/TX0, ...) is spare, nor MPU_SEV (every SEV the Cortex-A7s execute, which Linux's
// spinlocks do), FPU (the M4's own floating-point exceptions) or nCTIIRQ1/2 (a debugger's cross-triggers). First the 4
// reserved numbers, wired to nothing but implemented by the NVIC, which has all 150 lines; then HSEM_IT2, which HSEM
// raises only for semaphores the M4 itself enables in C2IER (RM0436, HSEM), and duet enables none.
inline constexpr std::array<unsigned, 5> spare_interrupts{4, 99, 143, 148, interrupt::hsem_it2};

// What duet pends on the spare lines (handlers Software0 .. Software4): the executive's slower rates 1 and 2
// (executive_port.hpp) and the model's "IPCC_RX1" task, which the link to Linux pends when the application's message
// has arrived (duet/hardware/hardware.hpp).
inline constexpr unsigned application_message_interrupt = spare_interrupts[2];

}  // namespace duet::stm32mp15
