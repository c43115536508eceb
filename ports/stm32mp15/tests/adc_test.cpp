// ADC1 sampling the battery against fake register files (ADC1, the ADC12 common block, DMA2, DMAMUX1): the start-up
// in RM0436's order, an ADC a previous firmware left converting stopped and disabled first, a one-shot run of 100
// samples by DMA stopped on the stream's completion, refusals while a run goes on, and DMA errors counted. Plain
// memory cannot end a calibration, so a thread plays that part of the ADC during start-up and notes what the driver
// had set when the calibration began. Nor can it show a wait for the ADC to stop or to disable: the driver's own
// writes of ADSTP and ADDIS leave ADSTART and ADEN 0 there (a 0 written to them does nothing on the chip).
#include "duet/stm32mp15/adc.hpp"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <thread>
#include <vector>

namespace duet::stm32mp15 {
namespace {

using Adc = AdcSampler<1024>;

constexpr std::uint32_t hisr = 0x04, hifcr = 0x0C;
constexpr std::uint32_t stream_cr = 0x10, ndtr = 0x14, par = 0x18, m0ar = 0x1C;
constexpr unsigned adc_stream = 4;
constexpr std::uint32_t stream_complete = 1U << 5, stream_error = 1U << 3;  // TCIF4, TEIF4 in HISR
constexpr unsigned battery = 6;
// A 2 kHz kernel clock stretches the driver's calibration bound (16384 ADC cycles, counted in core cycles) to
// billions of reads, so that the thread below answers in time however the PC schedules it.
constexpr std::uint32_t slow_kernel_clock_hz = 2'000;
constexpr std::uint32_t core_clock_hz = 209'000'000;

// The ADC's end of a calibration: clears ADCAL as soon as the driver sets it, after noting CR, CFGR, DIFSEL and
// the common CCR as they were then.
class CalibratingAdc {
 public:
  struct Registers {
    std::uint32_t cr, cfgr, difsel, ccr;
  };

  CalibratingAdc(std::uint32_t& control, std::uint32_t& configuration, std::uint32_t& differential,
                 std::uint32_t& common_control)
      : thread_([this, cr = &control, cfgr = &configuration, difsel = &differential,
                 ccr = &common_control](const std::stop_token& stop) {
          while (!stop.stop_requested()) {
            const std::uint32_t value = std::atomic_ref<std::uint32_t>{*cr}.load();
            if ((value & Adc::calibrate) != 0) {
              at_calibration_ = {value, std::atomic_ref<std::uint32_t>{*cfgr}.load(),
                                 std::atomic_ref<std::uint32_t>{*difsel}.load(),
                                 std::atomic_ref<std::uint32_t>{*ccr}.load()};
              std::atomic_ref<std::uint32_t>{*cr}.store(value & ~Adc::calibrate);
              return;
            }
            std::this_thread::yield();
          }
        }) {}

  // Stops playing the ADC; the registers as they were when calibration began (all 0 if it never did).
  Registers finish() {
    thread_.request_stop();
    thread_.join();
    return at_calibration_;
  }

 private:
  Registers at_calibration_{};
  std::jthread thread_;
};

class AdcTest : public ::testing::Test {
 protected:
  std::uint32_t& reg(std::uint32_t offset) { return adc_registers[offset / 4]; }
  std::uint32_t& stream_reg(std::uint32_t offset) { return dma[(offset + 0x18 * adc_stream) / 4]; }
  std::uintptr_t adc_base() { return reinterpret_cast<std::uintptr_t>(adc_registers.data()); }
  DmaStream stream() {
    return DmaStream{reinterpret_cast<std::uintptr_t>(dma.data()), adc_stream,
                     reinterpret_cast<std::uintptr_t>(&dmamux[8 + adc_stream])};
  }
  // Memory at a DMA address: the M4's 32-bit addresses are the low half of the PC's.
  std::uint16_t* memory_at(std::uint32_t address) {
    return reinterpret_cast<std::uint16_t*>((reinterpret_cast<std::uintptr_t>(&adc) & ~std::uintptr_t{0xFFFF'FFFF}) |
                                            address);
  }
  // Powers the ADC up from its reset state with the calibration answered; what was set when it began.
  CalibratingAdc::Registers power_up() {
    reg(Adc::cr) = Adc::deep_power_down;  // reset value
    CalibratingAdc calibration{reg(Adc::cr), reg(Adc::cfgr), reg(Adc::difsel), common[Adc::ccr / 4]};
    EXPECT_TRUE(adc.power_up(battery, slow_kernel_clock_hz, core_clock_hz));
    return calibration.finish();
  }
  // What the stream and the ADC do at the end of a run of `values.size()` samples.
  void finish_run(const std::vector<std::uint16_t>& values) {
    std::uint16_t* buffer = memory_at(stream_reg(m0ar));
    for (std::size_t i = 0; i < values.size(); ++i) buffer[i] = values[i];
    stream_reg(stream_cr) &= ~1U;
    dma[hisr / 4] = stream_complete;
    reg(Adc::cr) |= Adc::start_conversions;  // continuous conversions go on
  }

  std::array<std::uint32_t, 0xC8 / 4> adc_registers{};
  std::array<std::uint32_t, 4> common{};
  std::array<std::uint32_t, 0xD0 / 4> dma{};
  std::array<std::uint32_t, 16> dmamux{};
  Adc adc{adc_base(), reinterpret_cast<std::uintptr_t>(common.data()), stream(), dma_request::adc1};
};

TEST_F(AdcTest, PowersUpInTheManualsOrder) {
  reg(Adc::difsel) = 0x41;        // channel 6 differential, as a previous user might have left it
  reg(Adc::smpr1) = 0x3FFF'FFFF;  // every channel at 810.5 cycles
  const CalibratingAdc::Registers at_calibration = power_up();
  // Calibration began out of deep power-down, the regulator on, still disabled, single-ended, with the clock set
  // and DMA off (DMNGT = 00: the calibration factor passes through DR).
  EXPECT_EQ(at_calibration.cr, 0x9001'0000U);  // ADCAL, ADVREGEN, ADCALLIN
  EXPECT_EQ(at_calibration.cfgr, 0U);
  EXPECT_EQ(at_calibration.difsel, 0x01U);
  EXPECT_EQ(at_calibration.ccr, 0x0004'0000U);  // PRESC = 0001 (/2), CKMODE = 00
  EXPECT_EQ(reg(Adc::cr), 0x1001'0001U);        // ADEN; BOOST off at a 1 kHz ADC clock
  EXPECT_EQ(reg(Adc::isr), Adc::ready);         // cleared before ADEN was set
  EXPECT_EQ(reg(Adc::cfgr), 0x3001U);           // CONT, OVRMOD, DMNGT = 01, RES = 16 bits, software start
  EXPECT_EQ(reg(Adc::smpr1), 0x3FF7'FFFFU);     // channel 6 at 64.5 cycles, the others untouched
  EXPECT_EQ(reg(Adc::pcsel), 0x40U);
  EXPECT_EQ(reg(Adc::sqr1), 0x180U);  // SQ1 = 6, L = 0
  EXPECT_EQ(common[Adc::ccr / 4], 0x0004'0000U);
  EXPECT_EQ(stream_reg(stream_cr), 0x2C14U);  // peripheral to memory, half-words, MINC, TCIE, TEIE
  EXPECT_EQ(stream_reg(par), static_cast<std::uint32_t>(adc_base() + 0x40));  // DR
  EXPECT_EQ(dmamux[8 + adc_stream], 9U);
  const auto object = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(&adc));
  EXPECT_GE(stream_reg(m0ar), object);
  EXPECT_LE(stream_reg(m0ar) + 2 * 1024, object + sizeof(adc));
  EXPECT_FALSE(adc.running());
}

TEST_F(AdcTest, ChannelsFromTenTakeTheirSamplingTimeFromSmpr2) {
  reg(Adc::cr) = Adc::deep_power_down;
  reg(Adc::difsel) = 0xF'FFFF;
  CalibratingAdc calibration{reg(Adc::cr), reg(Adc::cfgr), reg(Adc::difsel), common[Adc::ccr / 4]};
  ASSERT_TRUE(adc.power_up(10, slow_kernel_clock_hz, core_clock_hz));
  EXPECT_EQ(calibration.finish().difsel, 0xF'FBFFU);
  EXPECT_EQ(reg(Adc::smpr1), 0U);
  EXPECT_EQ(reg(Adc::smpr2), 5U);  // SMP10, SMPR2's first field
  EXPECT_EQ(reg(Adc::pcsel), 1U << 10);
  EXPECT_EQ(reg(Adc::sqr1), 10U << 6);
}

TEST_F(AdcTest, BoostsAFastClockAndGivesUpOnACalibrationThatNeverEnds) {
  reg(Adc::cr) = Adc::deep_power_down;
  EXPECT_FALSE(adc.power_up(battery, 48'000'000, core_clock_hz));  // 24 MHz ADC clock; nothing clears ADCAL
  EXPECT_EQ(reg(Adc::cr), 0x9001'0100U);                           // ADCAL, ADVREGEN, ADCALLIN, BOOST; never ADEN
  EXPECT_EQ(reg(Adc::cfgr), 0U);
  EXPECT_EQ(reg(Adc::pcsel), 0U);
  EXPECT_TRUE(adc.running());  // never powered up: start() refuses
  EXPECT_FALSE(adc.start(100));
}

TEST_F(AdcTest, RefusesWhatItCannotTakeTouchingNothing) {
  const auto expect_refused = [this](unsigned channel, std::uint32_t kernel_clock_hz, std::uint32_t core_hz) {
    const auto adc_before = adc_registers;
    const auto dma_before = dma;
    EXPECT_FALSE(adc.power_up(channel, kernel_clock_hz, core_hz));
    EXPECT_EQ(adc_registers, adc_before);
    EXPECT_EQ(dma, dma_before);
    EXPECT_EQ(common[Adc::ccr / 4], 0U);
  };
  reg(Adc::cr) = Adc::deep_power_down;
  expect_refused(20, 24'000'000, core_clock_hz);       // ADC1 has channels 0-19
  expect_refused(battery, 74'000'000, core_clock_hz);  // 37 MHz: above the data sheet's 36 MHz
  expect_refused(battery, 1, core_clock_hz);           // no ADC clock at all
  expect_refused(battery, 24'000'000, 0);
}

TEST_F(AdcTest, AnAdcAPreviousFirmwareLeftConvertingIsDisabledAndStartedAgain) {
  reg(Adc::cr) = Adc::regulator | Adc::enable | Adc::start_conversions;
  reg(Adc::cfgr) = 0x3001;         // its continuous conversions into DMA
  stream_reg(stream_cr) = 0x2C15;  // its stream still moving
  CalibratingAdc calibration{reg(Adc::cr), reg(Adc::cfgr), reg(Adc::difsel), common[Adc::ccr / 4]};
  ASSERT_TRUE(adc.power_up(battery, slow_kernel_clock_hz, core_clock_hz));
  const CalibratingAdc::Registers at_calibration = calibration.finish();
  EXPECT_EQ(at_calibration.cr, 0x9001'0000U);  // calibrated disabled and stopped, as from reset
  EXPECT_EQ(reg(Adc::cr), 0x1001'0001U);       // enabled again, nothing else running
  EXPECT_EQ(stream_reg(stream_cr), 0x2C14U);   // the stream set up anew, not moving
  EXPECT_FALSE(adc.running());
  EXPECT_TRUE(adc.start(100));
}

TEST_F(AdcTest, StartArmsTheStreamThenStartsConversions) {
  power_up();
  reg(Adc::isr) = 0;
  ASSERT_TRUE(adc.start(100));
  EXPECT_EQ(reg(Adc::isr), 0x1CU);  // EOC, EOS, OVR cleared
  EXPECT_EQ(reg(Adc::cfgr), 0x3001U);
  EXPECT_EQ(dma[hifcr / 4], 0x3DU);  // stream 4's flags
  EXPECT_EQ(stream_reg(ndtr), 100U);
  EXPECT_EQ(stream_reg(stream_cr), 0x2C15U);
  EXPECT_EQ(reg(Adc::cr), 0x1001'0004U);  // ADSTART; ADEN written 0, which leaves it set in the ADC
  EXPECT_TRUE(adc.running());
}

TEST_F(AdcTest, RefusesWhileARunGoesOnAndCountsItCannotTake) {
  power_up();
  const auto expect_refused = [this](std::uint32_t count) {
    const auto adc_before = adc_registers;
    const auto dma_before = dma;
    EXPECT_FALSE(adc.start(count));
    EXPECT_EQ(adc_registers, adc_before);
    EXPECT_EQ(dma, dma_before);
  };
  expect_refused(0);
  expect_refused(1025);
  ASSERT_TRUE(adc.start(100));
  expect_refused(100);  // converting, the stream moving
  stream_reg(stream_cr) &= ~1U;
  expect_refused(100);  // converting
  reg(Adc::cr) = Adc::regulator | Adc::enable | Adc::stop_conversions;
  expect_refused(100);  // stopping
  reg(Adc::cr) = Adc::regulator | Adc::enable;
  stream_reg(stream_cr) |= 1U;
  expect_refused(100);  // the stream still moving
  stream_reg(stream_cr) &= ~1U;
  EXPECT_TRUE(adc.start(1024));
}

TEST_F(AdcTest, TheStreamsCompletionStopsTheAdcAndHandsOverTheSamples) {
  power_up();
  ASSERT_TRUE(adc.start(100));
  std::vector<std::uint16_t> values(100);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<std::uint16_t>(40'000 + i);
  finish_run(values);
  dma[hifcr / 4] = 0;
  const DmaFlags flags = adc.on_dma_interrupt();
  EXPECT_TRUE(flags.complete);
  EXPECT_FALSE(flags.error);
  EXPECT_EQ(dma[hifcr / 4], stream_complete);
  EXPECT_EQ(reg(Adc::cr), 0x1001'0010U);  // ADSTP (ADSTART written 0: the ADC clears it once stopped)
  const std::span<const std::uint16_t> samples = adc.samples();
  EXPECT_EQ(std::vector<std::uint16_t>(samples.begin(), samples.end()), values);
  EXPECT_EQ(adc.dma_errors(), 0U);
}

TEST_F(AdcTest, StopsOnlyWhatStillConvertsAndCountsDmaErrors) {
  power_up();
  ASSERT_TRUE(adc.start(100));
  reg(Adc::cr) = Adc::regulator | Adc::enable;  // conversions already stopped
  stream_reg(stream_cr) &= ~1U;
  dma[hisr / 4] = stream_error;
  const DmaFlags flags = adc.on_dma_interrupt();
  EXPECT_FALSE(flags.complete);
  EXPECT_TRUE(flags.error);
  EXPECT_EQ(dma[hifcr / 4], stream_error);
  EXPECT_EQ(adc.dma_errors(), 1U);
  EXPECT_EQ(reg(Adc::cr), Adc::regulator | Adc::enable);  // no ADSTP without ADSTART (RM0436)

  dma[hisr / 4] = 1U << 11;  // stream 5's complete flag
  reg(Adc::cr) = Adc::regulator | Adc::start_conversions;
  const DmaFlags none = adc.on_dma_interrupt();
  EXPECT_FALSE(none.complete);
  EXPECT_FALSE(none.error);
  EXPECT_EQ(reg(Adc::cr), Adc::regulator | Adc::start_conversions);
}

}  // namespace
}  // namespace duet::stm32mp15
