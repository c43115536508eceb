#pragma once
// An ADC converting one channel N times into memory by DMA (RM0436, ADC): the robot's battery voltage, ADC1 channel 6
// on PF12, the mean of 100 samples taken by one DMA one-shot within 2 ms (thesis 5.7 "ADC Battery Voltage", Req_08),
// DMA2 stream 4 with half-word elements. Register level, no HAL; the addresses are the blocks' (fake register files
// in the PC's tests). The object holds the samples: give it static storage in the M4's SRAM and never move it.
//   AdcSampler<> battery{adc1_base, adc12_common_base, DmaStream{dma2_base, 4, dma2_request_line(4)},
//                        dma_request::adc1};
//
// 16-bit results: the thesis' K_ADC = 3.3 V / 2^16 x (R46 + R47) / R46 ~ 192.85 uV per count (eq. 5.13) needs them
// (full scale 12.6 V); its CubeMX figure shows 12 bits, with which that gain would read a full scale of 0.79 V.
// Clock: the asynchronous kernel clock (CKMODE = 00) divided by 2, as the thesis' CubeMX set it; BOOST above 20 MHz
// (ST's HAL), at most 36 MHz (the STM32MP15 data sheet, as Linux's stm32-adc-core has it). Conversions run back to
// back (CONT) in DMA one-shot mode (DMNGT = 01): a DMA request per result until the stream's count is reached; the
// stream's completion then stops the ADC (ADSTP), which would otherwise convert on into overruns. Sampling time 64.5
// cycles, so a conversion takes 64.5 + 8.5 = 73 ADC cycles: 100 of them take 0.61 ms at 12 MHz, and fit in 2 ms down
// to an ADC clock of 3.65 MHz. The board enables the ADC's clock and leaves PF12 analog (its reset state).

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>

#include "duet/cortex_m/registers.hpp"
#include "duet/stm32mp15/dma.hpp"

namespace duet::stm32mp15 {

inline constexpr std::uintptr_t adc1_base = 0x4800'3000;
inline constexpr std::uintptr_t adc12_common_base = 0x4800'3300;

// `Capacity` samples at most per start(): the robot takes 100.
template <std::size_t Capacity = 1024>
class AdcSampler {
  static_assert(Capacity >= 1 && Capacity <= 0xFFFF, "NDTR counts at most 65535 samples");

 public:
  static constexpr std::uint32_t isr = 0x00, cr = 0x08, cfgr = 0x0C, smpr1 = 0x14, smpr2 = 0x18, pcsel = 0x1C,
                                 sqr1 = 0x30, dr = 0x40, difsel = 0xC0;
  static constexpr std::uint32_t ccr = 0x08;  // in the common block
  // ISR (flags cleared by writing 1)
  static constexpr std::uint32_t ready = 1U << 0U;              // ADRDY
  static constexpr std::uint32_t end_of_conversion = 1U << 2U;  // EOC
  static constexpr std::uint32_t end_of_sequence = 1U << 3U;    // EOS
  static constexpr std::uint32_t overrun = 1U << 4U;            // OVR
  // CR
  static constexpr std::uint32_t enable = 1U << 0U;                     // ADEN
  static constexpr std::uint32_t disable = 1U << 1U;                    // ADDIS
  static constexpr std::uint32_t start_conversions = 1U << 2U;          // ADSTART
  static constexpr std::uint32_t start_injected = 1U << 3U;             // JADSTART
  static constexpr std::uint32_t stop_conversions = 1U << 4U;           // ADSTP
  static constexpr std::uint32_t stop_injected = 1U << 5U;              // JADSTP
  static constexpr std::uint32_t boost = 1U << 8U;                      // BOOST
  static constexpr std::uint32_t linearity_calibration = 1U << 16U;     // ADCALLIN
  static constexpr std::uint32_t regulator = 1U << 28U;                 // ADVREGEN
  static constexpr std::uint32_t deep_power_down = 1U << 29U;           // DEEPPWD
  static constexpr std::uint32_t differential_calibration = 1U << 30U;  // ADCALDIF
  static constexpr std::uint32_t calibrate = 1U << 31U;                 // ADCAL
  // ADCAL, JADSTP, ADSTP, JADSTART, ADSTART, ADDIS, ADEN: software sets them, the ADC clears them, a 0 written to
  // them does nothing. Every write of CR leaves them 0 but the one asked for, so that a 1 read back never starts
  // its action again (ST's LL driver does the same).
  static constexpr std::uint32_t set_only = 0x8000'003F;
  // CFGR: DMNGT = 01 (DMA one-shot), OVRMOD, CONT; RES = 000 (16 bits), EXTEN = 00 (started by software)
  static constexpr std::uint32_t configuration = 1U << 0U | 1U << 12U | 1U << 13U;
  static constexpr std::uint32_t sampling_64_5_cycles = 5;        // SMPx
  static constexpr std::uint32_t clock_divided_by_2 = 1U << 18U;  // CCR: PRESC = 0001, CKMODE = 00 (asynchronous)
  static constexpr unsigned max_channel = 19;
  static constexpr std::uint32_t max_clock_hz = 36'000'000;
  static constexpr std::uint32_t boost_above_hz = 20'000'000;
  // Start-up timing: the regulator's start-up time t_ADCVREG_STUP, the longest calibration (offset and linearity),
  // and the ADC cycles between the end of calibration and ADEN (ST's LL driver, from the data sheet).
  static constexpr std::uint32_t regulator_start_up_us = 10;
  static constexpr std::uint64_t calibration_cycles = 16384;
  static constexpr std::uint64_t calibration_to_enable_cycles = 4;

  // `base`: the ADC's registers; `common_base`: its pair's common registers; `stream`: its DMA stream, fed by the
  // DMAMUX request `request`.
  constexpr AdcSampler(std::uintptr_t base, std::uintptr_t common_base, DmaStream stream, std::uint32_t request)
      : base_(base), common_base_(common_base), stream_(stream), request_(request) {}
  AdcSampler(const AdcSampler&) = delete;
  AdcSampler& operator=(const AdcSampler&) = delete;

  // At start-up, before the DMA interrupt is on; blocks for the ADC's start-up, each wait bounded (counted in reads
  // of the ADC's registers, each at least one core cycle). From the ADC's `kernel_clock_hz` with the core at
  // `cpu_clock_hz`: out of deep power-down, regulator on and settled, single-ended offset and linearity
  // calibration, enabled, then `channel` (0-19) preselected and alone in the regular sequence. An ADC a previous
  // firmware left enabled (remoteproc restarts the M4 without resetting its peripherals) is stopped and disabled
  // first, and its stream stopped. The other ADC of the pair must be disabled too (RM0436: the common clock setting
  // only then). False, nothing touched, for a channel or clock it cannot take; false when stopping, disabling,
  // calibration or ADRDY do not come in time.
  [[nodiscard]] bool power_up(unsigned channel, std::uint32_t kernel_clock_hz, std::uint32_t cpu_clock_hz) {
    const std::uint32_t adc_clock_hz = kernel_clock_hz / 2U;
    if (channel > max_channel || adc_clock_hz == 0 || adc_clock_hz > max_clock_hz || cpu_clock_hz == 0) {
      return false;
    }
    const std::uint64_t core_cycles_per_adc_cycle = (std::uint64_t{cpu_clock_hz} + adc_clock_hz - 1U) / adc_clock_hz;
    const std::uint64_t longest_wait = calibration_cycles * core_cycles_per_adc_cycle;
    if (!stop_previous_use(longest_wait)) return false;
    if (!stream_.configure({.direction = DmaDirection::peripheral_to_memory,
                            .peripheral_address = base_ + dr,
                            .memory_address = reinterpret_cast<std::uintptr_t>(samples_.data()),
                            .element = DmaElement::half_word,
                            .memory_increment = true,
                            .request = request_})) {
      return false;
    }
    cortex_m::register32(common_base_ + ccr) = clock_divided_by_2;
    control(deep_power_down, 0);
    control(0, regulator);
    pause(std::uint64_t{cpu_clock_hz} * regulator_start_up_us / 1'000'000U + 1U);
    if (adc_clock_hz > boost_above_hz) control(0, boost);
    cortex_m::modify32(base_ + difsel, 1U << channel, 0);  // single-ended: DIFSEL only while ADEN = 0
    // With DMNGT still 00: the calibration factor passes through DR and must not reach the DMA (ST's LL driver).
    control(differential_calibration, linearity_calibration | calibrate);
    if (!wait_for(cr, calibrate, 0, longest_wait)) return false;
    pause(calibration_to_enable_cycles * core_cycles_per_adc_cycle);
    write(isr, ready);  // a stale ADRDY must not end the wait below
    control(0, enable);
    if (!wait_for(isr, ready, ready, longest_wait)) return false;
    write(cfgr, configuration);
    const std::uint32_t sampling = channel < 10 ? smpr1 : smpr2;
    const unsigned shift = 3U * (channel % 10U);
    cortex_m::modify32(base_ + sampling, 7U << shift, sampling_64_5_cycles << shift);
    write(pcsel, 1U << channel);
    write(sqr1, channel << 6U);  // L = 0: one conversion, SQ1 = channel
    powered_ = true;
    return true;
  }

  // Conversions started and not yet stopped, or the stream still moving (or never powered up).
  [[nodiscard]] bool running() const {
    return !powered_ || (read(cr) & (start_conversions | stop_conversions)) != 0 || stream_.enabled();
  }

  // Converts `count` samples (1 to Capacity) into samples(). False, nothing touched, while running() or for a
  // count it cannot take. Call it from one task only.
  [[nodiscard]] bool start(std::uint32_t count) {
    if (count == 0 || count > Capacity || running()) return false;
    count_ = count;
    write(isr, end_of_conversion | end_of_sequence | overrun);  // nothing left from the last run (as the HAL does)
    write(cfgr, configuration);  // DMNGT written again before each start, as ST's HAL_ADC_Start_DMA does
    stream_.arm(count);
    control(0, start_conversions);
    return true;
  }

  // DMA2_Stream4's handler: takes the stream's flags; on completion or an error it stops the conversions (ADSTP
  // only while ADSTART = 1, RM0436; it never waits for them to stop). `complete` without `error`: samples() holds
  // the results.
  DmaFlags on_dma_interrupt() {
    const DmaFlags flags = stream_.take_flags();
    if (!flags.complete && !flags.error) return flags;
    if (flags.error) ++dma_errors_;
    if ((read(cr) & start_conversions) != 0) control(0, stop_conversions);
    return flags;
  }

  // The last run's samples, right-aligned 16-bit counts. Valid from its completion until the next start().
  [[nodiscard]] std::span<const std::uint16_t> samples() const {
    std::atomic_signal_fence(std::memory_order_acquire);  // the stream wrote them behind the compiler's back
    return {samples_.data(), count_};
  }
  [[nodiscard]] std::uint32_t dma_errors() const { return dma_errors_; }

 private:
  void control(std::uint32_t clear, std::uint32_t set) const { write(cr, (read(cr) & ~(set_only | clear)) | set); }
  // RM0436's way to disable an ADC: its conversions stopped (ADSTP, JADSTP, each only while its start bit is set),
  // then ADDIS, which the ADC clears with ADEN; then the stream stopped. Each wait within `polls` reads.
  [[nodiscard]] bool stop_previous_use(std::uint64_t polls) const {
    const std::uint32_t running = read(cr) & (start_conversions | start_injected);
    if (running != 0) {
      control(0, ((running & start_conversions) != 0 ? stop_conversions : 0U) |
                     ((running & start_injected) != 0 ? stop_injected : 0U));
      if (!wait_for(cr, start_conversions | start_injected, 0, polls)) return false;
    }
    if ((read(cr) & enable) != 0) {
      control(0, disable);
      if (!wait_for(cr, enable, 0, polls)) return false;
    }
    if (!stream_.enabled()) return true;
    stream_.disable();  // it finishes the element under way
    for (std::uint64_t poll = 0; poll < polls; ++poll) {
      if (!stream_.enabled()) return true;
    }
    return false;
  }
  // True once (read(offset) & mask) == expected, within `polls` reads.
  [[nodiscard]] bool wait_for(std::uint32_t offset, std::uint32_t mask, std::uint32_t expected,
                              std::uint64_t polls) const {
    for (std::uint64_t poll = 0; poll < polls; ++poll) {
      if ((read(offset) & mask) == expected) return true;
    }
    return false;
  }
  // At least `core_cycles` core cycles.
  void pause(std::uint64_t core_cycles) const {
    for (std::uint64_t cycle = 0; cycle < core_cycles; ++cycle) static_cast<void>(read(isr));
  }
  [[nodiscard]] std::uint32_t read(std::uint32_t offset) const { return cortex_m::register32(base_ + offset); }
  void write(std::uint32_t offset, std::uint32_t value) const { cortex_m::register32(base_ + offset) = value; }

  std::uintptr_t base_;
  std::uintptr_t common_base_;
  DmaStream stream_;
  std::uint32_t request_;
  std::array<std::uint16_t, Capacity> samples_{};
  std::size_t count_ = 0;
  std::uint32_t dma_errors_ = 0;
  bool powered_ = false;
};

}  // namespace duet::stm32mp15
