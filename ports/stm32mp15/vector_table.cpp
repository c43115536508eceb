// The vector table of the STM32MP15's Cortex-M4: 150 device interrupts. Each line with a peripheral has a handler of
// its RM0436 name (board.hpp's named_interrupts) + _IRQHandler, and the spare lines that software pends have
// Software0_IRQHandler to Software4_IRQHandler (board.hpp's spare_interrupts, in that order). An application handles
// an interrupt by defining a function of that name; the others report themselves as unhandled.

#include "duet/cortex_m/vector_table.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

#include "duet/stm32mp15/board.hpp"

// Every line with a peripheral but HSEM_IT2, which is a spare line (board.hpp) and so Software4's.
#define DUET_STM32MP15_PERIPHERAL_INTERRUPTS(X) \
  X(WWDG1);                                     \
  X(PVD_AVD);                                   \
  X(TAMP);                                      \
  X(RTC_WKUP_ALARM);                            \
  X(RCC);                                       \
  X(EXTI0);                                     \
  X(EXTI1);                                     \
  X(EXTI2);                                     \
  X(EXTI3);                                     \
  X(EXTI4);                                     \
  X(DMA1_Stream0);                              \
  X(DMA1_Stream1);                              \
  X(DMA1_Stream2);                              \
  X(DMA1_Stream3);                              \
  X(DMA1_Stream4);                              \
  X(DMA1_Stream5);                              \
  X(DMA1_Stream6);                              \
  X(ADC1);                                      \
  X(FDCAN1_IT0);                                \
  X(FDCAN2_IT0);                                \
  X(FDCAN1_IT1);                                \
  X(FDCAN2_IT1);                                \
  X(EXTI5);                                     \
  X(TIM1_BRK);                                  \
  X(TIM1_UP);                                   \
  X(TIM1_TRG_COM);                              \
  X(TIM1_CC);                                   \
  X(TIM2);                                      \
  X(TIM3);                                      \
  X(TIM4);                                      \
  X(I2C1_EV);                                   \
  X(I2C1_ER);                                   \
  X(I2C2_EV);                                   \
  X(I2C2_ER);                                   \
  X(SPI1);                                      \
  X(SPI2);                                      \
  X(USART1);                                    \
  X(USART2);                                    \
  X(USART3);                                    \
  X(EXTI10);                                    \
  X(RTC_TIMESTAMP);                             \
  X(EXTI11);                                    \
  X(TIM8_BRK);                                  \
  X(TIM8_UP);                                   \
  X(TIM8_TRG_COM);                              \
  X(TIM8_CC);                                   \
  X(DMA1_Stream7);                              \
  X(FMC);                                       \
  X(SDMMC1);                                    \
  X(TIM5);                                      \
  X(SPI3);                                      \
  X(UART4);                                     \
  X(UART5);                                     \
  X(TIM6);                                      \
  X(TIM7);                                      \
  X(DMA2_Stream0);                              \
  X(DMA2_Stream1);                              \
  X(DMA2_Stream2);                              \
  X(DMA2_Stream3);                              \
  X(DMA2_Stream4);                              \
  X(ETH1);                                      \
  X(ETH1_WKUP);                                 \
  X(FDCAN_CAL);                                 \
  X(EXTI6);                                     \
  X(EXTI7);                                     \
  X(EXTI8);                                     \
  X(EXTI9);                                     \
  X(DMA2_Stream5);                              \
  X(DMA2_Stream6);                              \
  X(DMA2_Stream7);                              \
  X(USART6);                                    \
  X(I2C3_EV);                                   \
  X(I2C3_ER);                                   \
  X(USBH_OHCI);                                 \
  X(USBH_EHCI);                                 \
  X(EXTI12);                                    \
  X(EXTI13);                                    \
  X(DCMI);                                      \
  X(CRYP1);                                     \
  X(HASH1);                                     \
  X(FPU);                                       \
  X(UART7);                                     \
  X(UART8);                                     \
  X(SPI4);                                      \
  X(SPI5);                                      \
  X(SPI6);                                      \
  X(SAI1);                                      \
  X(LTDC);                                      \
  X(LTDC_ER);                                   \
  X(ADC2);                                      \
  X(SAI2);                                      \
  X(QUADSPI);                                   \
  X(LPTIM1);                                    \
  X(CEC);                                       \
  X(I2C4_EV);                                   \
  X(I2C4_ER);                                   \
  X(SPDIF_RX);                                  \
  X(OTG);                                       \
  X(IPCC_RX0);                                  \
  X(IPCC_TX0);                                  \
  X(DMAMUX1_OVR);                               \
  X(IPCC_RX1);                                  \
  X(IPCC_TX1);                                  \
  X(CRYP2);                                     \
  X(HASH2);                                     \
  X(I2C5_EV);                                   \
  X(I2C5_ER);                                   \
  X(GPU);                                       \
  X(DFSDM1_FLT0);                               \
  X(DFSDM1_FLT1);                               \
  X(DFSDM1_FLT2);                               \
  X(DFSDM1_FLT3);                               \
  X(SAI3);                                      \
  X(DFSDM1_FLT4);                               \
  X(TIM15);                                     \
  X(TIM16);                                     \
  X(TIM17);                                     \
  X(TIM12);                                     \
  X(MDIOS);                                     \
  X(EXTI14);                                    \
  X(MDMA);                                      \
  X(DSI);                                       \
  X(SDMMC2);                                    \
  X(DFSDM1_FLT5);                               \
  X(EXTI15);                                    \
  X(nCTIIRQ1);                                  \
  X(nCTIIRQ2);                                  \
  X(TIM13);                                     \
  X(TIM14);                                     \
  X(DAC);                                       \
  X(RNG1);                                      \
  X(RNG2);                                      \
  X(I2C6_EV);                                   \
  X(I2C6_ER);                                   \
  X(SDMMC3);                                    \
  X(LPTIM2);                                    \
  X(LPTIM3);                                    \
  X(LPTIM4);                                    \
  X(LPTIM5);                                    \
  X(ETH1_LPI);                                  \
  X(MPU_SEV);                                   \
  X(RCC_WAKEUP);                                \
  X(SAI4);                                      \
  X(DTS);                                       \
  X(WAKEUP_PIN);

// Weak: an application's definition of the same name replaces it. Default_Handler reads the active exception number,
// so its report names the right interrupt.
#define DUET_WEAK_INTERRUPT_HANDLER(name) \
  extern "C" __attribute__((weak)) void name##_IRQHandler() { Default_Handler(); }

DUET_STM32MP15_PERIPHERAL_INTERRUPTS(DUET_WEAK_INTERRUPT_HANDLER)
DUET_WEAK_INTERRUPT_HANDLER(Software0)
DUET_WEAK_INTERRUPT_HANDLER(Software1)
DUET_WEAK_INTERRUPT_HANDLER(Software2)
DUET_WEAK_INTERRUPT_HANDLER(Software3)
DUET_WEAK_INTERRUPT_HANDLER(Software4)

namespace {

using duet::cortex_m::ExceptionHandler;
using duet::cortex_m::VectorTable;
namespace board = duet::stm32mp15;

struct DeviceHandlers {
  constexpr void place(unsigned line, ExceptionHandler handler) {
    by_line[line] = handler;
    ++placed;
  }

  std::array<ExceptionHandler, board::device_interrupt_count> by_line{};
  unsigned placed = 0;
};

// interrupt_by_name() fails to compile for a name that is not RM0436's.
#define DUET_PLACE_BY_NAME(name) handlers.place(board::interrupt_by_name(#name), name##_IRQHandler)

constexpr DeviceHandlers device_handlers = [] {
  DeviceHandlers handlers;
  DUET_STM32MP15_PERIPHERAL_INTERRUPTS(DUET_PLACE_BY_NAME)
  constexpr std::array software{Software0_IRQHandler, Software1_IRQHandler, Software2_IRQHandler, Software3_IRQHandler,
                                Software4_IRQHandler};
  static_assert(software.size() == board::spare_interrupts.size());
  for (std::size_t index = 0; index < software.size(); ++index) {
    handlers.place(board::spare_interrupts[index], software[index]);
  }
  return handlers;
}();

// Every line has a handler, and only one: no name above is missing or repeated, and no spare line is a peripheral's.
static_assert(device_handlers.placed == board::device_interrupt_count &&
              std::ranges::find(device_handlers.by_line, nullptr) == device_handlers.by_line.end());

}  // namespace

[[gnu::section(".vector_table"), gnu::used]] constinit const VectorTable<board::device_interrupt_count> vector_table{
    duet::cortex_m::__stack_end, duet::cortex_m::system_exception_handlers, device_handlers.by_line};
