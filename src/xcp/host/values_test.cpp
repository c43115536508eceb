#include "duet/xcp/host/values.hpp"

#include <gtest/gtest.h>

namespace duet::xcp::host {
namespace {

TEST(Values, DecodeThroughTypeAndConversion) {
  const Variable battery{
      .name = "battery", .type = DataType::uint16, .minimum = 0, .maximum = 20, .conversion = {0.01, 1.0}};
  EXPECT_EQ(decode(battery, std::vector<std::uint8_t>{0xE8, 0x03, 0x00, 0x00}), (std::vector<double>{11.0, 1.0}));
  const Variable angle{.name = "theta", .type = DataType::float32, .minimum = -90, .maximum = 90};
  EXPECT_EQ(decode(angle, std::vector<std::uint8_t>{0x00, 0x00, 0xC0, 0xBF}), std::vector<double>{-1.5});
  const Variable speed{.name = "speed", .type = DataType::int16, .minimum = -500, .maximum = 500};
  EXPECT_EQ(decode(speed, std::vector<std::uint8_t>{0xFE, 0xFF}), std::vector<double>{-2});
}

TEST(Values, EncodeRefusesWhatIsOutsideTheLimitsOrTheType) {
  const Variable battery{
      .name = "battery", .type = DataType::uint16, .unit = "V", .minimum = 0, .maximum = 20, .conversion = {0.01, 1.0}};
  EXPECT_EQ(encode(battery, 11.0).value(), (std::vector<std::uint8_t>{0xE8, 0x03}));
  EXPECT_EQ(encode(battery, 25.0).error(), "battery: 25 is outside 0 .. 20 V");
  const Variable tiny{.name = "tiny", .type = DataType::int8, .minimum = -1000, .maximum = 1000};
  EXPECT_EQ(encode(tiny, 200).error(), "tiny: the raw value 200.000000 does not fit SBYTE");
  const Variable gain{.name = "P", .type = DataType::float32, .minimum = 0, .maximum = 100};
  EXPECT_EQ(encode(gain, 2.5).value(), (std::vector<std::uint8_t>{0x00, 0x00, 0x20, 0x40}));
}

}  // namespace
}  // namespace duet::xcp::host
