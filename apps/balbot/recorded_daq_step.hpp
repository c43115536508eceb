#pragma once
// For the tests that run the robot's firmware with its XCP slave (on the PC, on QEMU): records the 1 ms task's
// samples for 10 s of wall time with `duet xcp record`, as a user would, and gives the mean step between consecutive
// DAQ timestamps, which must be the task's period: the timestamps are the executive's time.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "child_program.hpp"
#include "duet/plot/csv.hpp"
#include "duet/support/text_file.hpp"

namespace duet::sil {

// NAN (with the test failed) when the recording fails or holds fewer than 1000 samples.
inline double recorded_daq_step(const std::string& a2l, const std::string& url) {
  const TemporaryFile csv{"daq_step.csv"};
  Program record{DUET_PROGRAM,
                 // A long timeout: until the emulated firmware's line is open, the bridge answers ERR_CMD_BUSY,
                 // which the master repeats its command for, up to the timeout.
                 {"xcp", "record", "--a2l", a2l, "--connect", url, "--signal", "theta", "--event", "rate 1",
                  "--duration", "10", "--timeout", "10000", "--output", csv.path()},
                 "record"};
  EXPECT_EQ(record.wait(), 0) << record.errors();
  auto text = read_text_file(csv.path());
  if (!text.ok()) return NAN;
  auto recording = plot::read_csv(text.value(), csv.path());
  EXPECT_TRUE(recording.ok()) << (recording.ok() ? "" : recording.error());
  if (!recording.ok() || recording.value().time.size() < 1000) {
    ADD_FAILURE() << "too few samples in " << text.value().substr(0, 200);
    return NAN;
  }
  const std::vector<double>& time = recording.value().time;
  return (time.back() - time.front()) / static_cast<double>(time.size() - 1);
}

}  // namespace duet::sil
