// The robot's peripherals on the STM32MP15, set up as the thesis' blocks set them up (section 5.5), and the model's
// resources routed to them. Numbers: TIM1 PWM at 2 kHz on channels 3 (PE13, right motor PWMA) and 4 (PE14, left
// PWMB), its channel 1 compare as the "TIM1" task once per period; hall encoders' A signals captured on rising edges
// by TIM2 channel 1 (PG8, left) and TIM4 channel 4 (PD15, right), the ultrasonic echo on both edges by TIM5
// channel 2 (PH11), all counting at 1 MHz; the MPU6500 on SPI5 with DMA2 streams 3 (transmit) and 2 (receive),
// its INT on PE8 (EXTI8); the battery on ADC1 channel 6 (PF12) by DMA2 stream 4.

#include "robot_peripherals.hpp"

#include <array>
#include <cstddef>
#include <span>
#include <string_view>

#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/hardware/hardware.hpp"
#include "duet/stm32mp15/adc.hpp"
#include "duet/stm32mp15/board.hpp"
#include "duet/stm32mp15/dma.hpp"
#include "duet/stm32mp15/exti.hpp"
#include "duet/stm32mp15/fault.hpp"
#include "duet/stm32mp15/gpio.hpp"
#include "duet/stm32mp15/hsem.hpp"
#include "duet/stm32mp15/rcc.hpp"
#include "duet/stm32mp15/spi.hpp"
#include "duet/stm32mp15/timer.hpp"
#include "robot_channels.hpp"

namespace balbot::board {
namespace {

namespace chip = duet::stm32mp15;
namespace hardware = duet::hardware;

constexpr std::uint64_t pwm_period_ns = 500'000;  // 2 kHz: the thesis' task 4, every 500 us
constexpr float pwm_task_at_percent = 50.0F;      // where in the period the "TIM1" task runs (eq. 5.1)
constexpr std::uint32_t capture_counter_hz = 1'000'000;

constexpr chip::Timer pwm_timer{chip::tim1_base, true};
constexpr chip::Timer left_hall_timer{chip::tim2_base, false};
constexpr chip::Timer right_hall_timer{chip::tim4_base, false};
constexpr chip::Timer echo_timer{chip::tim5_base, false};
constexpr unsigned pwm_task_channel = 1, right_pwm_channel = 3, left_pwm_channel = 4;
constexpr unsigned left_hall_channel = 1, right_hall_channel = 4, echo_channel = 2;
constexpr chip::Exti exti{};
constexpr unsigned imu_interrupt_line = 8;

constexpr hardware::Pin echo_pin = hardware::pin("PH11");

// The MPU6500 on SPI5: DMA2 stream 3 transmits, stream 2 receives (the thesis' streams; the model's tasks are named
// after them); at most 1 MHz, what the MPU6500 takes for every register.
constexpr std::uint32_t imu_clock_hz = 1'000'000;
constexpr std::size_t imu_transfer_capacity = 32;
constexpr std::uint8_t mpu6500_read = 0x80;  // the address byte's bit 7: a read
chip::SpiMaster<imu_transfer_capacity> imu_bus{
    chip::spi5_base, chip::DmaStream{chip::dma2_base, 3, chip::dma2_request_line(3)}, chip::dma_request::spi5_tx,
    chip::DmaStream{chip::dma2_base, 2, chip::dma2_request_line(2)}, chip::dma_request::spi5_rx};
bool imu_read_transfer = false;  // whether the transfer under way reads (its receive-complete task runs)

// The battery on ADC1 channel 6, DMA2 stream 4; the model asks for 100 samples at a time.
constexpr unsigned battery_channel = 6;
constexpr std::size_t battery_sample_capacity = 128;
chip::AdcSampler<battery_sample_capacity> battery_adc{chip::adc1_base, chip::adc12_common_base,
                                                      chip::DmaStream{chip::dma2_base, 4, chip::dma2_request_line(4)},
                                                      chip::dma_request::adc1};
constexpr hardware::Pin imu_chip_select = hardware::pin("PE7");

// The motor driver's standby and direction inputs low (TB6612FNG: standby, outputs off), the PWM off.
constexpr chip::SafePin low(hardware::Pin pin) { return {chip::gpio_base(pin.port), pin.number, false}; }
constexpr std::array safe_pins{low(hardware::pin("PA12")),   // MTR_STBY
                               low(hardware::pin("PE9")),    // MTRL_P
                               low(hardware::pin("PD1")),    // MTRL_N
                               low(hardware::pin("PE10")),   // MTRR_P
                               low(hardware::pin("PD14"))};  // MTRR_N
constexpr std::array safe_timers{pwm_timer};

// What the capture handlers took, as the model reads it.
hardware::CaptureReading left_hall, right_hall, echo;

bool take(const chip::Timer& timer, unsigned channel, hardware::CaptureReading& reading, bool rising) {
  const chip::Capture capture = timer.take_capture(channel);
  if (!capture.captured) return false;
  reading = {capture.count, rising};
  return true;
}

hardware::CaptureReading read_capture(const hardware::CaptureReading& reading) {
  const duet::cortex_m::InterruptMask masked;  // the capture's handler may preempt
  return reading;
}

void start_clocks() {
  const chip::Rcc rcc;
  for (const unsigned port : {0U, 3U, 4U, 5U, 6U, 7U}) rcc.enable(chip::clock::gpio(port));  // A, D-H
  for (const chip::PeripheralClock clock :
       {chip::clock::tim1, chip::clock::tim2, chip::clock::tim4, chip::clock::tim5, chip::clock::spi5,
        chip::clock::dma2, chip::clock::dmamux, chip::clock::adc12, chip::clock::hsem}) {
    rcc.enable(clock);
  }
}

// Alternate functions from the STM32MP157's datasheet (DS12505): TIM1 and TIM2 are AF1, TIM4 and TIM5 AF2, SPI5
// AF5 (PF7 SCK, PF8 MISO, PF9 MOSI). PF12 (ADC1_INP6) stays in its reset mode, analog. False if a pin's
// configuration could not take the GPIO hardware semaphore from Linux.
bool start_pins() {
  using hardware::pin;
  bool configured = true;
  // Outputs, low first (the motor driver in standby, TRIG and FSYNC idle), then the IMU's chip select high (idle).
  constexpr std::array outputs{pin("PA12"), pin("PE9"),  pin("PD1"), pin("PE10"),
                               pin("PD14"), pin("PE11"), pin("PE1"), imu_chip_select};
  for (const hardware::Pin output : outputs) {
    hardware::gpio_write(output, false);
    configured = chip::GpioPort{chip::gpio_base(output.port)}.make_output(output.number) && configured;
  }
  hardware::gpio_write(imu_chip_select, true);
  constexpr std::array inputs{pin("PH6"), pin("PG3"), pin("PE8")};  // hall B signals, the IMU's INT
  for (const hardware::Pin input : inputs) {
    configured = chip::GpioPort{chip::gpio_base(input.port)}.make_input(input.number, chip::Pull::none) && configured;
  }
  constexpr struct {
    hardware::Pin pin;
    unsigned function;
  } alternates[] = {{pin("PE13"), 1}, {pin("PE14"), 1}, {pin("PG8"), 1}, {pin("PD15"), 2},
                    {echo_pin, 2},    {pin("PF7"), 5},  {pin("PF8"), 5}, {pin("PF9"), 5}};
  for (const auto& alternate : alternates) {
    configured =
        chip::GpioPort{chip::gpio_base(alternate.pin.port)}.make_alternate(alternate.pin.number, alternate.function) &&
        configured;
  }
  return configured;
}

// The pins and the IMU's EXTI line, each changed holding its hardware semaphore; when Linux kept one, the log says how
// many takes gave up.
bool start_shared_registers() {
  if (start_pins() && exti.connect(imu_interrupt_line, hardware::pin("PE8").port, true, false)) return true;
  duet::TextBuffer<96> line;
  line.append("balbot: a GPIO or EXTI hardware semaphore stayed with Linux (")
      .append(chip::Hsem::failed_takes())
      .append(" takes gave up)\n");
  duet::cortex_m::console_write(line.view());
  return false;
}

// SPI5 at the fastest clock of at most 1 MHz from the kernel clock RCC says it has, the choice in the log. A kernel
// clock duet cannot tell the rate of gets the slowest divider.
bool start_imu_bus() {
  using ImuBus = decltype(imu_bus);
  const chip::KernelClock kernel = chip::Rcc{}.spi45_kernel_clock(chip::core_clock_hz, chip::hse_clock_hz);
  const std::uint32_t setting = ImuBus::baud_rate_setting(kernel.hz, imu_clock_hz);
  std::string_view verdict = "";
  if (setting == ImuBus::no_baud_rate) {
    verdict = ": too fast for any divider, the IMU is not started";
  } else if (kernel.hz == 0) {
    verdict = ": error, a rate duet cannot tell (shown as 0): the slowest divider, SCK at most 1 MHz up to 256 MHz";
  }
  const std::uint32_t divider = setting == ImuBus::no_baud_rate ? 0 : ImuBus::divider(setting);
  duet::TextBuffer<192> line;
  line.append("balbot: SPI5's kernel clock is ").append(chip::name(kernel.source)).append(' ').append(kernel.hz);
  line.append(" Hz, divider ").append(divider).append(": SCK ").append(divider == 0 ? 0 : kernel.hz / divider);
  line.append(" Hz").append(verdict).append('\n');
  duet::cortex_m::console_write(line.view());
  return imu_bus.start(kernel.hz, imu_clock_hz);
}

bool start_battery_adc() {
  return battery_adc.power_up(battery_channel, chip::adc_kernel_clock_hz, chip::core_clock_hz);
}

// The model's SpiDma block: one transaction, chip select low for its length. A transfer still running refuses the
// new one (HAL_BUSY in the thesis; the simulated robot refuses it too).
void start_imu_transfer(std::span<const std::uint8_t> bytes) {
  // Masked: a task of another priority may start one too, and must see this one whole or not at all.
  const duet::cortex_m::InterruptMask masked;
  if (bytes.empty() || imu_bus.busy()) return;
  imu_read_transfer = (bytes[0] & mpu6500_read) != 0;
  hardware::gpio_write(imu_chip_select, false);
  if (!imu_bus.transfer(bytes.first(bytes.size() < imu_transfer_capacity ? bytes.size() : imu_transfer_capacity))) {
    hardware::gpio_write(imu_chip_select, true);
  }
}

// What a driver's DMA buffer holds, as the model reads it: zeros beyond it.
template <typename Element>
void read_buffer(std::span<const Element> buffer, std::span<Element> values) {
  for (std::size_t k = 0; k < values.size(); ++k) values[k] = k < buffer.size() ? buffer[k] : Element{0};
}

// The model's AdcStart block: `count` conversions, ignored while a sequence runs (as the simulated robot does).
void start_battery_samples(std::uint16_t count) {
  if (count < 1 || count > battery_sample_capacity) return;
  (void)battery_adc.start(count);
}

bool start_timers() {
  const std::uint32_t clock = chip::timer_clock_hz;
  return pwm_timer.configure_pwm(pwm_period_ns, clock) && pwm_timer.enable_pwm_output(right_pwm_channel, 0.0F) &&
         pwm_timer.enable_pwm_output(left_pwm_channel, 0.0F) &&
         pwm_timer.enable_compare_interrupt(pwm_task_channel, pwm_task_at_percent) &&
         left_hall_timer.start_capture(left_hall_channel, chip::CaptureEdges::rising, capture_counter_hz, clock) &&
         right_hall_timer.start_capture(right_hall_channel, chip::CaptureEdges::rising, capture_counter_hz, clock) &&
         echo_timer.start_capture(echo_channel, chip::CaptureEdges::both, capture_counter_hz, clock);
}

}  // namespace
}  // namespace balbot::board

namespace balbot::board {

bool start_peripherals() {
  chip::set_safe_state({safe_pins, safe_timers});
  start_clocks();
  if (!start_shared_registers() || !start_timers() || !start_imu_bus() || !start_battery_adc()) {
    chip::enter_safe_state();
    return false;
  }
  pwm_timer.start();
  return true;
}

bool on_pwm_period() { return pwm_timer.take_compare_flag(pwm_task_channel); }
bool on_left_hall() { return take(left_hall_timer, left_hall_channel, left_hall, true); }
bool on_right_hall() { return take(right_hall_timer, right_hall_channel, right_hall, true); }
// Which edge: the timer does not say; the pin's level just after it does (the echo lasts at least 150 us).
bool on_echo_edge() { return take(echo_timer, echo_channel, echo, hardware::gpio_read(echo_pin)); }
bool on_spi_transmitted() { return imu_bus.on_transmit_interrupt().complete; }
// The end of a transaction: chip select high; the model's receive task runs for reads only, as on the simulated robot
// (an MPU6500 register write clocks in nothing worth reading).
bool on_spi_received() {
  const chip::DmaFlags flags = imu_bus.on_receive_interrupt();
  if (!flags.complete && !flags.error) return false;
  hardware::gpio_write(imu_chip_select, true);
  return flags.complete && !flags.error && imu_read_transfer;
}
void on_spi_error() {
  if (imu_bus.on_error_interrupt()) hardware::gpio_write(imu_chip_select, true);
}
bool on_adc_samples() {
  const chip::DmaFlags flags = battery_adc.on_dma_interrupt();
  return flags.complete && !flags.error;
}
bool on_imu_data_ready() {
  const bool rose = exti.rose(imu_interrupt_line);
  exti.acknowledge(imu_interrupt_line);
  return rose;
}

}  // namespace balbot::board

namespace duet::hardware {

using namespace balbot::board;

template <>
void pwm_write<pwm("TIM1", 3)>(float percent) {
  (void)pwm_timer.set_duty(right_pwm_channel, percent);
}
template <>
void pwm_write<pwm("TIM1", 4)>(float percent) {
  (void)pwm_timer.set_duty(left_pwm_channel, percent);
}
template <>
CaptureReading capture_read<capture("TIM2", 1)>() {
  return read_capture(left_hall);
}
template <>
CaptureReading capture_read<capture("TIM4", 4)>() {
  return read_capture(right_hall);
}
template <>
CaptureReading capture_read<capture("TIM5", 2)>() {
  return read_capture(echo);
}
template <>
void spi_transfer<spi("SPI5")>(std::span<const std::uint8_t> bytes) {
  start_imu_transfer(bytes);
}
template <>
void spi_received<spi("SPI5")>(std::span<std::uint8_t> bytes) {
  read_buffer(imu_bus.received(), bytes);
}
template <>
void adc_start<adc("ADC1", 6)>(std::uint16_t count) {
  start_battery_samples(count);
}
template <>
void adc_samples<adc("ADC1", 6)>(std::span<std::uint16_t> samples) {
  read_buffer(battery_adc.samples(), samples);
}
}  // namespace duet::hardware
