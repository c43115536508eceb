#pragma once
// The memory a slave may touch: regions the firmware declares, each at an XCP address (extension + 32-bit address)
// and backed by real memory. Nothing outside them can be read or written, whatever a request asks. On the 32-bit
// firmware a region's XCP address is usually its real address; on a 64-bit host it is an offset the A2L also uses.

#include <cstdint>
#include <span>
#include <string_view>

namespace duet::xcp {

enum class Access : std::uint8_t {
  read_only,   // measurement
  read_write,  // calibration
};

struct MemoryRegion {
  std::string_view name;
  std::uint8_t extension = 0;
  std::uint32_t address = 0;  // XCP address of the first byte
  std::uint32_t size = 0;
  std::uint8_t* memory = nullptr;
  Access access = Access::read_only;
};

// A calibration segment with two pages: page 0, the working page in RAM that XCP writes, and page 1, the reference
// page (the values the firmware was built with), read-only. The model reads its parameters through `ecu_page`, a
// pointer the slave sets to either page (SET_CAL_PAGE for the ECU); at its XCP address XCP sees the page it chose.
struct CalibrationSegment {
  std::string_view name;
  std::uint8_t extension = 0;
  std::uint32_t address = 0;
  std::uint32_t size = 0;
  std::uint8_t* working = nullptr;
  const std::uint8_t* reference = nullptr;
  const std::uint8_t* volatile* ecu_page = nullptr;  // optional: without it the model always reads the working page
};

inline constexpr std::uint8_t working_page = 0;
inline constexpr std::uint8_t reference_page = 1;

class MemoryMap {
 public:
  constexpr explicit MemoryMap(std::span<const MemoryRegion> regions) : regions_(regions) {}

  // The memory behind `size` bytes at (`extension`, `address`) if one region holds all of them and allows `access`
  // (read_write: writable); nullptr otherwise. Safe for any input: no overflow, no partial overlap.
  [[nodiscard]] constexpr std::uint8_t* find(std::uint8_t extension, std::uint32_t address, std::uint32_t size,
                                             Access access) const {
    for (const MemoryRegion& region : regions_) {
      if (region.extension != extension || address < region.address) continue;
      const std::uint32_t offset = address - region.address;
      if (offset > region.size || size > region.size - offset) continue;
      if (access == Access::read_write && region.access != Access::read_write) return nullptr;
      return region.memory + offset;
    }
    return nullptr;
  }

  [[nodiscard]] constexpr std::span<const MemoryRegion> regions() const { return regions_; }

 private:
  std::span<const MemoryRegion> regions_;
};

}  // namespace duet::xcp
