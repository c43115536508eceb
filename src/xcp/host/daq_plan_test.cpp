// How the master lays DAQ lists out for a slave's limits, and what it refuses.

#include "daq_plan.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace duet::xcp::host {
namespace {

DaqProcessor dynamic_processor() {
  DaqProcessor processor;
  processor.properties = 0x01 | 0x02 | 0x10;  // dynamic, prescaler, timestamps
  processor.max_daq = 4;
  processor.max_event_channel = 2;
  processor.timestamp_size = 4;
  return processor;
}

std::string refusal(const Result<DaqPlan>& plan) { return plan.ok() ? std::string{"(planned)"} : plan.error(); }

std::vector<std::uint8_t> sizes(const PlannedOdt& odt) {
  std::vector<std::uint8_t> result;
  for (const DaqEntry& entry : odt.entries) result.push_back(entry.size);
  return result;
}

TEST(DaqPlan, FillsPacketsUpToMaxDtoAfterTheIdentificationAndTheFirstTimestamp) {
  DaqProcessor processor = dynamic_processor();
  processor.identification = IdentificationField::relative_word_aligned;
  // MAX_DTO 16: the first packet has 16 - 4 - 4 = 8 bytes for entries, the others 12.
  const auto plan =
      plan_daq({{.event = 1, .prescaler = 1, .entries = {{0, 0x100, 4}, {0, 0x104, 6}, {0, 0x10A, 4}}}}, processor, 16);
  ASSERT_TRUE(plan.ok()) << plan.error();
  ASSERT_EQ(plan.value().lists.size(), 1U);
  const PlannedList& list = plan.value().lists[0];
  ASSERT_EQ(list.odts.size(), 2U);
  EXPECT_EQ(sizes(list.odts[0]), (std::vector<std::uint8_t>{4, 4}));  // the 6-byte entry split at the packet's end
  EXPECT_EQ(sizes(list.odts[1]), (std::vector<std::uint8_t>{2, 4}));
  EXPECT_EQ(list.odts[1].entries[0].address, 0x108U);
  EXPECT_EQ(list.odts[0].payload, 8U);
  EXPECT_TRUE(plan.value().timestamps);
}

TEST(DaqPlan, SplitsEntriesToTheLargestAndGranularityTheSlaveTakes) {
  DaqProcessor processor = dynamic_processor();
  processor.granularity = 2;
  processor.max_entry_size = 5;  // pieces of 4: multiples of 2
  const auto plan = plan_daq({{.event = 0, .prescaler = 1, .entries = {{1, 0x200, 10}}}}, processor, 64);
  ASSERT_TRUE(plan.ok()) << plan.error();
  const PlannedOdt& odt = plan.value().lists[0].odts[0];
  EXPECT_EQ(sizes(odt), (std::vector<std::uint8_t>{4, 4, 2}));
  EXPECT_EQ(odt.entries[2].address, 0x208U);
  EXPECT_EQ(odt.entries[2].extension, 1U);
  EXPECT_EQ(refusal(plan_daq({{.event = 0, .prescaler = 1, .entries = {{0, 0x300, 3}}}}, processor, 64)),
            "the entry at 0x300 has 3 bytes, not a multiple of the slave's granularity of 2 "
            "(GRANULARITY_ODT_ENTRY_SIZE_DAQ)");
}

TEST(DaqPlan, NumbersDynamicListsFromMinDaqWithinMaxDaq) {
  DaqProcessor processor = dynamic_processor();
  processor.min_daq = 2;
  const DaqListSetup list{.event = 0, .prescaler = 1, .entries = {{0, 0x100, 1}}};
  const auto plan = plan_daq({list, list}, processor, 8);
  ASSERT_TRUE(plan.ok()) << plan.error();
  EXPECT_EQ(plan.value().lists[0].number, 2U);
  EXPECT_EQ(plan.value().lists[1].number, 3U);
  EXPECT_EQ(refusal(plan_daq({list, list, list}, processor, 8)),
            "3 DAQ lists asked for; the slave has room for 2 (MAX_DAQ 4, MIN_DAQ 2)");
}

TEST(DaqPlan, KeepsOdtNumbersWithinTheIdentificationField) {
  DaqProcessor processor = dynamic_processor();
  processor.timestamp_size = 0;
  // MAX_DTO 8 and a 1-byte PID: 7 bytes per packet; 253 packets for 1771 bytes is one more than 0xFC.
  std::vector<DaqEntry> entries;
  for (std::uint32_t entry = 0; entry < 253; ++entry) entries.push_back({0, 0x1000 + 7 * entry, 7});
  const std::vector<DaqListSetup> lists{{.event = 0, .prescaler = 1, .entries = entries}};
  EXPECT_EQ(refusal(plan_daq(lists, processor, 8)),
            "the DAQ lists need 253 ODTs; the slave's identification field numbers at most 252");
  processor.properties |= 0x40;  // overload in the PID's MSB: 7 bits for ODT numbers
  entries.resize(125);
  EXPECT_EQ(refusal(plan_daq({{.event = 0, .prescaler = 1, .entries = entries}}, processor, 8)),
            "the DAQ lists need 125 ODTs; the slave's identification field numbers at most 124");
  processor.properties = 0x01;
  processor.identification = IdentificationField::relative_byte;  // 6 bytes per packet, 0xFC ODTs per list
  entries.assign(253, {0, 0x1000, 6});
  EXPECT_EQ(refusal(plan_daq({{.event = 0, .prescaler = 1, .entries = entries}}, processor, 8)),
            "DAQ list 0 needs 253 ODTs; the slave's identification field numbers at most 252");
}

TEST(DaqPlan, KeepsOneAddressExtensionPerOdtOrListWhenTheSlaveAsks) {
  DaqProcessor processor = dynamic_processor();
  processor.address_extension = 1;  // one per ODT
  const DaqListSetup mixed{.event = 0, .prescaler = 1, .entries = {{0, 0x100, 2}, {1, 0x100, 2}}};
  const auto plan = plan_daq({mixed}, processor, 64);
  ASSERT_TRUE(plan.ok()) << plan.error();
  EXPECT_EQ(plan.value().lists[0].odts.size(), 2U);
  processor.address_extension = 3;  // one per DAQ list
  EXPECT_EQ(refusal(plan_daq({mixed}, processor, 64)),
            "DAQ list 0 mixes address extensions, which the slave allows only one of per DAQ list");
}

TEST(DaqPlan, RefusesWhatTheSlaveCannotDo) {
  const DaqListSetup list{.event = 0, .prescaler = 1, .entries = {{0, 0x100, 4}}};
  DaqProcessor processor = dynamic_processor();
  processor.properties = 0x10;
  EXPECT_EQ(refusal(plan_daq({list}, processor, 64)),
            "the slave's DAQ lists are predefined (static); this master configures dynamic DAQ lists only");
  processor = dynamic_processor();
  processor.properties = 0x01;
  EXPECT_EQ(refusal(plan_daq({{.event = 0, .prescaler = 2, .entries = list.entries}}, processor, 64)),
            "the slave offers no prescaler");
  EXPECT_FALSE(plan_daq({list}, processor, 64).value().timestamps);  // none offered: none asked for
  processor = dynamic_processor();
  EXPECT_EQ(refusal(plan_daq({{.event = 2, .prescaler = 1, .entries = list.entries}}, processor, 64)),
            "event 2: the slave has 2 event channels");
  EXPECT_EQ(refusal(plan_daq({{.event = 0, .prescaler = 1, .entries = {}}}, processor, 64)),
            "DAQ list 0 has no entries");
  EXPECT_EQ(refusal(plan_daq({list}, processor, 5)),
            "MAX_DTO 5 leaves no room for an entry after the 5-byte packet header");
  processor.timestamp_unit = 12;
  EXPECT_EQ(refusal(plan_daq({list}, processor, 64)),
            "the slave's timestamp unit code 12 is none of 0 (1 ns) ... 9 (1 s)");
}

TEST(DaqProcessor, TicksAreTheUnitTimesTheTicksPerTimestamp) {
  DaqProcessor processor = dynamic_processor();
  processor.timestamp_unit = 4;  // 10 us
  processor.timestamp_ticks = 5;
  EXPECT_DOUBLE_EQ(processor.seconds_per_tick(), 50e-6);
  processor.properties = 0x01;
  EXPECT_EQ(processor.seconds_per_tick(), 0.0);  // no timestamps
  processor.timestamp_fixed = true;              // sent anyway
  EXPECT_DOUBLE_EQ(processor.seconds_per_tick(), 50e-6);
}

}  // namespace
}  // namespace duet::xcp::host
