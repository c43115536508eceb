#pragma once
// How the master lays DAQ lists out for a slave: dynamic list numbers from MIN_DAQ, entries split to the slave's
// largest entry and granularity, ODTs filled up to MAX_DTO after the identification field (and in a sample's first
// ODT the timestamp), within the ODT numbers the identification field allows. What the slave cannot do is refused
// with a message that names the limit.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "duet/support/result.hpp"
#include "duet/xcp/host/daq_setup.hpp"

namespace duet::xcp::host {

struct PlannedOdt {
  std::vector<DaqEntry> entries;
  std::size_t payload = 0;  // the entries' bytes
};

struct PlannedList {
  std::uint16_t number = 0;  // the slave's DAQ list number
  std::uint16_t event = 0;
  std::uint8_t prescaler = 1;
  std::vector<PlannedOdt> odts;
};

struct DaqPlan {
  std::vector<PlannedList> lists;
  bool timestamps = false;  // each sample's first packet carries one
};

Result<DaqPlan> plan_daq(const std::vector<DaqListSetup>& lists, const DaqProcessor& processor, std::uint16_t max_dto);

}  // namespace duet::xcp::host
