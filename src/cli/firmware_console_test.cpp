// The firmware's console lines under duet pil: the three kinds it reports with, free text, and garbage.
#include "firmware_console.hpp"

#include <gtest/gtest.h>

namespace duet::cli {
namespace {

template <typename Line>
Line parsed_as(std::string_view text) {
  const ConsoleLine line = parse_console_line(text);
  EXPECT_TRUE(std::holds_alternative<Line>(line)) << text;
  return std::holds_alternative<Line>(line) ? std::get<Line>(line) : Line{};
}

std::string problem_of(std::string_view text) { return parsed_as<MalformedLine>(text).problem; }

TEST(FirmwareConsole, TheLinesTheFirmwareReportsWith) {
  const FirmwareStatus status =
      parsed_as<FirmwareStatus>("duet-status time_s=1.000 ticks=1000 busy_ppm=123456 overruns=2");
  EXPECT_EQ(status.time_s, 1.0);
  EXPECT_EQ(status.ticks, 1000U);
  EXPECT_EQ(status.busy_ppm, 123456U);
  EXPECT_EQ(status.overruns, 2U);

  const FirmwareTask task = parsed_as<FirmwareTask>(
      "duet-task index=1 name=step_rate_1 activations=1000 overruns=0 min_cycles=120 mean_cycles=130 "
      "max_cycles=150\r");  // a UART's line end
  EXPECT_EQ(task.index, 1U);
  EXPECT_EQ(task.name, "step_rate_1");
  EXPECT_EQ(task.activations, 1000U);
  EXPECT_EQ(task.min_cycles, 120U);
  EXPECT_EQ(task.mean_cycles, 130U);
  EXPECT_EQ(task.max_cycles, 150U);

  const FirmwareLosses losses = parsed_as<FirmwareLosses>("duet-lost xcp_responses=0 daq_samples=7 telemetry=1");
  using Count = std::pair<std::string, std::uint64_t>;
  EXPECT_EQ(losses.counts, (std::vector<Count>{{"xcp_responses", 0}, {"daq_samples", 7}, {"telemetry", 1}}));
  EXPECT_EQ(problem_of("duet-lost daq_samples=many"), "duet-lost: 'daq_samples' is not a number: 'many'");

  const FirmwareSection section = parsed_as<FirmwareSection>("duet-section ceiling=9 longest_cycles=40");
  EXPECT_EQ(section.ceiling, 9U);
  EXPECT_EQ(section.longest_cycles, 40U);

  const FirmwareEnd end = parsed_as<FirmwareEnd>("duet-end reason=final_tick ticks=10000 overruns=0");
  EXPECT_EQ(end.reason, "final_tick");
  EXPECT_EQ(end.ticks, 10000U);
}

TEST(FirmwareConsole, FieldsInAnyOrderAndMoreThanAsked) {
  const FirmwareEnd end = parsed_as<FirmwareEnd>("duet-end  overruns=1 future=yes ticks=7   reason=button ");
  EXPECT_EQ(end.reason, "button");
  EXPECT_EQ(end.ticks, 7U);
  EXPECT_EQ(end.overruns, 1U);
}

TEST(FirmwareConsole, AnythingElseIsText) {
  for (const char* text : {"", "hello", "error: the MPU6500 did not answer", "duet-statusx ticks=1", "duet-", "duet",
                           "\x01\xff garbage \x7f", "DUET-STATUS time_s=1 ticks=1 busy_ppm=1 overruns=0"}) {
    EXPECT_EQ(parsed_as<ConsoleText>(text).text, text);
  }
}

TEST(FirmwareConsole, ReportLinesThatDoNotSayWhatTheyMustAreMalformed) {
  EXPECT_EQ(problem_of("duet-status"), "duet-status: no 'time_s'");
  EXPECT_EQ(problem_of("duet-status time_s=1 ticks=1 busy_ppm=1"), "duet-status: no 'overruns'");
  EXPECT_EQ(problem_of("duet-status time_s=1 ticks=-1 busy_ppm=1 overruns=0"),
            "duet-status: 'ticks' is not a number: '-1'");
  EXPECT_EQ(problem_of("duet-status time_s=1s ticks=1 busy_ppm=1 overruns=0"),
            "duet-status: 'time_s' is not a number: '1s'");
  EXPECT_EQ(problem_of("duet-status time_s= ticks=1 busy_ppm=1 overruns=0"), "duet-status: no 'time_s'");
  EXPECT_EQ(problem_of("duet-status time_s=1 time_s=2 ticks=1 busy_ppm=1 overruns=0"), "duet-status: 'time_s' twice");
  EXPECT_EQ(problem_of("duet-task index=0 activations=1 overruns=0 min_cycles=1 mean_cycles=1 max_cycles=1"),
            "duet-task: no 'name'");
  EXPECT_EQ(problem_of("duet-task index=999 name=x activations=1 overruns=0 min_cycles=1 mean_cycles=1 max_cycles=1"),
            "duet-task: index 999 is beyond 255");
  EXPECT_EQ(problem_of("duet-end ticks=99999999999999999999999 overruns=0 reason=x"),
            "duet-end: 'ticks' is not a number: '99999999999999999999999'");
  EXPECT_EQ(problem_of("duet-end \xff\xfe"), "duet-end: no 'reason'");
  EXPECT_EQ(problem_of("duet-section ceiling=16 longest_cycles=4"), "duet-section: ceiling 16 is beyond 15");
  EXPECT_EQ(problem_of("duet-section ceiling=3"), "duet-section: no 'longest_cycles'");
}

TEST(FirmwareConsole, TheReportKeepsTheLatestOfEach) {
  FirmwareReport report;
  for (const char* line : {"boot", "duet-status time_s=1 ticks=1000 busy_ppm=10 overruns=0",
                           "duet-task index=1 name=b activations=1 overruns=0 min_cycles=1 mean_cycles=1 max_cycles=1",
                           "duet-status time_s=2 ticks=2000 busy_ppm=20 overruns=1", "duet-status garbage",
                           "duet-task index=1 name=b activations=2 overruns=0 min_cycles=1 mean_cycles=1 max_cycles=3",
                           "duet-section ceiling=2 longest_cycles=7", "duet-section ceiling=2 longest_cycles=9",
                           "duet-end reason=final_tick ticks=2000 overruns=1"}) {
    take(report, parse_console_line(line));
  }
  ASSERT_TRUE(report.status);
  EXPECT_EQ(report.status->ticks, 2000U);
  ASSERT_EQ(report.tasks.size(), 2U);
  EXPECT_EQ(report.tasks[0].name, "");  // never reported
  EXPECT_EQ(report.tasks[1].activations, 2U);
  EXPECT_EQ(report.tasks[1].max_cycles, 3U);
  EXPECT_EQ(report.sections, (std::map<std::uint64_t, std::uint64_t>{{2, 9}}));
  ASSERT_TRUE(report.end);
  EXPECT_EQ(report.end->reason, "final_tick");
}

}  // namespace
}  // namespace duet::cli
