#pragma once
// Copies bytes that interrupt handlers read with every interrupt masked, so that no handler sees half of them: the XCP
// slave's write_atomically for parameters that tasks of any priority read (duet/xcp/slave.hpp).

#include <cstdint>
#include <cstring>
#include <span>

#include "duet/cortex_m/interrupts.hpp"

namespace duet::cortex_m {

inline void copy_with_interrupts_masked(std::uint8_t* destination, std::span<const std::uint8_t> bytes) {
  const InterruptMask masked;
  std::memcpy(destination, bytes.data(), bytes.size());
}

}  // namespace duet::cortex_m
