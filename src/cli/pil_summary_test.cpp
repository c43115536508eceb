// duet pil's summary from what a run left behind: the robot's tilt, instructions from timer cycles, the bridge's
// counters, and the text itself.
#include "pil_summary.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "bridge_counters.hpp"
#include "machine_load.hpp"

namespace duet::cli {
namespace {

model::Recording tilt_recording() {
  model::Recording recording;
  recording.names = {"x_m", "theta_deg"};
  recording.units = {"m", "deg"};
  recording.time_s = {0.0, 0.5, 1.0, 1.5};
  recording.columns = {{0, 0, 0, 0}, {5, -3, 1, -1}};
  return recording;
}

TEST(PilSummary, TiltStatisticsOverTheWholeRunAndFromTheRelease) {
  const auto whole = tilt_statistics(tilt_recording(), 0);
  ASSERT_TRUE(whole);
  EXPECT_EQ(whole->samples, 4U);
  EXPECT_DOUBLE_EQ(whole->mean_deg, 0.5);
  EXPECT_DOUBLE_EQ(whole->rms_deg, 3.0);  // sqrt((25 + 9 + 1 + 1) / 4)
  EXPECT_DOUBLE_EQ(whole->largest_abs_deg, 5);

  const auto released = tilt_statistics(tilt_recording(), 1.0);  // from the row at 1.0 on
  ASSERT_TRUE(released);
  EXPECT_EQ(released->samples, 2U);
  EXPECT_DOUBLE_EQ(released->mean_deg, 0);
  EXPECT_DOUBLE_EQ(released->rms_deg, 1);
  EXPECT_DOUBLE_EQ(released->largest_abs_deg, 1);
  EXPECT_EQ(released->from_s, 1.0);

  EXPECT_FALSE(tilt_statistics(tilt_recording(), 2.0));  // no row that late
  model::Recording no_tilt = tilt_recording();
  no_tilt.names[1] = "v_m_s";
  EXPECT_FALSE(tilt_statistics(no_tilt, 0));
  EXPECT_FALSE(tilt_statistics(model::Recording{}, 0));
}

TEST(PilSummary, InstructionsFromTimerCycles) {
  // A 25 MHz timer tick is 40 ns; at shift 2 an instruction is 4 ns: 10 instructions a tick.
  EXPECT_EQ(instructions_from_cycles(150, 2), 1500);
  EXPECT_EQ(instructions_from_cycles(150, 0), 6000);
  EXPECT_EQ(instructions_from_cycles(1, 3), 5);
  EXPECT_EQ(estimated_us_at_209_mhz(20900), 100);  // the thesis' 99.8 us step, about 20,900 cycles
}

TEST(PilSummary, TheBridgesCountersFromItsLastWords) {
  const std::string output =
      "duet-bridge: channel unix:/tmp/x/xcp.sock: cannot open (No such file or directory); retrying\n"
      "duet-bridge: WebSocket clients on 127.0.0.1:8765\n"
      "duet-bridge: stopped; channel open, master none; frames to master 12 (340 bytes), to slave 6 (60 bytes); DAQ "
      "frames dropped 2; garbage bytes 0; channel opened 1 times; masters served 3, refused 0; latency mean 80 us, "
      "max 140 us; application channel {\"type\":\"status\"}\n";
  const auto traffic = parse_bridge_counters(output);
  ASSERT_TRUE(traffic);
  EXPECT_EQ(traffic->frames_to_master, 12U);
  EXPECT_EQ(traffic->bytes_to_master, 340U);
  EXPECT_EQ(traffic->frames_to_slave, 6U);
  EXPECT_EQ(traffic->bytes_to_slave, 60U);
  EXPECT_EQ(traffic->daq_frames_dropped, 2U);
  EXPECT_EQ(traffic->masters_served, 3U);

  EXPECT_FALSE(parse_bridge_counters(""));
  EXPECT_FALSE(parse_bridge_counters("duet-bridge: cannot listen on 127.0.0.1:5555: Address already in use\n"));
  EXPECT_FALSE(parse_bridge_counters("duet-bridge: stopped; frames to master many\n"));
}

TEST(PilSummary, TheWholeText) {
  PilRun run;
  run.lock_step = false;
  run.icount_shift = 2;
  run.model_time_s = 3;
  run.wall_s = 2;
  run.session = link::ServeSummary{};
  run.session->ticks = 3000;
  run.session->writes = 6000;
  run.session->reads = 3000;
  run.session->last_tick_s = 3;
  link::PacingReport& pacing = run.session->pacing;
  pacing.first_second.ticks = 1000;
  pacing.first_second.late = 2;
  pacing.first_second.worst = std::chrono::microseconds{1500};
  pacing.after_first_second.ticks = 2000;
  pacing.after_first_second.histogram[0] = 2000;
  pacing.busy_model_s = 2;
  pacing.busy_wall = std::chrono::milliseconds{1200};
  pacing.longest_busy = std::chrono::milliseconds{3};
  run.machine = MachineLoad{2, 0.1};
  run.tilt = TiltStatistics{0, 3000, 0.5, 3, 5};
  run.tilt_after_release = TiltStatistics{2, 1000, 0, 1, 1};
  take(run.firmware, parse_console_line("duet-status time_s=3 ticks=3000 busy_ppm=123456 overruns=1"));
  take(run.firmware, parse_console_line("duet-task index=0 name=step_rate_1 activations=3000 overruns=1 "
                                        "min_cycles=100 mean_cycles=150 max_cycles=2090"));
  take(run.firmware, parse_console_line("duet-task index=1 name=t activations=30 overruns=0 min_cycles=1 "
                                        "mean_cycles=2 max_cycles=3"));
  take(run.firmware, parse_console_line("duet-lost xcp_responses=0 daq_samples=7 telemetry_samples=1"));
  run.xcp = XcpTraffic{12, 340, 6, 60, 0, 1};
  EXPECT_EQ(format_summary(run),
            "summary\n"
            "  run       3.000 s of model time in 2.000 s of wall time: 1.50 x real time (real time)\n"
            "  pacing    after the first second 0 of 2,000 ticks (0.00 %) were more than 1 ms late (allowed: 1 %)\n"
            "            99 % within 0.1 ms\n"
            "            the first second (start-up): 2 of 1,000 ticks more than 1 ms late, the latest 1.5 ms\n"
            "            without the waits QEMU, the firmware, the link and the plant went 1.67 x real time; the "
            "longest tick 3.0 ms\n"
            "            other programs kept 0.1 of the machine's 2 processors busy\n"
            "  tilt      whole run: mean 0.50 deg, RMS 3.00 deg, largest |theta| 5.00 deg\n"
            "            from the release at 2.000 s: mean 0.00 deg, RMS 1.00 deg, largest |theta| 1.00 deg\n"
            "  link      3000 ticks, 0 interrupts, 6000 writes, 3000 reads\n"
            "  firmware  3000 ticks, 1 overruns, core load 12.35 %\n"
            "  tasks     instructions at -icount shift=2; us: an ESTIMATE for a 209 MHz core at one instruction per "
            "cycle\n"
            "            task        activations  overruns  mean instr  max instr  max us (est.)\n"
            "            step_rate_1        3000         1        1500      20900         100.00\n"
            "            t                    30         0          20         30           0.14\n"
            "  lost      7 daq_samples, 1 telemetry_samples (the firmware's channels)\n"
            "  xcp       6 frames to the slave (60 bytes), 12 to the master (340 bytes), 0 DAQ frames dropped, 1 "
            "masters served\n");
}

TEST(PilSummary, EveryDisturbanceWithItsExactModelTime) {
  PilRun run;
  run.bridge = false;
  run.offered = {{"push", "", {{"force_n", "N", -50, 50, 5}, {"duration_s", "s", 0.001, 1, 0.05}}},
                 {"restart", "", {}}};
  run.disturbances = {{{"push", {-7.5, 0.05}}, 9 * 0.001}, {{"restart", {}}, 20.001}};
  const std::string text = format_summary(run);
  EXPECT_NE(text.find("  link      the firmware never connected\n"
                      "  disturbed 2 times through the plant's control endpoint:\n"
                      "            push force_n=-7.5 duration_s=0.05 at 0.009000000000000001 s\n"
                      "            restart at 20.001 s\n"
                      "  firmware  "),
            std::string::npos)
      << text;
}

// A real-time run whose ticks after the first second were late: 3 % of 9,000, in 30 stretches.
PilRun late_run(double loop_speed, double others_busy) {
  PilRun run;
  run.model_time_s = 10;
  run.wall_s = 10;
  run.session = link::ServeSummary{};
  link::PacingReport& pacing = run.session->pacing;
  pacing.first_second.ticks = 1000;
  pacing.after_first_second.ticks = 9000;
  pacing.after_first_second.late = 270;
  pacing.after_first_second.worst = std::chrono::microseconds{12'340};
  pacing.after_first_second.late_stretches = 30;
  pacing.after_first_second.longest_stretch = 15;
  pacing.after_first_second.histogram[0] = 8700;
  pacing.after_first_second.histogram[3] = 200;
  pacing.after_first_second.histogram[5] = 100;
  pacing.busy_model_s = 9;
  pacing.busy_wall =
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>{9 / loop_speed});
  pacing.longest_busy = std::chrono::microseconds{13'000};
  run.machine = MachineLoad{2, others_busy};
  return run;
}

// The pacing lines of a summary: from its line "  pacing" to the line after them.
std::string pacing_lines(const std::string& summary) {
  const std::size_t begin = summary.find("  pacing");
  const std::size_t end = summary.find("\n  tilt", begin) != std::string::npos ? summary.find("\n  tilt", begin)
                                                                               : summary.find("\n  link", begin);
  return summary.substr(begin, end + 1 - begin);
}

TEST(PilSummary, TooManyLateTicksFromStallsOnABusyMachineSayWhy) {
  EXPECT_EQ(pacing_lines(format_summary(late_run(1.5, 1.8))),
            "  pacing    after the first second 270 of 9,000 ticks (3.00 %) were more than 1 ms late (allowed: 1 %), "
            "the latest 12.3 ms\n"
            "            99 % within 10.0 ms; late in 30 stretches, the longest 15 ticks (each a fall behind, then "
            "catching up)\n"
            "            the first second (start-up): 0 of 1,000 ticks more than 1 ms late\n"
            "            without the waits QEMU, the firmware, the link and the plant went 1.50 x real time; the "
            "longest tick 13.0 ms\n"
            "            why: stalls: ticks that took long (the longest 13.0 ms) left the run behind, and at 1.50 x "
            "real time it caught up 0.50 s a second\n"
            "                 other programs kept 1.8 of the machine's 2 processors busy: QEMU and the plant got "
            "theirs late\n");
}

TEST(PilSummary, AnEmulatorSlowerThanRealTimeIsTheReason) {
  const std::string lines = pacing_lines(format_summary(late_run(0.8, 0.2)));
  EXPECT_NE(
      lines.find("            why: they went only 0.80 x real time: the emulator is slower than the robot's time, "
                 "and each tick falls further behind\n"
                 "                 other programs kept 0.2 of the machine's 2 processors busy\n"),
      std::string::npos)
      << lines;
}

TEST(PilSummary, LateTicksWithinTheAllowanceNeedNoReason) {
  PilRun run = late_run(1.5, 1.8);
  run.session->pacing.after_first_second.late = 90;  // 1 %
  const std::string lines = pacing_lines(format_summary(run));
  EXPECT_NE(lines.find("90 of 9,000 ticks (1.00 %)"), std::string::npos) << lines;
  EXPECT_EQ(lines.find("why"), std::string::npos) << lines;
}

TEST(PilSummary, ARunWithinItsFirstSecondIsNotJudged) {
  PilRun run = late_run(1.5, 0);
  run.session->pacing.after_first_second = {};
  run.session->pacing.busy_wall = {};
  run.machine.reset();
  EXPECT_EQ(pacing_lines(format_summary(run)),
            "  pacing    the run ended within its first second (start-up), which is not judged\n"
            "            the first second (start-up): 0 of 1,000 ticks more than 1 ms late\n");
}

TEST(PilSummary, TheMachinesBusyTimeFromProcStat) {
  // user nice system idle iowait irq softirq steal guest guest_nice
  const std::string text =
      "cpu  100 20 30 5000 7 1 2 4 50 0\n"
      "cpu0 50 10 15 2500 3 0 1 2 25 0\n"
      "intr 12345\n";
  const auto busy = busy_seconds_from_proc_stat(text, 100);
  ASSERT_TRUE(busy);
  EXPECT_DOUBLE_EQ(*busy, (100 + 20 + 30 + 1 + 2 + 4) / 100.0);  // guest time is within user already
  EXPECT_FALSE(busy_seconds_from_proc_stat("cpu0 1 2 3 4 5 6 7 8\n", 100));
  EXPECT_FALSE(busy_seconds_from_proc_stat("cpu  1 2 3\n", 100));
  EXPECT_FALSE(busy_seconds_from_proc_stat(text, 0));
}

TEST(PilSummary, WhatIsMissingIsSaid) {
  PilRun run;
  run.lock_step = true;
  run.bridge = false;
  EXPECT_EQ(format_summary(run),
            "summary\n"
            "  run       0.000 s of model time in 0.000 s of wall time (lock-step)\n"
            "  link      the firmware never connected\n"
            "  firmware  said nothing on its console (no duet-status line)\n"
            "  xcp       no bridge (--no-bridge)\n");
  run.bridge = true;
  EXPECT_NE(format_summary(run).find("  xcp       the bridge did not report its counters\n"), std::string::npos);
}

// With --signal, what the firmware's recording got, after the bridge's counters (without it, no line: above).
TEST(PilSummary, TheFirmwaresSignalsRecorded) {
  PilRun run;
  run.daq = "recorded 9911 samples of 1 signals on event 'rate 1' (0 overloads, 0 lost packets, 0 discarded)";
  EXPECT_TRUE(
      format_summary(run).ends_with("  xcp       the bridge did not report its counters\n"
                                    "  daq       recorded 9911 samples of 1 signals on event 'rate 1' (0 "
                                    "overloads, 0 lost packets, 0 discarded)\n"))
      << format_summary(run);
}

}  // namespace
}  // namespace duet::cli
