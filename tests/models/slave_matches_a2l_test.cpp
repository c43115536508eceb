// One description: each example's generated XCP slave answers what its generated A2L says. The slave is asked with
// the standard's commands and its answers read at the standard's byte positions; the A2L is read by duet's reader.
// A master that plans DAQ from the A2L (as CANape and INCA do) then finds the slave it expects.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "balbot_xcp.hpp"
#include "block_tour_xcp.hpp"
#include "duet/support/text_file.hpp"
#include "duet/xcp/host/a2l.hpp"
#include "examples.hpp"
#include "pid_demo_xcp.hpp"
#include "step_time_xcp.hpp"
#include "thermostat_xcp.hpp"
#include "tilt_reference_xcp.hpp"
#include "transfer_test_xcp.hpp"

namespace duet::model {
namespace {

using Bytes = std::vector<std::uint8_t>;

// A generated slave of any model, asked one command at a time.
class GeneratedSlave {
 public:
  virtual ~GeneratedSlave() = default;
  virtual Bytes ask(const Bytes& command) = 0;
};

template <typename Slave>
class SlaveOf : public GeneratedSlave {
 public:
  Bytes ask(const Bytes& command) override {
    const std::span<const std::uint8_t> response = slave_.protocol().handle(command);
    return {response.begin(), response.end()};
  }

 private:
  Slave slave_{{}};
};

std::unique_ptr<GeneratedSlave> generated_slave(const std::string& model) {
  if (model == "step_time") return std::make_unique<SlaveOf<step_time::xcp::Slave>>();
  if (model == "transfer_test") return std::make_unique<SlaveOf<transfer_test::xcp::Slave>>();
  if (model == "pid_demo") return std::make_unique<SlaveOf<pid_demo::xcp::Slave>>();
  if (model == "thermostat") return std::make_unique<SlaveOf<thermostat::xcp::Slave>>();
  if (model == "balbot") return std::make_unique<SlaveOf<balbot::xcp::Slave>>();
  if (model == "block_tour") return std::make_unique<SlaveOf<block_tour::xcp::Slave>>();
  if (model == "tilt_reference") return std::make_unique<SlaveOf<tilt_reference::xcp::Slave>>();
  return nullptr;
}

std::uint16_t u16(const Bytes& bytes, std::size_t at) {  // Intel, as CONNECT announces
  return static_cast<std::uint16_t>(bytes.at(at) | (bytes.at(at + 1) << 8U));
}
std::uint32_t u32(const Bytes& bytes, std::size_t at) {
  return u16(bytes, at) | (static_cast<std::uint32_t>(u16(bytes, at + 2)) << 16U);
}

class SlaveMatchesA2l : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    slave = generated_slave(GetParam());
    ASSERT_NE(slave, nullptr);
    const std::string file = generated_folder(GetParam()) + "/" + GetParam() + ".a2l";
    auto text = read_text_file(file);
    ASSERT_TRUE(text.ok()) << text.error();
    a2l_text = text.value();
    auto read = xcp::host::read_a2l(a2l_text, file);
    ASSERT_TRUE(read.ok()) << read.error();
    a2l = read.value();
    const Bytes connected = slave->ask({0xFF, 0x00});
    ASSERT_EQ(connected.size(), 8U);
    connect = connected;
  }

  // A positive response, or the test fails.
  Bytes positive(const Bytes& command) {
    Bytes response = slave->ask(command);
    EXPECT_FALSE(response.empty());
    if (response.empty() || response[0] != 0xFF) {
      ADD_FAILURE() << "command 0x" << std::hex << int{command[0]} << " refused";
      return Bytes(16);
    }
    return response;
  }
  bool a2l_says(const std::string& text) const { return a2l_text.find(text) != std::string::npos; }

  std::unique_ptr<GeneratedSlave> slave;
  std::string a2l_text;
  xcp::host::A2lDescription a2l;
  Bytes connect;
};

TEST_P(SlaveMatchesA2l, Connect) {
  EXPECT_EQ(connect[0], 0xFF);
  EXPECT_EQ(connect[3], a2l.max_cto);
  EXPECT_EQ(u16(connect, 4), a2l.max_dto);
  EXPECT_EQ(connect[2] & 0x01U, 0U);                                      // Intel byte order ...
  EXPECT_TRUE(a2l_says("BYTE_ORDER_MSB_LAST ADDRESS_GRANULARITY_BYTE"));  // ... as the protocol layer says
  EXPECT_EQ(connect[2] & 0x06U, 0U);                                      // byte granularity
  EXPECT_NE(connect[1] & 0x04U, 0U);                                      // DAQ
}

TEST_P(SlaveMatchesA2l, CommunicationModes) {
  const Bytes info = positive({0xFB});
  EXPECT_NE(connect[2] & 0x80U, 0U);  // GET_COMM_MODE_INFO offered
  EXPECT_NE(info[2] & 0x01U, 0U);     // master block mode
  EXPECT_TRUE(
      a2l_says("COMMUNICATION_MODE_SUPPORTED BLOCK MASTER " + std::to_string(info[4]) + " " + std::to_string(info[5])));
}

TEST_P(SlaveMatchesA2l, DaqProcessor) {
  const Bytes info = positive({0xDA});
  EXPECT_EQ(u16(info, 2), a2l.max_daq_lists);
  EXPECT_EQ(u16(info, 4), a2l.events.size());
  EXPECT_EQ(info[6], 0U);          // MIN_DAQ: the A2L's DAQ DYNAMIC ... 0
  EXPECT_NE(info[1] & 0x01U, 0U);  // dynamic configuration
  EXPECT_TRUE(a2l_says("/begin DAQ DYNAMIC " + std::to_string(u16(info, 2)) + " " + std::to_string(u16(info, 4)) + " " +
                       std::to_string(info[6]) + " "));
  EXPECT_EQ((info[1] & 0x02U) != 0, a2l_says("PRESCALER_SUPPORTED"));
  EXPECT_EQ((info[1] & 0x10U) != 0, a2l_says("TIMESTAMP_SUPPORTED"));
  EXPECT_EQ(info[1] >> 6U, 2U);  // overload by event ...
  EXPECT_TRUE(a2l_says("OVERLOAD_INDICATION_EVENT"));
  EXPECT_EQ(info[7] >> 6U, static_cast<unsigned>(a2l.identification_field));
}

TEST_P(SlaveMatchesA2l, DaqResolution) {
  const Bytes info = positive({0xD9});
  EXPECT_EQ(info[1], 1U);  // byte granularity ...
  EXPECT_TRUE(a2l_says("GRANULARITY_ODT_ENTRY_SIZE_DAQ_BYTE"));
  EXPECT_EQ(info[2], a2l.max_odt_entry_size);
  EXPECT_EQ(info[5] & 0x07U, a2l.timestamp_size);
  EXPECT_EQ(info[5] >> 4U, a2l.timestamp_unit);
  EXPECT_EQ(u16(info, 6), a2l.timestamp_ticks);
}

TEST_P(SlaveMatchesA2l, EveryEvent) {
  ASSERT_FALSE(a2l.events.empty());
  for (const xcp::host::EventInfo& event : a2l.events) {
    const Bytes info = positive(
        {0xD7, 0x00, static_cast<std::uint8_t>(event.channel), static_cast<std::uint8_t>(event.channel >> 8U)});
    EXPECT_EQ(info[4], event.time_cycle) << event.name;
    EXPECT_EQ(info[5], event.time_unit) << event.name;
    EXPECT_EQ(info[6], event.priority) << event.name;
    const Bytes name = positive({0xF5, info[3]});  // the name, uploaded from where the MTA now points
    EXPECT_EQ(std::string(name.begin() + 1, name.end()), event.name);
  }
  EXPECT_EQ(slave->ask({0xD7, 0x00, static_cast<std::uint8_t>(a2l.events.size()), 0x00}), (Bytes{0xFE, 0x22}));
}

TEST_P(SlaveMatchesA2l, SegmentsAndPages) {
  std::vector<xcp::host::MemoryInfo> calibration;
  for (const xcp::host::MemoryInfo& memory : a2l.memory) {
    if (memory.calibration) calibration.push_back(memory);
  }
  const Bytes processor = positive({0xE9});
  ASSERT_EQ(processor[1], calibration.size());
  EXPECT_TRUE(a2l_says("/begin PAG " + std::to_string(calibration.size()) + " /end PAG"));
  for (std::size_t segment = 0; segment < calibration.size(); ++segment) {
    const auto number = static_cast<std::uint8_t>(segment);
    EXPECT_EQ(u32(positive({0xE8, 0x00, number, 0x00, 0x00}), 4), calibration[segment].address);
    EXPECT_EQ(u32(positive({0xE8, 0x00, number, 0x01, 0x00}), 4), calibration[segment].size);
    const Bytes standard = positive({0xE8, 0x01, number, 0x00, 0x00});
    EXPECT_EQ(standard[1], 2U);  // two pages ...
    EXPECT_EQ(standard[2], calibration[segment].extension);
    EXPECT_TRUE(
        a2l_says("/begin SEGMENT " + std::to_string(segment) + " 2 " + std::to_string(calibration[segment].extension)));
    // The working page: the ECU and XCP read it, XCP writes it; the reference page XCP may not write.
    EXPECT_EQ(positive({0xE7, 0x00, number, 0x00})[1] & 0x30U, 0x30U);
    EXPECT_EQ(positive({0xE7, 0x00, number, 0x01})[1] & 0x30U, 0x00U);
    EXPECT_TRUE(a2l_says("/begin PAGE 1 ECU_ACCESS_DONT_CARE XCP_READ_ACCESS_DONT_CARE XCP_WRITE_ACCESS_NOT_ALLOWED"));
  }
  EXPECT_EQ(slave->ask({0xE8, 0x00, static_cast<std::uint8_t>(calibration.size()), 0x00, 0x00}), (Bytes{0xFE, 0x28}));
}

TEST_P(SlaveMatchesA2l, Epk) {
  ASSERT_FALSE(a2l.epk.empty());
  ASSERT_LT(a2l.epk.size(), 248U);
  const std::uint32_t at = a2l.epk_address;
  const Bytes uploaded = positive({0xF4, static_cast<std::uint8_t>(a2l.epk.size()), 0x00, 0x00,
                                   static_cast<std::uint8_t>(at), static_cast<std::uint8_t>(at >> 8U),
                                   static_cast<std::uint8_t>(at >> 16U), static_cast<std::uint8_t>(at >> 24U)});
  EXPECT_EQ(std::string(uploaded.begin() + 1, uploaded.end()), a2l.epk);
  const Bytes id = positive({0xFA, 0x05});  // GET_ID EPK: its length, to upload through the MTA (mode 0)
  EXPECT_EQ(id[1], 0x00);
  ASSERT_EQ(u32(id, 4), a2l.epk.size());
  const Bytes epk = positive({0xF5, static_cast<std::uint8_t>(a2l.epk.size())});
  EXPECT_EQ(std::string(epk.begin() + 1, epk.end()), a2l.epk);
}

TEST_P(SlaveMatchesA2l, Checksum) {
  for (const xcp::host::MemoryInfo& memory : a2l.memory) {
    if (!memory.calibration) continue;
    const std::uint32_t at = memory.address;
    positive({0xF6, 0x00, 0x00, memory.extension, static_cast<std::uint8_t>(at), static_cast<std::uint8_t>(at >> 8U),
              static_cast<std::uint8_t>(at >> 16U), static_cast<std::uint8_t>(at >> 24U)});
    const std::uint32_t size = memory.size & ~1U;  // a whole number of the largest checksum element
    const Bytes checksum =
        positive({0xF3, 0x00, 0x00, 0x00, static_cast<std::uint8_t>(size), static_cast<std::uint8_t>(size >> 8U),
                  static_cast<std::uint8_t>(size >> 16U), static_cast<std::uint8_t>(size >> 24U)});
    EXPECT_EQ(checksum[1], static_cast<std::uint8_t>(a2l.checksum_type));
  }
}

INSTANTIATE_TEST_SUITE_P(Examples, SlaveMatchesA2l, ::testing::ValuesIn(example_models),
                         [](const auto& test) { return test.param; });

}  // namespace
}  // namespace duet::model
