// The EPK check at connect: the slave's EPK against the A2L's, equal, different, unreadable, or not named at all.
#include "duet/xcp/host/epk.hpp"

#include <gtest/gtest.h>

#include <chrono>

#include "test_target.hpp"

namespace duet::xcp::host {
namespace {

class Epk : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(target.server.start({}).ok());
    auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", target.server.port()}, std::chrono::seconds{1});
    ASSERT_TRUE(channel.ok()) << channel.error();
    master = std::make_unique<Master>(std::move(channel).value());
    ASSERT_TRUE(master->connect().ok());
  }
  TestTarget target;
  std::unique_ptr<Master> master;
  A2lDescription a2l = TestTarget::a2l({});
};

TEST_F(Epk, TheFirmwaresOwnA2lPasses) { EXPECT_TRUE(check_epk(*master, a2l).ok()); }

TEST_F(Epk, AnotherFirmwaresA2lIsRefusedWithBothNames) {
  a2l.epk = "duet_target 2";
  const Status checked = check_epk(*master, a2l);
  ASSERT_FALSE(checked.ok());
  EXPECT_EQ(checked.error(),
            "the slave holds EPK \"duet_target 1\" at 0x4000, the A2L names \"duet_target 2\": the A2L does not "
            "describe this firmware (generate it from the firmware's model, or load the firmware it was generated "
            "with)");
}

TEST_F(Epk, AnEpkWhereTheSlaveHasNoneIsRefused) {
  a2l.epk_address = 0x5000;
  const Status checked = check_epk(*master, a2l);
  ASSERT_FALSE(checked.ok());
  EXPECT_NE(checked.error().find("the slave's EPK at 0x5000 cannot be read (UPLOAD: ERR_ACCESS_DENIED (0x24))"),
            std::string::npos)
      << checked.error();
}

TEST_F(Epk, AnA2lWithoutAnEpkCannotTellAndPasses) {
  a2l.epk.clear();
  EXPECT_TRUE(check_epk(*master, a2l).ok());
}

}  // namespace
}  // namespace duet::xcp::host
