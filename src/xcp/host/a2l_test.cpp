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
  };
  a2l.characteristics = {
      {"P", "proportional gain", DataType::float32, 0, 0x2000, 1, "", 0, 100, {}},
      {"table", "4096 test values", DataType::uint16, 0, 0x2010, 4096, "", 0, 65535, {}},
  };
  a2l.events = {{"1 ms", 0, 1, 6, 0}, {"EXTI8 interrupt", 1, 0, 6, 1}};
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
  EXPECT_NE(text.find("COEFFS_LINEAR 0.0032000000000000002 -0.10000000000000001"), std::string::npos);
  EXPECT_NE(text.find("/begin XCP_ON_UDP_IP 0x0100 5555 ADDRESS \"192.0.2.7\" /end XCP_ON_UDP_IP"), std::string::npos);
  EXPECT_NE(text.find("/begin EVENT \"EXTI8 interrupt\" \"EXTI8 in\" 1 DAQ 0xFF 0 6 1 /end EVENT"), std::string::npos);
  EXPECT_NE(text.find("/begin SEGMENT 0 2 0 0 0"), std::string::npos);
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
}

}  // namespace
}  // namespace duet::xcp::host
