#include "daq_plan.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "duet/xcp/host/a2l.hpp"

namespace duet::xcp::host {
namespace {

constexpr std::size_t max_odt_number = 0xFC;           // identification bytes below RES/ERR/EV/SERV
constexpr std::size_t max_odt_number_with_msb = 0x7C;  // the PID's MSB flags an overload
constexpr std::size_t max_entries_per_odt = 0xFF;      // ALLOC_ODT_ENTRY's count is a byte
constexpr unsigned last_timestamp_unit = 9;            // 1 s

std::string hex(std::uint32_t address) {
  char text[16];
  std::snprintf(text, sizeof(text), "0x%X", address);
  return text;
}

// Lays one list's entries out in ODTs: each ODT filled up to MAX_DTO, entries split where an ODT ends and into
// pieces the slave takes (its largest entry, multiples of its granularity).
Result<std::vector<PlannedOdt>> plan_odts(std::size_t list, const DaqListSetup& setup, const DaqProcessor& processor,
                                          std::size_t max_dto, bool timestamps) {
  const std::size_t header = identification_size(processor.identification);
  const std::size_t first_header = header + (timestamps ? processor.timestamp_size : 0U);
  const std::size_t granularity = processor.granularity;
  const std::size_t largest_piece = processor.max_entry_size / granularity * granularity;
  if (first_header + granularity > max_dto) {
    return Failure{"MAX_DTO " + std::to_string(max_dto) + " leaves no room for an entry after the " +
                   std::to_string(first_header) + "-byte packet header"};
  }
  std::vector<PlannedOdt> odts(1);
  std::size_t used = first_header;
  for (const DaqEntry& entry : setup.entries) {
    if (entry.size == 0) return Failure{"DAQ list " + std::to_string(list) + ": an entry of 0 bytes"};
    if (entry.size % granularity != 0) {
      return Failure{"the entry at " + hex(entry.address) + " has " + std::to_string(entry.size) +
                     " bytes, not a multiple of the slave's granularity of " + std::to_string(granularity) +
                     " (GRANULARITY_ODT_ENTRY_SIZE_DAQ)"};
    }
    if (processor.address_extension == 3 && entry.extension != setup.entries.front().extension) {
      return Failure{"DAQ list " + std::to_string(list) +
                     " mixes address extensions, which the slave allows only one of per DAQ list"};
    }
    std::size_t done = 0;
    while (done < entry.size) {
      const PlannedOdt& current = odts.back();
      const bool other_extension = processor.address_extension == 1 && !current.entries.empty() &&
                                   current.entries.front().extension != entry.extension;
      const std::size_t room = (max_dto - used) / granularity * granularity;
      if (room == 0 || current.entries.size() == max_entries_per_odt || other_extension) {
        odts.emplace_back();
        used = header;
        continue;
      }
      const std::size_t piece = std::min({entry.size - done, room, largest_piece});
      odts.back().entries.push_back(
          {entry.extension, static_cast<std::uint32_t>(entry.address + done), static_cast<std::uint8_t>(piece)});
      odts.back().payload += piece;
      used += piece;
      done += piece;
    }
  }
  return odts;
}

}  // namespace

double DaqProcessor::seconds_per_tick() const {
  return timestamps() ? seconds_per_unit(timestamp_unit) * timestamp_ticks : 0.0;
}

Result<DaqPlan> plan_daq(const std::vector<DaqListSetup>& lists, const DaqProcessor& processor, std::uint16_t max_dto) {
  if (!processor.dynamic()) {
    return Failure{"the slave's DAQ lists are predefined (static); this master configures dynamic DAQ lists only"};
  }
  const std::size_t room = processor.max_daq > processor.min_daq ? processor.max_daq - processor.min_daq : 0U;
  if (lists.size() > room) {
    return Failure{std::to_string(lists.size()) + " DAQ lists asked for; the slave has room for " +
                   std::to_string(room) + " (MAX_DAQ " + std::to_string(processor.max_daq) + ", MIN_DAQ " +
                   std::to_string(processor.min_daq) + ")"};
  }
  if (processor.identification == IdentificationField::relative_byte && processor.min_daq + lists.size() > 0x100) {
    return Failure{"DAQ list numbers above 255 do not fit the slave's one-byte identification field"};
  }
  if (processor.granularity == 0 || processor.max_entry_size < processor.granularity) {
    return Failure{"the slave's entry size limits (granularity " + std::to_string(processor.granularity) +
                   ", largest " + std::to_string(processor.max_entry_size) + ") allow no entry"};
  }
  DaqPlan plan{.lists = {}, .timestamps = processor.timestamps()};
  if (plan.timestamps && processor.timestamp_unit > last_timestamp_unit) {
    return Failure{"the slave's timestamp unit code " + std::to_string(processor.timestamp_unit) +
                   " is none of 0 (1 ns) ... 9 (1 s)"};
  }
  const std::size_t odt_numbers =
      processor.overload_indication() == OverloadIndication::pid_msb ? max_odt_number_with_msb : max_odt_number;
  std::size_t absolute_odts = 0;
  for (std::size_t index = 0; index < lists.size(); ++index) {
    const DaqListSetup& setup = lists[index];
    const std::string name = "DAQ list " + std::to_string(index);
    if (setup.entries.empty()) return Failure{name + " has no entries"};
    if (setup.prescaler == 0) return Failure{name + ": a prescaler of 0"};
    if (setup.prescaler > 1 && !processor.prescaler()) return Failure{"the slave offers no prescaler"};
    if (processor.max_event_channel != 0 && setup.event >= processor.max_event_channel) {
      return Failure{"event " + std::to_string(setup.event) + ": the slave has " +
                     std::to_string(processor.max_event_channel) + " event channels"};
    }
    auto odts = plan_odts(index, setup, processor, max_dto, plan.timestamps);
    if (!odts) return Failure{odts.error()};
    absolute_odts += odts.value().size();
    const bool absolute = processor.identification == IdentificationField::absolute;
    if ((absolute ? absolute_odts : odts.value().size()) > odt_numbers) {
      return Failure{(absolute ? "the DAQ lists need " + std::to_string(absolute_odts)
                               : name + " needs " + std::to_string(odts.value().size())) +
                     " ODTs; the slave's identification field numbers at most " + std::to_string(odt_numbers)};
    }
    plan.lists.push_back(
        {static_cast<std::uint16_t>(processor.min_daq + index), setup.event, setup.prescaler, std::move(odts).value()});
  }
  return plan;
}

}  // namespace duet::xcp::host
