#include "xml.hpp"

#include <gtest/gtest.h>

#include <string>

namespace duet::plot {
namespace {

TEST(PlotXml, EscapesTheSpecialCharacters) {
  EXPECT_EQ(escaped(R"(a<b & "c" > 'd')"), "a&lt;b &amp; &quot;c&quot; &gt; &apos;d&apos;");
  EXPECT_EQ(escaped("x[0]"), "x[0]");
}

TEST(PlotXml, KeepsUtf8AndReplacesWhatXmlCannotHold) {
  EXPECT_EQ(escaped("\xCF\x89 rad/s \xC2\xB0"
                    "C"),
            "\xCF\x89 rad/s \xC2\xB0"
            "C");  // omega, degree sign
  EXPECT_EQ(escaped("a\x01"
                    "b"),
            "a?b");  // a control character
  EXPECT_EQ(escaped("\xFF"
                    "a\xC3"),
            "\xEF\xBF\xBD"
            "a\xEF\xBF\xBD");                                  // not UTF-8; cut short
  EXPECT_EQ(escaped("\xC0\xAF"), "\xEF\xBF\xBD\xEF\xBF\xBD");  // an overlong '/'
  EXPECT_EQ(escaped("\xEF\xBF\xBF"), "\xEF\xBF\xBD");          // U+FFFF
}

TEST(PlotXml, CoordinatesAreShort) {
  const auto text = [](double value) {
    std::string out;
    append_coordinate(out, value);
    return out;
  };
  EXPECT_EQ(text(12), "12");
  EXPECT_EQ(text(12.25), "12.3");
  EXPECT_EQ(text(0.30000000000000004), "0.3");
  EXPECT_EQ(text(-0.01), "0");
  EXPECT_EQ(text(-3.5), "-3.5");
}

}  // namespace
}  // namespace duet::plot
