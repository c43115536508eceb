// The tick count read while a base tick interrupts the reader between its loads: it must never be seen torn.
#include "duet/rt/tick_count.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <utility>

namespace duet::rt {
namespace {

// The simulated base-tick interrupt: runs just before the `loads_until`-th load of any word from now.
struct PendingInterrupt {
  int loads_until = 0;
  std::function<void()> handler;
};
PendingInterrupt pending_interrupt;

// A word like std::atomic<std::uint32_t> whose loads let the pending interrupt in first, as the core would between
// two instructions.
class InterruptibleWord {
 public:
  explicit InterruptibleWord(std::uint32_t value) : value_(value) {}

  std::uint32_t load(std::memory_order /*order*/) const {
    if (pending_interrupt.handler && --pending_interrupt.loads_until == 0) {
      const std::function<void()> handler = std::move(pending_interrupt.handler);
      pending_interrupt.handler = nullptr;  // the handler's own loads run without another interrupt
      handler();
    }
    return value_;
  }
  void store(std::uint32_t value, std::memory_order /*order*/) { value_ = value; }

 private:
  std::uint32_t value_;
};

constexpr std::uint64_t before_carry = 0xffff'ffffU;  // the next tick carries into the high word
constexpr std::uint64_t after_carry = before_carry + 1;

// Reads a count of `before_carry` while a base tick runs just before the reader's load number `load`.
std::uint64_t read_with_tick_before_load(int load) {
  TickCount<InterruptibleWord> count{before_carry};
  pending_interrupt = {load, [&count] { count.increment(); }};
  const std::uint64_t seen = count.read();
  EXPECT_FALSE(pending_interrupt.handler) << "the reader made fewer than " << load << " loads";
  EXPECT_EQ(count.read(), after_carry) << "the tick was not counted";
  return seen;
}

TEST(TickCount, ATickBetweenTheHalvesIsNotSeenTorn) {
  // The reader loads high, low, high. A tick before the low word's load is the case a plain two-word read gets
  // wrong: old high word 0 with new low word 0, the count 2^32 ticks behind.
  EXPECT_EQ(read_with_tick_before_load(2), after_carry);
}

TEST(TickCount, ATickAnywhereInTheReadGivesTheCountBeforeOrAfterIt) {
  for (int load = 1; load <= 3; ++load) {
    const std::uint64_t seen = read_with_tick_before_load(load);
    EXPECT_TRUE(seen == before_carry || seen == after_carry) << "tick before load " << load << ": seen " << seen;
  }
}

TEST(TickCount, CountsAcrossTheWordBoundary) {
  TickCount<> count{before_carry - 1};
  count.increment();
  EXPECT_EQ(count.read(), before_carry);
  count.increment();
  EXPECT_EQ(count.read(), after_carry);
  count.increment();
  EXPECT_EQ(count.read(), after_carry + 1);
}

}  // namespace
}  // namespace duet::rt
