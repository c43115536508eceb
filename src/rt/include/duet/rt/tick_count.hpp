#pragma once
// The executive's 64-bit count of base ticks. Only the base-tick interrupt writes it; the base rate itself, slower
// rates, interrupt tasks of less urgent groups and main read it. A 32-bit core reads 64 bits as two words: the
// Cortex-M4 with two LDRs or an LDRD, which the architecture does not promise to be one access. A base tick between
// the two words would pair a new low word with the old high word: when the low word wraps (2^32 ticks, 49.7 days at
// 1 kHz) the reader would see the count 2^32 ticks behind, or ahead. So the count is kept as two 32-bit atomic words,
// each read whole, and the reader reads high, low and high again, and starts over if the high word moved.
//
// A reader more urgent than the base tick could still see an increment half made (it cannot wait for the writer it
// preempts): read the count from the base tick or less urgent contexts only.

#include <atomic>
#include <cstdint>

namespace duet::rt {

// Each word is then one plain load or store (LDR, STR on the Cortex-M4): never torn itself.
static_assert(std::atomic<std::uint32_t>::is_always_lock_free);

// `Word` is std::atomic<std::uint32_t> in the executive; tests put in a word that lets an "interrupt" run between
// the reader's loads.
template <typename Word = std::atomic<std::uint32_t>>
class TickCount {
 public:
  explicit TickCount(std::uint64_t start = 0)
      : low_(static_cast<std::uint32_t>(start)), high_(static_cast<std::uint32_t>(start >> word_bits)) {}

  // In the base-tick interrupt only. Less urgent readers cannot run in between, so the order of the stores is free.
  // Returns the new low word: what the writer compares first.
  std::uint32_t increment() {
    const std::uint32_t low = low_.load(std::memory_order_relaxed) + 1U;
    if (low == 0) high_.store(high_.load(std::memory_order_relaxed) + 1U, std::memory_order_relaxed);
    low_.store(low, std::memory_order_relaxed);
    return low;
  }

  // In the base-tick interrupt only: no one else writes the words, so the writer reads its own count whole.
  [[nodiscard]] std::uint64_t read_in_writer() const {
    return (std::uint64_t{high_.load(std::memory_order_relaxed)} << word_bits) | low_.load(std::memory_order_relaxed);
  }

  // From the base tick or a less urgent context: the count as it was before or after any increment, never a mix.
  [[nodiscard]] std::uint64_t read() const {
    std::uint32_t high = high_.load(std::memory_order_relaxed);
    while (true) {
      // Compiler barriers only: the interrupt runs on this core, so keeping the three loads in order is all it needs.
      std::atomic_signal_fence(std::memory_order_acq_rel);
      const std::uint32_t low = low_.load(std::memory_order_relaxed);
      std::atomic_signal_fence(std::memory_order_acq_rel);
      const std::uint32_t high_again = high_.load(std::memory_order_relaxed);
      if (high_again == high) return (std::uint64_t{high} << word_bits) | low;
      high = high_again;  // a base tick carried into the high word meanwhile: the low word may be from either side
    }
  }

 private:
  static constexpr int word_bits = 32;

  Word low_;
  Word high_;
};

}  // namespace duet::rt
