// A GPIO port against a fake register file: outputs, inputs with pulls and alternate functions change only their
// pin's fields, holding the GPIO hardware semaphore, and nothing when Linux holds it; outputs are driven through
// BSRR; inputs read IDR.
#include "duet/stm32mp15/gpio.hpp"

#include <gtest/gtest.h>

#include <array>

namespace duet::stm32mp15 {
namespace {

class GpioTest : public ::testing::Test {
 protected:
  GpioTest() { semaphore_answer() = Hsem::locked | Hsem::m4_core; }  // free: the read takes it for the M4
  std::uint32_t& reg(std::uint32_t offset) { return registers[offset / 4]; }
  std::uint32_t& semaphore_answer() { return semaphores[Hsem::read_lock_offset / 4 + semaphore::gpio]; }
  std::uint32_t& semaphore_release() { return semaphores[semaphore::gpio]; }
  std::array<std::uint32_t, 10> registers{};
  std::array<std::uint32_t, 64> semaphores{};
  GpioPort port{reinterpret_cast<std::uintptr_t>(registers.data()),
                Hsem{reinterpret_cast<std::uintptr_t>(semaphores.data())}};
};

TEST_F(GpioTest, TheRobotsPortsAreWhereTheManualSays) {
  EXPECT_EQ(gpio_base(0), 0x5000'2000U);  // GPIOA (MTR_STBY)
  EXPECT_EQ(gpio_base(4), 0x5000'6000U);  // GPIOE (PWM, CS, INT)
  EXPECT_EQ(gpio_base(7), 0x5000'9000U);  // GPIOH (ECHO0)
}

TEST_F(GpioTest, AnOutputChangesOnlyItsPinsFields) {
  reg(GpioPort::moder) = 0xFFFF'FFFF;  // every pin analog, as after reset
  reg(GpioPort::otyper) = 0xFFFF;
  EXPECT_TRUE(port.make_output(12));              // MTR_STBY, PA12
  EXPECT_EQ(semaphore_release(), Hsem::m4_core);  // released after
  EXPECT_EQ(reg(GpioPort::moder), 0xFDFF'FFFFU);
  EXPECT_EQ(reg(GpioPort::otyper), 0xEFFFU);
  port.set(12, true);
  EXPECT_EQ(reg(GpioPort::bsrr), 1U << 12);
  port.set(12, false);
  EXPECT_EQ(reg(GpioPort::bsrr), 1U << 28);
}

TEST_F(GpioTest, AnInputWithItsPullIsRead) {
  reg(GpioPort::moder) = 0xFFFF'FFFF;
  EXPECT_TRUE(port.make_input(8, Pull::down));  // MPU INT, PE8
  EXPECT_EQ(reg(GpioPort::moder), 0xFFFC'FFFFU);
  EXPECT_EQ(reg(GpioPort::pupdr), 2U << 16);
  reg(GpioPort::idr) = 1U << 8;
  EXPECT_TRUE(port.read(8));
  EXPECT_FALSE(port.read(7));
}

TEST_F(GpioTest, AlternateFunctionsGoToTheLowOrHighRegister) {
  EXPECT_TRUE(port.make_alternate(13, 1));  // e.g. a timer channel on AF1
  EXPECT_TRUE(port.make_alternate(7, 5));   // e.g. an SPI clock on AF5
  EXPECT_EQ(reg(GpioPort::afrh), 1U << 20);
  EXPECT_EQ(reg(GpioPort::afrl), 5U << 28);
  EXPECT_EQ(reg(GpioPort::moder), 2U << 26 | 2U << 14);
}

TEST_F(GpioTest, NothingChangesWhileLinuxHoldsTheSemaphore) {
  semaphore_answer() = Hsem::locked | 1U << 8U;  // a Cortex-A7's lock
  reg(GpioPort::moder) = 0xFFFF'FFFF;
  EXPECT_FALSE(port.make_output(12));
  EXPECT_FALSE(port.make_input(8, Pull::down));
  EXPECT_FALSE(port.make_alternate(7, 5));
  EXPECT_EQ(reg(GpioPort::moder), 0xFFFF'FFFFU);
  EXPECT_EQ(reg(GpioPort::pupdr), 0U);
  EXPECT_EQ(reg(GpioPort::afrl), 0U);
  EXPECT_EQ(semaphore_release(), 0U);  // Linux's semaphore left alone
}

}  // namespace
}  // namespace duet::stm32mp15
