#include "duet/xcp/host/a2l.hpp"

#include <gtest/gtest.h>

namespace duet::xcp::host {
namespace {

A2lDescription robot() {
  A2lDescription a2l;
  a2l.module = "balbot";
  a2l.description = "the self-balancing robot";
  a2l.memory = {{"signals", 0, 0x1000, 0x100, false}, {"parameters", 0, 0x2000, 0x2000, true}};
  a2l.measurements = {
      {"theta", "tilt angle", DataType::float32, 0, 0x1000, 1, "deg", -90, 90, {}},
      {"battery", "battery voltage, raw ADC", DataType::uint16, 0, 0x1004, 1, "V", 0, 13.2, {0.0032, -0.1}},
      {"wheel_speeds", "left and right", DataType::int16, 0, 0x1008, 2, "rpm", -500, 500, {}},
      {"state",
       "what the robot does",
       DataType::uint8,
       0,
       0x100C,
       1,
       "",
       0,
       2,
       {},
       {{0, "initialising"}, {1, "balancing"}, {2, "stopped"}}},
  };
  a2l.characteristics = {
      {"P", "proportional gain", DataType::float32, 0, 0x2000, 1, "", 0, 100, {}},
      {"table", "4096 test values", DataType::uint16, 0, 0x2010, 4096, "", 0, 65535, {}},
  };
  a2l.events = {{"1 ms", 0, 1, 6, 0, "1 ms"}, {"EXTI8 interrupt", 1, 0, 6, 1, "EXTI8 in"}};
  a2l.max_cto = 248;
  a2l.max_dto = 1024;
  a2l.transport = {Protocol::udp, "192.0.2.7", 5555};
  return a2l;
}

TEST(A2l, WhatTheWriterWritesTheReaderReadsBack) {
  const std::string text = write_a2l(robot());
  const Result<A2lDescription> read = read_a2l(text, "robot.a2l");
  ASSERT_TRUE(read.ok()) << read.error();
  EXPECT_EQ(read.value(), robot());
}

TEST(A2l, TheDefaultsAreTodaysSlave) {
  const std::string text = write_a2l(robot());
  EXPECT_NE(text.find(" IDENTIFICATION_FIELD_TYPE_ABSOLUTE GRANULARITY_ODT_ENTRY_SIZE_DAQ_BYTE 0xFF "),
            std::string::npos);
  EXPECT_NE(text.find("/begin TIMESTAMP_SUPPORTED 1 SIZE_DWORD UNIT_1US /end TIMESTAMP_SUPPORTED"), std::string::npos);
  EXPECT_NE(text.find("/begin CHECKSUM XCP_CRC_16_CITT MAX_BLOCK_SIZE 0xFFFF EXTERNAL_FUNCTION \"\" /end CHECKSUM"),
            std::string::npos);
  EXPECT_NE(text.find("/begin PAGE 1 "), std::string::npos);
}

TEST(A2l, NamedValuesAreAVerbalConversionWithItsTable) {
  const std::string text = write_a2l(robot());
  EXPECT_NE(text.find("/begin MEASUREMENT state \"what the robot does\" UBYTE duet_verbal_state "), std::string::npos);
  EXPECT_NE(text.find("/begin COMPU_METHOD duet_verbal_state \"\" TAB_VERB \"%12.0\" \"\" COMPU_TAB_REF "
                      "duet_verbal_state_table /end COMPU_METHOD"),
            std::string::npos);
  EXPECT_NE(text.find("/begin COMPU_VTAB duet_verbal_state_table \"\" TAB_VERB 3 0 \"initialising\" 1 \"balancing\" "
                      "2 \"stopped\" /end COMPU_VTAB"),
            std::string::npos);
}

TEST(A2l, TheFileIsPlainForTools) {
  const std::string text = write_a2l(robot());
  EXPECT_TRUE(text.starts_with("ASAP2_VERSION 1 71\n"));
  EXPECT_EQ(text.find("TYPEDEF"), std::string::npos);
  EXPECT_EQ(text.find("/include"), std::string::npos);
  EXPECT_NE(text.find("    /begin MEASUREMENT theta \"tilt angle\" FLOAT32_IEEE duet_identity 0 0 -90 90\n"
                      "      ECU_ADDRESS 0x1000\n"),
            std::string::npos);
  EXPECT_NE(
      text.find("/begin CHARACTERISTIC table \"4096 test values\" VAL_BLK 0x2010 duet_UWORD 0 duet_identity 0 65535\n"),
      std::string::npos);
  EXPECT_NE(text.find("      MATRIX_DIM 4096\n"), std::string::npos);
  EXPECT_NE(text.find("/begin COMPU_METHOD duet_identity \"\" IDENTICAL \"%12.6\" \"\" /end COMPU_METHOD"),
            std::string::npos);
  EXPECT_EQ(text.find("\"%.6\""), std::string::npos) << "FORMAT needs its length: %Length.Layout";
  EXPECT_NE(text.find("COEFFS_LINEAR 0.0032000000000000002 -0.10000000000000001"), std::string::npos);
  EXPECT_NE(text.find("/begin XCP_ON_UDP_IP 0x0100 5555 ADDRESS \"192.0.2.7\" /end XCP_ON_UDP_IP"), std::string::npos);
  EXPECT_NE(text.find("/begin EVENT \"EXTI8 interrupt\" \"EXTI8 in\" 1 DAQ 0xFF 0 6 1 /end EVENT"), std::string::npos);
  EXPECT_NE(text.find("/begin SEGMENT 0 2 0 0 0"), std::string::npos);
  EXPECT_EQ(text.find("OPTIONAL_CMD USER_CMD"), std::string::npos) << "the slave answers USER_CMD only with a hook";
}

// The calibration segment's address is its working page, in RAM; signals are variables in RAM.
TEST(A2l, SegmentsSayWhatTheyHold) {
  const std::string text = write_a2l(robot());
  EXPECT_NE(text.find("/begin MEMORY_SEGMENT parameters \"\" DATA RAM INTERN 0x2000 0x2000 -1 -1 -1 -1 -1\n"),
            std::string::npos);
  EXPECT_NE(text.find("/begin MEMORY_SEGMENT signals \"\" VARIABLES RAM INTERN 0x1000 0x100 -1 -1 -1 -1 -1\n"),
            std::string::npos);
  EXPECT_EQ(text.find("FLASH"), std::string::npos);
}

TEST(A2l, ArraysGiveEveryDimension) {
  A2lDescription a2l = robot();
  a2l.characteristics[1].count = 4;
  a2l.characteristics[1].dimensions = {2, 2};
  const std::string text = write_a2l(a2l);
  EXPECT_NE(text.find("      MATRIX_DIM 2 2\n"), std::string::npos);
  EXPECT_EQ(text.find("MATRIX_DIM 4\n"), std::string::npos);
  const Result<A2lDescription> read = read_a2l(text, "robot.a2l");
  ASSERT_TRUE(read.ok()) << read.error();
  EXPECT_EQ(read.value().characteristics[1].count, 4U);
  EXPECT_EQ(read.value().characteristics[1].dimensions, (std::vector<std::uint32_t>{2, 2}));
}

TEST(A2l, EpkIsInModParAndInADeclaredSegment) {
  A2lDescription a2l = robot();
  a2l.epk = "balbot 2026-11-26 1a2b3c";
  a2l.epk_address = 0x8000;
  std::string text = write_a2l(a2l);
  EXPECT_NE(text.find("      EPK \"balbot 2026-11-26 1a2b3c\"\n      ADDR_EPK 0x8000\n"), std::string::npos);
  EXPECT_NE(text.find("/begin MEMORY_SEGMENT epk \"the ECU program identifier\" CODE ROM INTERN 0x8000 0x18"),
            std::string::npos);
  Result<A2lDescription> read = read_a2l(text, "robot.a2l");
  ASSERT_TRUE(read.ok()) << read.error();
  EXPECT_EQ(read.value().epk, a2l.epk);
  EXPECT_EQ(read.value().epk_address, 0x8000U);

  a2l.epk_address = 0x1010;  // inside the signals' segment: no segment of its own
  text = write_a2l(a2l);
  EXPECT_NE(text.find("ADDR_EPK 0x1010\n"), std::string::npos);
  EXPECT_EQ(text.find("MEMORY_SEGMENT epk"), std::string::npos);
  EXPECT_EQ(write_a2l(robot()).find("EPK"), std::string::npos);
}

TEST(A2l, EventShortNamesAreUniqueAndAtMostEightCharacters) {
  A2lDescription a2l = robot();
  a2l.events = {{"DMA2_Stream2", 0, 0, 6, 3}, {"DMA2_Stream3", 1, 0, 6, 2}, {"DMA2_Stream4", 2, 0, 6, 1}};
  const std::string text = write_a2l(a2l);
  EXPECT_NE(text.find("/begin EVENT \"DMA2_Stream2\" \"DMA2_St2\" 0 DAQ"), std::string::npos) << text;
  EXPECT_NE(text.find("/begin EVENT \"DMA2_Stream3\" \"DMA2_St3\" 1 DAQ"), std::string::npos);
  EXPECT_NE(text.find("/begin EVENT \"DMA2_Stream4\" \"DMA2_St4\" 2 DAQ"), std::string::npos);
  // A given short name is kept; the derived ones make way for it.
  a2l.events = {{"DMA2_Stream2", 0, 0, 6, 3},      {"DMA2_Stream3", 1, 0, 6, 2}, {"DMA2_Stream4", 2, 0, 6, 1},
                {"timer", 3, 1, 6, 0, "DMA2_St2"}, {"DMA2_Stream", 4, 0, 6, 0},  {"DMA2_Streams", 5, 0, 6, 0}};
  const Result<A2lDescription> read = read_a2l(write_a2l(a2l), "robot.a2l");
  ASSERT_TRUE(read.ok()) << read.error();
  std::vector<std::string> short_names;
  for (const EventInfo& event : read.value().events) short_names.push_back(event.short_name);
  EXPECT_EQ(short_names,
            (std::vector<std::string>{"DMA2_St1", "DMA2_St3", "DMA2_St4", "DMA2_St2", "DMA2_Str", "DMA2_St5"}));
}

TEST(A2l, DaqAndSegmentLimitsComeFromTheDescription) {
  A2lDescription a2l = robot();
  a2l.max_daq_lists = 4;
  a2l.max_odt_entry_size = 8;
  a2l.identification_field = IdentificationField::relative_word_aligned;
  a2l.timestamp_size = 2;
  a2l.timestamp_unit = 6;
  a2l.timestamp_ticks = 10;
  a2l.checksum_type = ChecksumType::crc_32;
  a2l.checksum_max_block_size = 0x100000;
  a2l.calibration_reference_page = false;
  a2l.user_command = true;
  const std::string text = write_a2l(a2l);
  EXPECT_NE(text.find("/begin DAQ DYNAMIC 4 2 0 OPTIMISATION_TYPE_DEFAULT ADDRESS_EXTENSION_FREE "
                      "IDENTIFICATION_FIELD_TYPE_RELATIVE_WORD_ALIGNED GRANULARITY_ODT_ENTRY_SIZE_DAQ_BYTE 0x8 "
                      "OVERLOAD_INDICATION_EVENT\n"),
            std::string::npos);
  EXPECT_NE(text.find("/begin TIMESTAMP_SUPPORTED 10 SIZE_WORD UNIT_1MS /end TIMESTAMP_SUPPORTED"), std::string::npos);
  EXPECT_NE(text.find("/begin CHECKSUM XCP_CRC_32 MAX_BLOCK_SIZE 0x100000"), std::string::npos);
  EXPECT_NE(text.find("/begin SEGMENT 0 1 0 0 0"), std::string::npos);
  EXPECT_EQ(text.find("/begin PAGE 1"), std::string::npos);
  EXPECT_NE(text.find("OPTIONAL_CMD USER_CMD"), std::string::npos);
  const Result<A2lDescription> read = read_a2l(text, "robot.a2l");
  ASSERT_TRUE(read.ok()) << read.error();
  EXPECT_EQ(read.value(), a2l);

  a2l.timestamp_size = 0;
  EXPECT_EQ(write_a2l(a2l).find("TIMESTAMP_SUPPORTED"), std::string::npos);
}

TEST(A2l, ErrorsNameTheLineTheColumnAndTheProblem) {
  EXPECT_EQ(
      read_a2l("ASAP2_VERSION 1 71\n/begin PROJECT p \"\"\n  /begin MODULE m \"\"\n/end PROJECT\n", "x.a2l").error(),
      "x.a2l:4:1: /end PROJECT closes /begin MODULE (line 3)");
  EXPECT_EQ(read_a2l("/begin PROJECT p \"\"\n  /begin MODULE m \"\"\n", "x.a2l").error(),
            "x.a2l:2:3: /begin MODULE is never closed");
  EXPECT_EQ(read_a2l("ASAP2_VERSION 1 71\n", "x.a2l").error(), "x.a2l:1:1: no /begin PROJECT");
  const std::string bad_number =
      "/begin PROJECT p \"\" /begin MODULE m \"\"\n"
      "/begin MEASUREMENT a \"\" UBYTE NO_COMPU_METHOD 0 0 zero 1 /end MEASUREMENT\n"
      "/end MODULE /end PROJECT\n";
  EXPECT_EQ(read_a2l(bad_number, "x.a2l").error(), "x.a2l:2:51: 'zero' is not a number");
  const std::string bad_type =
      "/begin PROJECT p \"\" /begin MODULE m \"\"\n"
      "/begin MEASUREMENT a \"\" UCHAR NO_COMPU_METHOD 0 0 0 1 /end MEASUREMENT\n"
      "/end MODULE /end PROJECT\n";
  EXPECT_EQ(read_a2l(bad_type, "x.a2l").error(), "x.a2l:2:25: 'UCHAR' is not an A2L data type");
  EXPECT_EQ(read_a2l("/begin PROJECT p \"open", "x.a2l").error(), "x.a2l:1:18: a text that never ends");
  std::string deep;
  for (int level = 0; level < 1000; ++level) deep += "/begin X ";
  EXPECT_EQ(read_a2l(deep, "x.a2l").error(), "x.a2l:1:577: /begin X: blocks nest deeper than 64");
}

}  // namespace
}  // namespace duet::xcp::host
