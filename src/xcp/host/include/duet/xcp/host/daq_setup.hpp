#pragma once
// DAQ from the master's side: what to sample (lists of entries on events) and how the slave samples
// (GET_DAQ_PROCESSOR_INFO and GET_DAQ_RESOLUTION_INFO), which decides how the master plans ODTs and reads packets.

#include <cstdint>
#include <vector>

#include "duet/xcp/daq.hpp"

namespace duet::xcp::host {

struct DaqEntry {
  std::uint8_t extension = 0;
  std::uint32_t address = 0;
  std::uint8_t size = 0;
};

// One DAQ list: what to sample, on which event, how often.
struct DaqListSetup {
  std::uint16_t event = 0;
  std::uint8_t prescaler = 1;
  std::vector<DaqEntry> entries;
};

// How the slave says it dropped samples (DAQ_PROPERTIES bits 6-7).
enum class OverloadIndication : std::uint8_t { none = 0, pid_msb = 1, event = 2 };

// What GET_DAQ_PROCESSOR_INFO and GET_DAQ_RESOLUTION_INFO said.
struct DaqProcessor {
  std::uint8_t properties = 0;          // DAQ_PROPERTIES
  std::uint16_t max_daq = 0;            // DAQ lists in all, the predefined ones included
  std::uint16_t max_event_channel = 0;  // 0: the slave does not say
  std::uint8_t min_daq = 0;             // predefined lists; the dynamic ones are numbered from here
  IdentificationField identification = IdentificationField::absolute;  // DAQ_KEY_BYTE bits 6-7
  std::uint8_t address_extension = 0;  // DAQ_KEY_BYTE bits 4-5: 0 free, 1 one per ODT, 3 one per DAQ list
  std::uint8_t granularity = 1;        // GRANULARITY_ODT_ENTRY_SIZE_DAQ: entry sizes are multiples of it
  std::uint8_t max_entry_size = 0xFF;  // MAX_ODT_ENTRY_SIZE_DAQ
  std::uint8_t timestamp_size = 0;     // TIMESTAMP_MODE bits 0-2: 0, 1, 2 or 4 bytes
  bool timestamp_fixed = false;        // TIMESTAMP_MODE bit 3: every sample carries one, asked for or not
  std::uint8_t timestamp_unit = 3;     // TIMESTAMP_MODE bits 4-7: 0 = 1 ns ... 9 = 1 s
  std::uint16_t timestamp_ticks = 1;   // TIMESTAMP_TICKS: units per tick

  [[nodiscard]] bool dynamic() const { return (properties & 0x01U) != 0; }
  [[nodiscard]] bool prescaler() const { return (properties & 0x02U) != 0; }
  // Samples carry timestamps: the slave offers them (or always sends them) in a size it names.
  [[nodiscard]] bool timestamps() const {
    return ((properties & 0x10U) != 0 || timestamp_fixed) && timestamp_size != 0;
  }
  [[nodiscard]] OverloadIndication overload_indication() const {
    return static_cast<OverloadIndication>((properties >> 6U) & 0x03U);
  }
  // Seconds per timestamp tick; 0 without timestamps.
  [[nodiscard]] double seconds_per_tick() const;
};

}  // namespace duet::xcp::host
