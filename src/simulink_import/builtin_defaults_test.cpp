// Defaults as files of each era would carry them (docs/IMPORT.md, "Defaults"): the values that changed in R2019b
// and R2020a answer by the release that saved the file.
#include "duet/simulink_import/builtin_defaults.hpp"

#include <gtest/gtest.h>

namespace duet::simulink_import {
namespace {

TEST(BuiltinDefaults, AnswerByTheReleaseThatSavedTheFile) {
  EXPECT_EQ(builtin_default("Gain", "Gain", "R2014a"), "1");
  EXPECT_EQ(builtin_default("Gain", "SaturateOnIntegerOverflow", "R2019b"), "on");
  EXPECT_EQ(builtin_default("Gain", "SaturateOnIntegerOverflow", "R2020a"), "off");
  EXPECT_EQ(builtin_default("Product", "RndMeth", "R2019b"), "Zero");
  EXPECT_EQ(builtin_default("Product", "RndMeth", "R2024b"), "Floor");
  EXPECT_EQ(builtin_default("Lookup_n-D", "InterpMethod", "R2019a"), "Linear");
  EXPECT_EQ(builtin_default("Lookup_n-D", "InterpMethod", "R2019b"), "Linear point-slope");
  EXPECT_EQ(builtin_default("Sum", "OutDataTypeStr", ""), "Inherit: Inherit via internal rule");  // the newest
  EXPECT_EQ(builtin_default("Sum", "OutDataTypeStr", "R2025b"), "Inherit: Inherit via internal rule");
  // The built-in default, not the library dialog's (which a block dragged from the library stores explicitly).
  EXPECT_EQ(builtin_default("UnitDelay", "SampleTime", "R2022b"), "1");
  EXPECT_EQ(builtin_default("Constant", "SampleTime", "R2022b"), "inf");
  EXPECT_EQ(builtin_default("Delay", "DelayLength", "R2022b"), "2");
}

TEST(BuiltinDefaults, KnowNothingOfWhatTheyDoNotList) {
  EXPECT_FALSE(builtin_default("Gain", "NoSuchParameter", "R2022b"));
  EXPECT_FALSE(builtin_default("S-Function", "FunctionName", "R2022b"));
  EXPECT_EQ(builtin_default("Gain", "Gain", "not a release"), "1");  // read as the newest
}

}  // namespace
}  // namespace duet::simulink_import
