#include "duet/base/text_buffer.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

namespace duet {
namespace {

TEST(TextBuffer, AppendsTextAndDecimalIntegers) {
  TextBuffer<64> text;
  text.append("ticks: ").append(std::uint32_t{1000}).append(", error ").append(-42).append('\n');
  EXPECT_EQ(text.view(), "ticks: 1000, error -42\n");
  EXPECT_FALSE(text.truncated());
}

TEST(TextBuffer, WritesExtremeIntegersExactly) {
  TextBuffer<64> text;
  text.append(std::numeric_limits<std::int64_t>::min()).append(' ').append(std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(text.view(), "-9223372036854775808 18446744073709551615");
  text.clear();
  text.append(std::int8_t{-128}).append(' ').append(0).append(' ').append(true);
  EXPECT_EQ(text.view(), "-128 0 true");
}

TEST(TextBuffer, WritesFixedWidthHexadecimal) {
  TextBuffer<32> text;
  text.append_hex(0x2000'0fc0U).append(' ').append_hex(0xab, 2).append(' ').append_hex(0x1, 4);
  EXPECT_EQ(text.view(), "0x20000fc0 0xab 0x0001");
}

TEST(TextBuffer, CutsOffWhatDoesNotFitAndSaysSo) {
  TextBuffer<5> text;
  text.append("abc").append(12345);
  EXPECT_EQ(text.view(), "abc12");
  EXPECT_TRUE(text.truncated());
  text.clear();
  EXPECT_EQ(text.view(), "");
  EXPECT_FALSE(text.truncated());
}

}  // namespace
}  // namespace duet
