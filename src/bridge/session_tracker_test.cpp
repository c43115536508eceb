// The relay's view of the XCP session, packet by packet, on a clock the test sets.
#include "session_tracker.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "duet/xcp/protocol.hpp"

namespace duet::bridge {
namespace {

using std::chrono::milliseconds;
using Packet = std::vector<std::uint8_t>;

constexpr SessionTracker::Clock::time_point start{};
SessionTracker::Clock::time_point at(int milliseconds_in) { return start + milliseconds{milliseconds_in}; }

constexpr std::array<std::uint8_t, 2> connect{0xFF, 0x00};
constexpr std::array<std::uint8_t, 1> disconnect{0xFE};
constexpr std::array<std::uint8_t, 1> get_status{0xFD};
constexpr std::array<std::uint8_t, 4> unlock{0xF7, 0x02, 0x12, 0x34};
constexpr std::array<std::uint8_t, 1> positive{0xFF};
constexpr std::array<std::uint8_t, 8> connect_response{0xFF, 0x05, 0x00, 0x08, 0x08, 0x00, 0x01, 0x01};
constexpr std::array<std::uint8_t, 2> access_locked{0xFE, 0x25};
constexpr std::array<std::uint8_t, 2> session_terminated{0xFD, 0x07};
constexpr std::array<std::uint8_t, 5> daq{0x00, 0x01, 0x02, 0x03, 0x04};

class SessionTrackerTest : public ::testing::Test {
 protected:
  void connected() {
    ASSERT_TRUE(tracker.master_command(connect, at(0)));
    ASSERT_TRUE(tracker.slave_packet(connect_response, at(0)).to_master);
  }
  SessionTracker tracker;
};

TEST_F(SessionTrackerTest, AnAnswerPairsWithItsCommandAndTimesIt) {
  ASSERT_TRUE(tracker.master_command(connect, at(0)));
  const SessionTracker::Delivery delivery = tracker.slave_packet(connect_response, at(1));
  EXPECT_TRUE(delivery.to_master);
  EXPECT_EQ(delivery.answers_command, 0xFF);
  EXPECT_TRUE(tracker.master_command(get_status, at(10)));
  EXPECT_TRUE(tracker.slave_packet(daq, at(11)).to_master);  // DAQ answers nothing
  EXPECT_EQ(tracker.slave_packet(positive, at(13)).answers_command, 0xFD);
  EXPECT_EQ(tracker.figures().responses, 2U);
  EXPECT_DOUBLE_EQ(tracker.figures().latency_max_us, 3000.0);
  EXPECT_DOUBLE_EQ(tracker.figures().latency_total_us, 4000.0);
  EXPECT_EQ(tracker.figures().commands_unanswered, 0U);
}

TEST_F(SessionTrackerTest, ABlockModeDownloadWaitsForTheAnswerToItsLastPacketOnly) {
  connected();
  // 20 bytes in packets of at most 6 data bytes: DOWNLOAD, then DOWNLOAD_NEXT with the 14, 8 and 2 bytes left.
  EXPECT_FALSE(tracker.master_command(Packet{0xF0, 20, 1, 2, 3, 4, 5, 6}, at(10)));
  EXPECT_FALSE(tracker.master_command(Packet{0xEF, 14, 1, 2, 3, 4, 5, 6}, at(11)));
  EXPECT_FALSE(tracker.master_command(Packet{0xEF, 8, 1, 2, 3, 4, 5, 6}, at(12)));
  EXPECT_TRUE(tracker.master_command(Packet{0xEF, 2, 1, 2}, at(13)));
  EXPECT_EQ(tracker.slave_packet(positive, at(15)).answers_command, 0xEF);
  EXPECT_TRUE(tracker.master_command(Packet{0xF0, 2, 1, 2}, at(20)));  // a DOWNLOAD that fits one packet is answered
  EXPECT_EQ(tracker.slave_packet(positive, at(21)).answers_command, 0xF0);
  EXPECT_EQ(tracker.figures().responses, 3U);
  EXPECT_EQ(tracker.figures().commands_unanswered, 0U);
  EXPECT_DOUBLE_EQ(tracker.figures().latency_max_us, 2000.0);
}

TEST_F(SessionTrackerTest, CommandsToADisconnectedSlaveWaitForNothing) {
  connected();
  ASSERT_TRUE(tracker.master_command(disconnect, at(1)));
  ASSERT_TRUE(tracker.slave_packet(positive, at(2)).to_master);
  for (int command = 0; command < 10000; ++command) EXPECT_FALSE(tracker.master_command(get_status, at(3)));
  EXPECT_TRUE(tracker.master_command(connect, at(10000)));
  EXPECT_EQ(tracker.slave_packet(connect_response, at(10001)).answers_command, 0xFF);
  EXPECT_EQ(tracker.figures().responses, 3U);
  EXPECT_DOUBLE_EQ(tracker.figures().latency_max_us, 1000.0);
  EXPECT_EQ(tracker.figures().commands_unanswered, 0U);
  EXPECT_FALSE(tracker.owes_answers());
}

TEST_F(SessionTrackerTest, ANewCommandGivesUpOnTheOneBeforeIt) {
  connected();
  EXPECT_TRUE(tracker.master_command(get_status, at(10)));
  EXPECT_TRUE(tracker.master_command(get_status, at(500)));  // the master stopped waiting for the first
  EXPECT_EQ(tracker.slave_packet(positive, at(501)).answers_command, 0xFD);
  EXPECT_TRUE(tracker.slave_packet(positive, at(502)).to_master);  // a late answer still goes to the master
  EXPECT_EQ(tracker.figures().commands_unanswered, 1U);
  EXPECT_EQ(tracker.figures().responses, 2U);
  EXPECT_DOUBLE_EQ(tracker.figures().latency_max_us, 1000.0);
}

TEST_F(SessionTrackerTest, TheSlaveEndsTheSessionOnAWrongKeyOnDisconnectAndWithAnEvent) {
  connected();
  ASSERT_TRUE(tracker.master_command(unlock, at(1)));
  EXPECT_TRUE(tracker.slave_packet(access_locked, at(2)).to_master);
  EXPECT_FALSE(tracker.master_gone(at(3)));  // nothing to end, so no answer to wait for
  EXPECT_FALSE(tracker.owes_answers());

  connected();
  ASSERT_TRUE(tracker.master_command(disconnect, at(4)));
  EXPECT_EQ(tracker.slave_packet(positive, at(5)).answers_command, 0xFE);
  EXPECT_FALSE(tracker.master_gone(at(6)));

  connected();
  EXPECT_TRUE(tracker.slave_packet(session_terminated, at(7)).to_master);
  EXPECT_FALSE(tracker.master_gone(at(8)));
}

TEST_F(SessionTrackerTest, AccessLockedToAnythingButUnlockLeavesTheSessionOpen) {
  connected();
  ASSERT_TRUE(tracker.master_command(Packet{0xF0, 1, 7}, at(1)));
  EXPECT_TRUE(tracker.slave_packet(access_locked, at(2)).to_master);
  EXPECT_TRUE(tracker.master_gone(at(3)));
}

TEST_F(SessionTrackerTest, TheAnswersAMasterThatLeftWaitedForAreOwedToNobody) {
  connected();
  ASSERT_TRUE(tracker.master_command(get_status, at(10)));
  ASSERT_TRUE(tracker.master_gone(at(11)));
  tracker.relay_disconnect(at(11));
  EXPECT_TRUE(tracker.owes_answers());
  EXPECT_FALSE(tracker.slave_packet(positive, at(12)).to_master);  // GET_STATUS's
  EXPECT_TRUE(tracker.owes_answers());
  EXPECT_TRUE(tracker.slave_packet(daq, at(12)).to_master);        // DAQ is not an answer
  EXPECT_FALSE(tracker.slave_packet(positive, at(13)).to_master);  // the relay's DISCONNECT's
  EXPECT_FALSE(tracker.owes_answers());
  EXPECT_FALSE(tracker.master_gone(at(14)));  // the relay's DISCONNECT ended the session
  EXPECT_TRUE(tracker.master_command(connect, at(20)));
  EXPECT_EQ(tracker.slave_packet(connect_response, at(21)).answers_command, 0xFF);
  EXPECT_EQ(tracker.figures().commands_unanswered, 0U);
  EXPECT_EQ(tracker.figures().responses, 2U);  // the answers owed to nobody are no master's latency
}

TEST_F(SessionTrackerTest, AConnectLeftWaitingIsEndedToo) {
  ASSERT_TRUE(tracker.master_command(connect, at(0)));
  EXPECT_TRUE(tracker.master_gone(at(1)));  // its CONNECT may yet open a session
}

TEST_F(SessionTrackerTest, OwedAnswersThatNeverComeAreGivenUpInTime) {
  connected();
  ASSERT_TRUE(tracker.master_gone(at(10)));
  tracker.relay_disconnect(at(10));
  EXPECT_EQ(tracker.owed_until(), at(10) + SessionTracker::default_owed_answer_patience);
  EXPECT_FALSE(tracker.give_up_owed_answers(at(11)));
  EXPECT_TRUE(tracker.owes_answers());
  EXPECT_TRUE(tracker.give_up_owed_answers(at(10) + SessionTracker::default_owed_answer_patience));
  EXPECT_FALSE(tracker.owes_answers());
  EXPECT_EQ(tracker.figures().commands_unanswered, 1U);
  EXPECT_TRUE(tracker.master_command(connect, at(300)));
  EXPECT_TRUE(tracker.slave_packet(connect_response, at(301)).to_master);
}

TEST_F(SessionTrackerTest, ANewChannelIsANewSlave) {
  connected();
  ASSERT_TRUE(tracker.master_command(get_status, at(1)));
  tracker.channel_reset();
  EXPECT_EQ(tracker.figures().commands_unanswered, 1U);
  EXPECT_FALSE(tracker.master_gone(at(2)));
}

TEST_F(SessionTrackerTest, APositiveAnswerNothingWaitedForShowsASession) {
  EXPECT_FALSE(tracker.master_command(get_status, at(0)));  // a session older than the tracker: not known yet
  const SessionTracker::Delivery delivery = tracker.slave_packet(positive, at(1));
  EXPECT_TRUE(delivery.to_master);
  EXPECT_FALSE(delivery.answers_command);
  EXPECT_EQ(tracker.figures().responses, 0U);
  EXPECT_TRUE(tracker.master_gone(at(2)));
}

}  // namespace
}  // namespace duet::bridge
