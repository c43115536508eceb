#include "duet/xcp/host/a2l_check.hpp"

#include <gtest/gtest.h>

#include "duet/support/text_file.hpp"
#include "duet/xcp/host/a2l.hpp"

namespace duet::xcp::host {
namespace {

std::string engine_file() { return std::string{DUET_A2L_TESTING} + "/engine.a2l"; }

std::string engine_text() {
  auto text = read_text_file(engine_file());
  EXPECT_TRUE(text.ok()) << text.error();
  return text.ok() ? text.value() : std::string{};
}

std::vector<std::string> texts(const std::vector<A2lProblem>& problems) {
  std::vector<std::string> lines;
  lines.reserve(problems.size());
  for (const A2lProblem& problem : problems) lines.push_back(problem.text());
  return lines;
}

TEST(A2lCheck, AFileOfOtherToolsConstructsPasses) {
  const std::vector<A2lProblem> problems = check_a2l_file(engine_file());
  EXPECT_TRUE(problems.empty()) << testing::PrintToString(texts(problems));
}

TEST(A2lCheck, WhatDuetWritesPasses) {
  A2lDescription a2l;
  a2l.module = "robot";
  a2l.memory = {{"signals", 0, 0x1000, 0x100, false}, {"parameters", 0, 0x2000, 0x100, true}};
  a2l.measurements = {{"theta", "tilt", DataType::float32, 0, 0x1000, 1, "deg", -90, 90, {}},
                      {"wheels", "", DataType::int16, 0, 0x1004, 4, "rpm", -500, 500, {0.5, 0}, {}, {2, 2}},
                      {"state", "", DataType::uint8, 0, 0x100C, 1, "", 0, 1, {}, {{0, "off"}, {1, "on"}}}};
  a2l.characteristics = {{"gains", "", DataType::float32, 0, 0x2000, 3, "", 0, 100, {}}};
  a2l.events = {{"DMA2_Stream2", 0, 0, 6, 1}, {"DMA2_Stream3", 1, 0, 6, 2}, {"1 ms", 2, 1, 6, 0}};
  a2l.epk = "robot 1.0";
  a2l.epk_address = 0x3000;
  const std::vector<A2lProblem> problems = check_a2l(write_a2l(a2l), "robot.a2l");
  EXPECT_TRUE(problems.empty()) << testing::PrintToString(texts(problems));
}

TEST(A2lCheck, UnknownKeywordsAreWarningsNotSilence) {
  std::string text = engine_text();
  text.replace(text.find("EXTENDED_LIMITS 0 3000"), 22, "EXTENDED_LIMITS 0 3000 COLOUR 3");
  const std::string vendor = "/begin IF_DATA CANAPE_EXT 100 /end IF_DATA\n    /end MEASUREMENT";
  text.replace(text.find("/end MEASUREMENT"), 16, vendor);
  text.replace(text.find("/end MEASUREMENT", text.find(vendor) + vendor.size()), 16, vendor);
  text.replace(text.find("/end MODULE"), 11, "/begin FRAME_WORK x /end FRAME_WORK /end MODULE");
  const std::vector<A2lProblem> problems = check_a2l(text, engine_file());
  EXPECT_EQ(texts(problems),
            (std::vector<std::string>{
                engine_file() + ":91:20: warning: IF_DATA CANAPE_EXT is not checked",
                engine_file() + ":110:30: warning: unknown keyword COLOUR in CHARACTERISTIC (not checked)",
                engine_file() + ":163:3: warning: unknown keyword FRAME_WORK in MODULE (not checked)",
            }));
  EXPECT_FALSE(has_errors(problems));
}

TEST(A2lCheck, AFileThatIsNotThereIsAnError) {
  const std::vector<A2lProblem> problems = check_a2l_file("/nonexistent/x.a2l");
  EXPECT_EQ(texts(problems), std::vector<std::string>{"/nonexistent/x.a2l: error: cannot open"});
}

// One rule broken: the engine file with `from` replaced by `to` gives exactly `expected` (after "FILE:").
struct Broken {
  std::string rule;
  std::string from;
  std::string to;
  std::string expected;
};

class A2lCheckRule : public testing::TestWithParam<Broken> {};

TEST_P(A2lCheckRule, IsReportedAtItsPlace) {
  const Broken& broken = GetParam();
  std::string text = engine_text();
  const std::size_t at = text.find(broken.from);
  ASSERT_NE(at, std::string::npos) << broken.from;
  text.replace(at, broken.from.size(), broken.to);
  const std::vector<A2lProblem> problems = check_a2l(text, engine_file());
  EXPECT_EQ(texts(problems), std::vector<std::string>{engine_file() + ":" + broken.expected});
  EXPECT_TRUE(has_errors(problems));
}

std::vector<Broken> broken_rules() {
  return {
      {"balanced_blocks", "/begin PAG 1 FREEZE_SUPPORTED /end PAG", "/begin PAG 1 FREEZE_SUPPORTED /end DAQ",
       "50:37: error: /end DAQ closes /begin PAG (line 50)"},
      {"conversion_exists", "UBYTE temperature", "UBYTE temperatur",
       "92:60: error: MEASUREMENT 'coolant': no COMPU_METHOD named 'temperatur'"},
      {"record_layout_exists", "scalar_uword 0 rpm 500", "scalar_word 0 rpm 500",
       "106:72: error: CHARACTERISTIC 'idle_speed': no RECORD_LAYOUT named 'scalar_word'"},
      {"axis_points_exist", "AXIS_PTS_REF load_points", "AXIS_PTS_REF load_point",
       "125:22: error: AXIS_DESCR: no AXIS_PTS named 'load_point'"},
      {"group_members_exist", "engine_speed coolant front_left.speed", "engine_speed coolant2 front_left.speed",
       "149:43: error: REF_MEASUREMENT: no MEASUREMENT named 'coolant2'"},
      {"typedef_exists", "wheel 0x20001010", "wheels 0x20001010",
       "145:55: error: INSTANCE 'front_left': no TYPEDEF_STRUCTURE or TYPEDEF_MEASUREMENT or TYPEDEF_CHARACTERISTIC or "
       "TYPEDEF_AXIS or TYPEDEF_BLOB named 'wheels'"},
      {"object_names_unique", "MEASUREMENT flags", "MEASUREMENT gear",
       "98:24: error: MEASUREMENT 'gear': the name is taken by the MEASUREMENT at line 95"},
      {"conversion_names_unique", "COMPU_METHOD pedal ", "COMPU_METHOD gear_names ",
       "69:25: error: COMPU_METHOD 'gear_names': the name is taken by the COMPU_METHOD at line 60"},
      {"identifier_charset", "MEASUREMENT flags", "MEASUREMENT 2flags",
       "98:24: error: MEASUREMENT: Name: '2flags' is not an identifier (a letter or _, then letters, digits, _ . [ ], "
       "at "
       "most 1024)"},
      {"identifier_length", "MEASUREMENT flags", "MEASUREMENT " + std::string(1025, 'f'),
       "98:24: error: MEASUREMENT: Name: '" + std::string(1025, 'f') +
           "' is not an identifier (a letter or _, then letters, digits, _ . [ ], at most 1024)"},
      {"uchar_range", "0 8 8 BYTE_ORDER", "0 256 8 BYTE_ORDER",
       "40:56: error: PROTOCOL_LAYER: MAX_CTO: '256' is outside uchar (0 to 255)"},
      {"short_name_length", "\"crank\"", "\"crank_angle\"",
       "48:46: error: EVENT: ShortName: 'crank_angle' is longer than 8 characters"},
      {"event_channels_unique", "\"crank\" 1 DAQ", "\"crank\" 0 DAQ",
       "48:54: error: EVENT: the channel '0' is taken by the event at line 47"},
      {"event_names_unique", "\"crank angle interrupt\"", "\"10 ms task\"",
       "48:22: error: EVENT: the name '10 ms task' is taken by the event at line 47"},
      {"event_count", "DYNAMIC 2 2 0", "DYNAMIC 2 3 0",
       "45:28: error: DAQ: MAX_EVENT_CHANNEL is 3 but 2 EVENTs follow"},
      {"address_in_segment", "ECU_ADDRESS 0x20001002", "ECU_ADDRESS 0x30000000",
       "93:19: error: MEASUREMENT 'coolant' at 0x30000000 (1 byte) is in no MEMORY_SEGMENT"},
      {"epk_in_segment", "ADDR_EPK 0x8000", "ADDR_EPK 0x4000",
       "15:16: error: MOD_PAR: the EPK at 0x4000 (21 bytes) is in no MEMORY_SEGMENT, so a master cannot upload it"},
      {"epk_with_address", "      EPK \"engine 1.0 2026-11-26\"\n", "",
       "14:16: error: MOD_PAR: ADDR_EPK without EPK (what should a master find there?)"},
      {"keyword_of_a_set", "DATA RAM INTERN", "DATA RAM INSIDE",
       "19:81: error: MEMORY_SEGMENT: Attribute: 'INSIDE' is not one of INTERN, EXTERN"},
      {"value_missing", "values_sword 0 NO_COMPU_METHOD 0 100\n      /begin AXIS_DESCR FIX_AXIS",
       "values_sword 0 NO_COMPU_METHOD 0\n      /begin AXIS_DESCR FIX_AXIS",
       "128:5: error: CHARACTERISTIC: UpperLimit (float) is missing"},
      {"limits_within_the_type", "UBYTE NO_COMPU_METHOD 0 0 0 255", "UBYTE NO_COMPU_METHOD 0 0 0 256",
       "98:72: error: MEASUREMENT 'flags': the limits 0 to 256 are outside what UBYTE holds"},
      {"limits_in_order", "scalar_uword 0 rpm 500 1500", "scalar_uword 0 rpm 1500 500",
       "106:91: error: CHARACTERISTIC 'idle_speed': LowerLimit 1500 is above UpperLimit 500"},
      {"number", "-40 87.5", "-40 hot", "92:82: error: MEASUREMENT: UpperLimit: 'hot' is not a number"},
      {"block_in_its_parent", "/begin PAG 1 FREEZE_SUPPORTED /end PAG",
       "/begin PAG 1 /begin PAGE 0 ECU_ACCESS_DONT_CARE XCP_READ_ACCESS_DONT_CARE XCP_WRITE_ACCESS_DONT_CARE /end PAGE "
       "/end PAG",
       "50:20: error: PAGE is not allowed in PAG"},
      {"format", "RAT_FUNC \"%6.1\"", "RAT_FUNC \"%.1\"",
       "53:82: error: COMPU_METHOD: the format '%.1' is not %Length.Layout (e.g. %8.3: 8 characters, 3 after the "
       "point)"},
      {"axes_of_a_curve", "MAP 0x20000200", "CURVE 0x20000200",
       "120:64: error: CHARACTERISTIC 'fuel': a CURVE has 1 AXIS_DESCR, not 2"},
      {"size_of_a_block", "VALUE 0x20000000", "VAL_BLK 0x20000000",
       "106:55: error: CHARACTERISTIC 'idle_speed': a VAL_BLK needs MATRIX_DIM (or NUMBER) to say how many values it "
       "has"},
      {"keyword_once", "ECU_ADDRESS 0x20001002", "ECU_ADDRESS 0x20001002 ECU_ADDRESS 0x20001002",
       "93:30: error: MEASUREMENT: ECU_ADDRESS appears twice (first at line 93)"},
      {"table_size", "TAB_VERB 3", "TAB_VERB 4", "63:51: error: COMPU_VTAB: NumberValuePairs is 4 but 3 follow"},
      {"segment_numbers", "/begin PAG 1", "/begin PAG 0",
       "21:26: error: SEGMENT: number 0 is not below PAG's MAX_SEGMENTS 0"},
      {"include_found", "/include \"engine_units.a2l\"", "/include \"missing_units.a2l\"",
       "11:5: error: /include \"missing_units.a2l\": cannot open " + std::string{DUET_A2L_TESTING} +
           "/missing_units.a2l"},
  };
}

INSTANTIATE_TEST_SUITE_P(Broken, A2lCheckRule, testing::ValuesIn(broken_rules()),
                         [](const testing::TestParamInfo<Broken>& broken) { return broken.param.rule; });

}  // namespace
}  // namespace duet::xcp::host
