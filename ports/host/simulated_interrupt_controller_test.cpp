#include "duet/host/simulated_interrupt_controller.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace duet::host {
namespace {

class SimulatedInterruptControllerTest : public ::testing::Test {
 protected:
  // Connects `line` with a handler that records "+name", runs `body`, and records "-name".
  void connect(
      std::size_t line, SimulatedInterruptController::Priority priority, const std::string& name,
      const std::function<void()>& body = [] {}) {
    controller.connect(line, priority, [this, name, body] {
      trace.push_back("+" + name);
      body();
      trace.push_back("-" + name);
    });
  }

  SimulatedInterruptController controller{8};
  std::vector<std::string> trace;
};

TEST_F(SimulatedInterruptControllerTest, AMoreUrgentGroupPreemptsAtOnce) {
  connect(1, {2, 0}, "low", [this] { controller.pend(2); });
  connect(2, {1, 0}, "high");
  controller.pend(1);
  EXPECT_EQ(trace, (std::vector<std::string>{"+low", "+high", "-high", "-low"}));
}

TEST_F(SimulatedInterruptControllerTest, TheSameGroupWaitsAndSubPriorityThenLineNumberOrderIt) {
  connect(1, {2, 0}, "first", [this] {
    controller.pend(5);  // group 2, sub 1
    controller.pend(4);  // group 2, sub 0: before 5 despite being pended later
    controller.pend(3);  // group 2, sub 0: before 4, the lower line number
  });
  connect(3, {2, 0}, "three");
  connect(4, {2, 0}, "four");
  connect(5, {2, 1}, "five");
  controller.pend(1);
  EXPECT_EQ(trace,
            (std::vector<std::string>{"+first", "-first", "+three", "-three", "+four", "-four", "+five", "-five"}));
}

TEST_F(SimulatedInterruptControllerTest, ALessUrgentLineWaitsForTheRunningOne) {
  connect(1, {1, 0}, "urgent", [this] {
    controller.pend(2);
    trace.emplace_back("still urgent");
  });
  connect(2, {3, 0}, "later");
  controller.pend(1);
  EXPECT_EQ(trace, (std::vector<std::string>{"+urgent", "still urgent", "-urgent", "+later", "-later"}));
}

TEST_F(SimulatedInterruptControllerTest, ALineWithoutHandlerStaysQuietAndPendingCanBeCleared) {
  controller.pend(7);
  EXPECT_FALSE(controller.pending(7));
  connect(6, {1, 0}, "six", [this] {
    controller.pend(6);  // itself, while running: the same group, so it waits
    EXPECT_TRUE(controller.pending(6));
    controller.clear_pending(6);
  });
  controller.pend(6);
  EXPECT_EQ(trace, (std::vector<std::string>{"+six", "-six"}));
}

}  // namespace
}  // namespace duet::host
