#include "duet/cortex_m/interrupts.hpp"

#include "duet/cortex_m/registers.hpp"

namespace duet::cortex_m {
namespace {

// NVIC register banks: one bit per interrupt in 32-bit words, one byte of priority per interrupt.
constexpr std::uintptr_t set_enable = 0xE000E100;
constexpr std::uintptr_t clear_enable = 0xE000E180;
constexpr std::uintptr_t set_pending = 0xE000E200;
constexpr std::uintptr_t clear_pending = 0xE000E280;
constexpr std::uintptr_t priority = 0xE000E400;

volatile std::uint32_t& bank_word(std::uintptr_t bank, unsigned interrupt_number) {
  return register32(bank + 4U * (interrupt_number / 32U));
}

std::uint32_t bank_bit(unsigned interrupt_number) { return 1U << (interrupt_number % 32U); }

}  // namespace

// Writing a one sets or clears exactly that interrupt's bit, so these need no read-modify-write.
void enable_interrupt(unsigned interrupt_number) {
  bank_word(set_enable, interrupt_number) = bank_bit(interrupt_number);
}

void disable_interrupt(unsigned interrupt_number) {
  bank_word(clear_enable, interrupt_number) = bank_bit(interrupt_number);
  synchronize();  // so that the interrupt can no longer be taken once this returns
}

void set_interrupt_pending(unsigned interrupt_number) {
  bank_word(set_pending, interrupt_number) = bank_bit(interrupt_number);
}

void clear_interrupt_pending(unsigned interrupt_number) {
  bank_word(clear_pending, interrupt_number) = bank_bit(interrupt_number);
}

void set_priority_grouping(unsigned sub_priority_bits) {
  // AIRCR.PRIGROUP counts the sub-priority bits of the whole 8-bit field; the implemented bits are its top nibble,
  // so 3 + sub_priority_bits. Writes need the key in the upper half.
  constexpr std::uintptr_t application_interrupt_and_reset_control = 0xE000ED0C;
  constexpr std::uint32_t key = 0x05FAU << 16;
  const unsigned bits = sub_priority_bits < priority_bits ? sub_priority_bits : priority_bits - 1U;
  volatile std::uint32_t& aircr = register32(application_interrupt_and_reset_control);
  aircr = key | (aircr & ~(0xFFFFU << 16) & ~(0x7U << 8)) | ((8U - priority_bits + bits - 1U) << 8);
}

void set_interrupt_priority(unsigned interrupt_number, unsigned level) {
  const unsigned bounded = level < priority_levels ? level : priority_levels - 1U;
  register8(priority + interrupt_number) = static_cast<std::uint8_t>(bounded << (8U - priority_bits));
}

}  // namespace duet::cortex_m
