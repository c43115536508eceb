#include "duet/xcp/host/endpoint.hpp"

#include <gtest/gtest.h>

namespace duet::xcp::host {
namespace {

TEST(Endpoint, ParsesTcpAndUdp) {
  const Result<Endpoint> tcp = parse_endpoint("tcp://127.0.0.1:5555");
  ASSERT_TRUE(tcp.ok()) << tcp.error();
  EXPECT_EQ(tcp.value().protocol, Protocol::tcp);
  EXPECT_EQ(tcp.value().host, "127.0.0.1");
  EXPECT_EQ(tcp.value().port, 5555);
  const Result<Endpoint> udp = parse_endpoint("udp://localhost:17725");
  ASSERT_TRUE(udp.ok()) << udp.error();
  EXPECT_EQ(udp.value().protocol, Protocol::udp);
  EXPECT_EQ(to_string(udp.value()), "udp://localhost:17725");
}

TEST(Endpoint, RefusesWhatItCannotUseAndSaysWhy) {
  EXPECT_EQ(parse_endpoint("http://x:1").error(),
            "'http://x:1': unknown scheme (expected tcp://host:port or udp://host:port)");
  EXPECT_NE(parse_endpoint("tcp://host").error().find("no host:port"), std::string::npos);
  EXPECT_NE(parse_endpoint("tcp://host:0").error().find("port must be a number"), std::string::npos);
  EXPECT_NE(parse_endpoint("tcp://host:70000").error().find("port must be a number"), std::string::npos);
  EXPECT_NE(parse_endpoint("tcp://host:55x").error().find("port must be a number"), std::string::npos);
}

}  // namespace
}  // namespace duet::xcp::host
