// `duet sim` and `duet gen` as a user types them: what they write, and how they refuse.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "duet/mdf4/reader.hpp"
#include "duet/plot/csv.hpp"
#include "duet/support/text_file.hpp"
#include "run_for_test.hpp"

namespace duet::cli {
namespace {

const std::string examples = std::string{DUET_SOURCE_DIR} + "/apps/";

class SimGen : public ::testing::Test {
 protected:
  void SetUp() override { std::filesystem::create_directories(folder); }
  void TearDown() override { std::filesystem::remove_all(folder); }
  [[nodiscard]] std::string in_folder(const std::string& name) const { return (folder / name).string(); }
  void write(const std::string& name, const std::string& text) const { std::ofstream{folder / name} << text; }
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("duet_sim_gen_" + std::to_string(::getpid()));
};

TEST_F(SimGen, SimWritesTheCsvAndThePlot) {
  const Outcome outcome = run({"sim", examples + "step_time/step_time.yaml", "--duration", "0.0005", "--csv",
                               in_folder("s.csv"), "--plot", in_folder("s.svg")});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.out, "simulated step_time for 0.0005 s (6 base ticks) against plant 'none'; wrote " +
                             in_folder("s.csv") + " (1 columns) and " + in_folder("s.svg") + "\n");
  EXPECT_EQ(read_text_file(in_folder("s.csv")).value(),
            "time_s,level\n0,1\n9.999999999999999e-05,0\n0.00019999999999999998,1\n3e-04,0\n"
            "0.00039999999999999996,1\n5e-04,0\n");
  EXPECT_NE(read_text_file(in_folder("s.svg")).value().find("<svg"), std::string::npos);
}

// --mdf: the signals in their model types (a single f32, a boolean and a uint8 u8, a uint32 u32) with their units
// and descriptions, the plant's quantities as doubles, the same values as the CSV.
TEST_F(SimGen, SimWritesAnMdfFileOfTheSignalsInTheirTypes) {
  const Outcome outcome = run({"sim", examples + "balbot/balbot.yaml", "--plant", "balbot", "--duration", "0.01", "-s",
                               "theta", "-s", "stop", "-s", "robot_state", "-s", "requests_sent", "--csv",
                               in_folder("b.csv"), "--mdf", in_folder("b.mf4"), "--no-plot"});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_NE(outcome.out.find("wrote " + in_folder("b.csv") + " and " + in_folder("b.mf4")), std::string::npos)
      << outcome.out;
  auto reader = mdf4::Reader::open(in_folder("b.mf4"));
  ASSERT_TRUE(reader.ok()) << reader.error();
  ASSERT_EQ(reader.value().info().groups.size(), 1U);
  const mdf4::GroupInfo& group = reader.value().info().groups[0];
  EXPECT_EQ(group.name, "base period 1000 us");
  ASSERT_GT(group.channels.size(), 5U);
  const std::vector<std::string> names{"time", "theta", "stop", "robot_state", "requests_sent"};
  const std::vector<std::uint32_t> bits{64, 32, 8, 8, 32};
  for (std::size_t k = 0; k < names.size(); ++k) {
    EXPECT_EQ(group.channels[k].name, names[k]);
    EXPECT_EQ(group.channels[k].bit_count, bits[k]) << names[k];
  }
  EXPECT_EQ(group.channels[1].unit, "deg");
  EXPECT_EQ(group.channels[1].comment, "tilt, Kalman-filtered (theta filtered)");
  EXPECT_EQ(group.channels[1].data_type, 4);  // float
  EXPECT_TRUE(group.channels[5].name.starts_with("plant.")) << group.channels[5].name;
  EXPECT_EQ(group.channels[5].bit_count, 64U);
  // Every value as the CSV has it (the CSV writes numbers that read back as the same doubles).
  auto csv = plot::read_csv(read_text_file(in_folder("b.csv")).value(), "b.csv");
  ASSERT_TRUE(csv.ok()) << csv.error();
  std::size_t row = 0;
  const Status read = reader.value().for_each_record(0, [&](const mdf4::Record& record) {
    ASSERT_LT(row, csv.value().time.size());
    EXPECT_EQ(record.time(), csv.value().time[row]);
    for (std::size_t column = 0; column < csv.value().series.size(); ++column) {
      EXPECT_EQ(mdf4::to_double(record.value(column + 1)), csv.value().series[column].values[row])
          << csv.value().series[column].name << " at row " << row;
    }
    ++row;
  });
  ASSERT_TRUE(read.ok()) << read.error();
  EXPECT_EQ(row, 11U);
}

TEST_F(SimGen, SimAgainstAPlantThatIsAModel) {
  const Outcome outcome =
      run({"sim", examples + "thermostat/thermostat.yaml", "--plant", examples + "thermostat/heater.yaml", "--duration",
           "2", "--csv", in_folder("t.csv"), "--no-plot"});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  const std::string csv = read_text_file(in_folder("t.csv")).value();
  // After 2 s the relay holds the room at the set point of 2000 counts, within a few.
  const std::string last = csv.substr(csv.rfind('\n', csv.size() - 2) + 1);
  const double sample = std::stod(last.substr(last.find(',') + 1));
  EXPECT_NEAR(sample, 2000, 10) << last;
}

// Issue #25's round trip: the thermostat's plant model exported as an FMU (3.0 and 2.0) and imported back as its
// plant closes the same loop, bit for bit, as the plant model itself (lock-step; the plant at its own 1 ms base
// period inside the thermostat's 10 ms steps either way).
TEST_F(SimGen, TheHeaterExportedAsAnFmuAndImportedBackClosesTheSameLoopBitForBit) {
  const std::string thermostat = examples + "thermostat/thermostat.yaml";
  Outcome outcome = run({"sim", thermostat, "--plant", examples + "thermostat/heater.yaml", "--duration", "5", "--csv",
                         in_folder("native.csv"), "--no-plot"});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  const std::string native = read_text_file(in_folder("native.csv")).value();
  ASSERT_EQ(native.substr(0, native.find('\n')), "time_s,sample,heating");
  ASSERT_NE(native.find(",0\n"), std::string::npos);  // the heating switches off and on: a loop worth comparing
  for (const std::string version : {"3", "2"}) {
    const std::string fmu = in_folder("heater" + version + ".fmu");
    outcome = run({"fmu", "export", examples + "thermostat/heater.yaml", "-o", fmu, "--fmi", version});
    ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
    const std::string csv = in_folder("fmu" + version + ".csv");
    outcome = run({"sim", thermostat, "--plant", fmu, "--connect", examples + "thermostat/heater.connect.yaml",
                   "--duration", "5", "--csv", csv, "--no-plot"});
    ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
    // The same rows, and beside them what the FMU shows of itself (its output, plant.adc:ADC1/6).
    std::istringstream native_rows{native};
    std::istringstream fmu_rows{read_text_file(csv).value()};
    std::size_t rows = 0;
    for (std::string expected, row; std::getline(native_rows, expected); ++rows) {
      ASSERT_TRUE(std::getline(fmu_rows, row)) << "FMI " << version << ": ends before " << expected;
      EXPECT_EQ(row.substr(0, expected.size() + 1), expected + ",") << "FMI " << version;
    }
    EXPECT_EQ(rows, 502U);
    std::string extra;
    EXPECT_FALSE(std::getline(fmu_rows, extra)) << extra;
  }
}

TEST_F(SimGen, SimAgainstAnFmu) {
  const std::string testing = std::string{DUET_SOURCE_DIR} + "/src/fmu_plant/testing/";
  const std::string fmus = std::string{DUET_TEST_FMU_DIR} + "/";
  const std::string controller = testing + "lag_controller.yaml";
  Outcome outcome =
      run({"sim", controller, "--plant", fmus + "FirstOrderLag_fmi3.fmu", "--connect", testing + "lag.connect.yaml",
           "--fmu-set", "k=3", "--duration", "0.1", "--csv", in_folder("lag.csv"), "--no-plot"});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.err, "");
  const std::string csv = read_text_file(in_folder("lag.csv")).value();
  ASSERT_EQ(csv.substr(0, csv.find('\n')), "time_s,sample,plant.y");
  // The duty of 50 set at tick 0 drives the lag from the step after: y_n = 3·50·(1 - exp(-n·0.01/0.05)).
  std::istringstream rows{csv.substr(csv.find('\n') + 1)};
  int tick = 0;
  for (std::string row; std::getline(rows, row); ++tick) {
    const double y = std::stod(row.substr(row.rfind(',') + 1));
    EXPECT_NEAR(y, 150.0 * (1 - std::exp(-tick * 0.2)), 1e-9) << row;
  }
  EXPECT_EQ(tick, 11);

  write("stop.yaml", "outputs:\n  - {variable: y, resource: \"adc:ADC1/6\"}\n");
  outcome = run({"sim", controller, "--plant", fmus + "Terminating_fmi2.fmu", "--connect", in_folder("stop.yaml"),
                 "--fmu-set", "stop_at=0.05", "--csv", in_folder("stop.csv"), "--no-plot"});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.err, "duet sim: the plant ended the run: Terminating asked to stop at t = 0.05 s\n");
  EXPECT_EQ(outcome.out.substr(0, outcome.out.find(';')),
            "simulated lag_controller for 0.05 s (6 base ticks) against plant '" + fmus + "Terminating_fmi2.fmu'");

  outcome = run({"sim", controller, "--plant", fmus + "Failing_fmi3.fmu", "--connect", in_folder("stop.yaml"),
                 "--fmu-set", "fail_at=0.05", "--no-plot", "--csv", in_folder("fail.csv")});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.err,
            "Failing: Error: The model failed in this step\n"
            "duet sim: the plant failed: Failing at t = 0.04 s: fmi3DoStep returned Error: The model failed in this "
            "step\n");

  outcome = run({"sim", controller, "--plant", fmus + "FirstOrderLag_fmi3.fmu"});
  EXPECT_EQ(outcome.exit_code, ExitCode::usage);
  EXPECT_EQ(outcome.err, "duet sim: an FMU as the plant needs --connect MAPPING.yaml\n");
  outcome = run({"sim", controller, "--connect", testing + "lag.connect.yaml"});
  EXPECT_EQ(outcome.exit_code, ExitCode::usage);
  EXPECT_EQ(outcome.err, "duet sim: --connect and --fmu-set are for an FMU as the plant (X.fmu)\n");
  outcome = run({"sim", controller, "--plant", fmus + "NoBinary.fmu", "--connect", testing + "lag.connect.yaml"});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.err, "duet sim: " + fmus +
                             "NoBinary.fmu: no binaries/x86_64-linux/FirstOrderLag.so: the FMU has no library for "
                             "Linux x86_64 (FMI 3.0), so duet cannot run it\n");
}

TEST_F(SimGen, SimRefusesWhatItCannotRun) {
  Outcome outcome = run({"sim", examples + "step_time/step_time.yaml", "--plant", "non"});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.err, "duet sim: unknown plant 'non' (did you mean 'none'?)\n");
  outcome = run({"sim", examples + "step_time/step_time.yaml", "--duration", "1000000", "--no-plot"});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.err,
            "duet sim: recording 1 columns for 10000000001 ticks is more than 100000000 values: simulate a shorter "
            "time, or record fewer signals (-s)\n");
  outcome = run({"sim", examples + "step_time/step_time.yaml", "-s", "levl", "--no-plot", "--csv", in_folder("x")});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_NE(outcome.err.find("'levl'"), std::string::npos) << outcome.err;
  write("broken.hpp",
        "template <typename I, typename O, typename S, typename P> void f(const I&, O&, S&, const P&) { x }\n");
  write("code.yaml",
        "duet_model: 1\nname: code\nbase_period_us: 1000\nblocks:\n"
        "  - {name: c, type: Code, function: f, file: broken.hpp, outputs: {y: {signal: y, type: single}}}\n");
  outcome = run({"sim", in_folder("code.yaml"), "--no-plot", "--csv", in_folder("c.csv")});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_NE(outcome.err.find("duet sim: the Code blocks did not compile:"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("broken.hpp"), std::string::npos) << outcome.err;
  write("heater.yaml", "duet_model: 1\nname: heater\nbase_period_us: 1000\nblocks:\n  - {name: g, type: Gian}\n");
  outcome = run({"sim", examples + "thermostat/thermostat.yaml", "--plant", in_folder("heater.yaml")});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_NE(outcome.err.find("unknown block type 'Gian' (did you mean 'Gain'?)"), std::string::npos) << outcome.err;
}

TEST_F(SimGen, GenWritesEveryFileAndKeepsUnchangedOnes) {
  const Outcome outcome = run({"gen", examples + "step_time/step_time.yaml", "-o", in_folder("out")});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.out, "generated step_time into " + in_folder("out") +
                             ": step_time.hpp step_time.cpp step_time_xcp.hpp step_time.a2l step_time.cmake\n");
  for (const char* name : {"step_time.hpp", "step_time.cpp", "step_time_xcp.hpp", "step_time.a2l", "step_time.cmake"}) {
    EXPECT_EQ(read_text_file(in_folder("out/") + name).value(),
              read_text_file(examples + "step_time/generated/" + name).value())
        << name;
  }
  const auto written = std::filesystem::last_write_time(in_folder("out/step_time.cpp"));
  ASSERT_EQ(run({"gen", examples + "step_time/step_time.yaml", "-o", in_folder("out")}).exit_code, ExitCode::success);
  EXPECT_EQ(std::filesystem::last_write_time(in_folder("out/step_time.cpp")), written);
}

// Double precision the model did not ask for is a warning, at its place; the code is generated all the same.
TEST_F(SimGen, GenWarnsWhereDoublePrecisionStarts) {
  write("wide.yaml",
        "duet_model: 1\nname: wide\nbase_period_us: 100\nblocks:\n"
        "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
        "  - {name: g, type: Gain, parameters: {k: 2}, inputs: {u: x}, outputs: {y: y}}\n");
  const Outcome outcome = run({"gen", in_folder("wide.yaml"), "-o", in_folder("out")});
  EXPECT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.err,
            in_folder("wide.yaml") +
                ":5:5: warning: block 'c' computes in double precision, which the Cortex-M4 does in "
                "software (give its type as single, or say 'precision: double' at the top of the model)\n");
  EXPECT_TRUE(std::filesystem::exists(in_folder("out") + "/wide.cpp"));
}

TEST_F(SimGen, GenRefusesAModelWithErrorsAndAFolderItCannotMake) {
  write("bad.yaml",
        "duet_model: 1\nname: bad\nbase_period_us: 100\nblocks:\n  - {name: g, type: Gain, inputs: {u: x}}\n");
  Outcome outcome = run({"gen", in_folder("bad.yaml"), "-o", in_folder("out")});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_NE(outcome.err.find("needs parameter 'k'"), std::string::npos) << outcome.err;
  EXPECT_FALSE(std::filesystem::exists(in_folder("out")));
  write("reserved.yaml",
        "duet_model: 1\nname: reserved\nbase_period_us: 100\nblocks:\n"
        "  - {name: c, type: Constant, parameters: {value: 1, type: single}, outputs: {y: i}}\n"
        "  - {name: g, type: Gain, parameters: {k: 2}, inputs: {u: i}, outputs: {y: x}}\n");
  outcome = run({"gen", in_folder("reserved.yaml"), "-o", in_folder("out")});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.err, "duet gen: " + in_folder("reserved.yaml") +
                             ": signal 'i' has a name that C++ or the generated code reserves: rename it\n");
  write("file", "");
  outcome = run({"gen", examples + "step_time/step_time.yaml", "-o", in_folder("file/out")});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_NE(outcome.err.find("duet gen: cannot create " + in_folder("file/out")), std::string::npos) << outcome.err;
}

TEST_F(SimGen, TasksMakeATaskFileForSched) {
  const std::string model = examples + "pid_demo/pid_demo.yaml";
  Outcome outcome = run({"model", "tasks", model, "--wcet", "step_rate_1=25"});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.err,
            "duet model tasks: task 'step_rate_10' needs its execution time: --wcet step_rate_10=MICROSECONDS (the "
            "executive measures it on the target: docs/EXECUTIVE.md)\n");
  EXPECT_EQ(run({"model", "tasks", model, "--wcet", "step_rate_2=1"}).err,
            "duet model tasks: the model has no task 'step_rate_2' (its tasks: step_rate_1, step_rate_10)\n");
  EXPECT_EQ(run({"model", "tasks", model, "--wcet", "step_rate_1"}).err,
            "duet model tasks: 'step_rate_1' is not TASK=MICROSECONDS\n");
  outcome = run({"model", "tasks", model, "--wcet", "step_rate_1=25", "--wcet", "step_rate_10=12"});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.out,
            "# The tasks of pid_demo for duet sched (docs/SCHEDULING.md), written by duet model tasks.\n"
            "core: {priority_bits: 4, sub_priority_bits: 0}\ntasks:\n"
            "  - {name: step_rate_1, source: base timer, period_us: 1000, wcet_us: 25, priority: {group: 1, sub: 0}}\n"
            "  - {name: step_rate_10, source: base timer, period_us: 10000, wcet_us: 12, priority: {group: 2, sub: "
            "0}}\n");
  write("tasks.yaml", outcome.out);
  outcome = run({"sched", in_folder("tasks.yaml")});
  EXPECT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_NE(outcome.out.find("step_rate_10        2.0     12.000    10000.0    10000.0     0.0000     0.0012     "
                             "0.0000     37.000"),
            std::string::npos)
      << outcome.out;
}

TEST_F(SimGen, TasksTakeTheTimesAndSectionsAFirmwareMeasured) {
  const std::string model = examples + "pid_demo/pid_demo.yaml";
  // A console as the firmware writes it: the latest line of each kind counts; 20 cycles a microsecond.
  write("console.txt",
        "booting\n"
        "duet-task index=0 name=rate_1 activations=10 overruns=0 min_cycles=1 mean_cycles=1 max_cycles=100\n"
        "duet-task index=1 name=rate_10 activations=1 overruns=0 min_cycles=1 mean_cycles=1 max_cycles=30\n"
        "duet-section ceiling=1 longest_cycles=5\n"
        "duet-task index=0 name=rate_1 activations=20 overruns=0 min_cycles=1 mean_cycles=1 max_cycles=500\n"
        "duet-section ceiling=2 longest_cycles=1\n");
  Outcome outcome = run({"model", "tasks", model, "--measured", in_folder("console.txt"), "--cycles-per-us", "20"});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.out,
            "# The tasks of pid_demo for duet sched (docs/SCHEDULING.md), written by duet model tasks.\n"
            "core: {priority_bits: 4, sub_priority_bits: 0, sections: [{ceiling: 1, longest_us: 0.25}, {ceiling: 2, "
            "longest_us: 0.05}]}\ntasks:\n"
            "  - {name: step_rate_1, source: base timer, period_us: 1000, wcet_us: 25, priority: {group: 1, sub: 0}}\n"
            "  - {name: step_rate_10, source: base timer, period_us: 10000, wcet_us: 1.5, priority: {group: 2, sub: "
            "0}}\n");
  // What is given wins; a time that is no whole number of picoseconds is rounded up.
  outcome = run({"model", "tasks", model, "--measured", in_folder("console.txt"), "--cycles-per-us", "3", "--wcet",
                 "step_rate_1=40", "--section", "2=3"});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_NE(outcome.out.find("sections: [{ceiling: 1, longest_us: 1.666667}, {ceiling: 2, longest_us: 3}]"),
            std::string::npos)
      << outcome.out;
  EXPECT_NE(outcome.out.find("wcet_us: 40,"), std::string::npos) << outcome.out;
  write("tasks.yaml", outcome.out);
  outcome = run({"sched", in_folder("tasks.yaml")});
  EXPECT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  // A section blocks the tasks at and below its ceiling only: group 1 sees the one at 1, group 2 both.
  EXPECT_NE(
      outcome.out.find("step_rate_1         1.0     40.000     1000.0     1000.0     0.0000     0.0400     1.6667"),
      std::string::npos)
      << outcome.out;
  EXPECT_NE(
      outcome.out.find("step_rate_10        2.0     10.000    10000.0    10000.0     0.0000     0.0010     3.0000"),
      std::string::npos)
      << outcome.out;

  EXPECT_EQ(run({"model", "tasks", model, "--measured", in_folder("console.txt")}).err,
            "duet model tasks: --measured needs --cycles-per-us above 0 (the rate of the cycles it reports)\n");
  EXPECT_EQ(run({"model", "tasks", model, "--measured", in_folder("none.txt"), "--cycles-per-us", "1"}).err,
            "duet model tasks: cannot read the console file '" + in_folder("none.txt") + "'\n");
  write("bad.txt", "duet-section ceiling=99 longest_cycles=1\n");
  EXPECT_EQ(run({"model", "tasks", model, "--measured", in_folder("bad.txt"), "--cycles-per-us", "1"}).err,
            "duet model tasks: " + in_folder("bad.txt") + ":1: duet-section: ceiling 99 is beyond 15\n");
  EXPECT_EQ(
      run({"model", "tasks", model, "--wcet", "step_rate_1=1", "--wcet", "step_rate_10=1", "--section", "x=1"}).err,
      "duet model tasks: 'x=1' is not GROUP=MICROSECONDS\n");
  EXPECT_EQ(
      run({"model", "tasks", model, "--wcet", "step_rate_1=1", "--wcet", "step_rate_10=1", "--section", "16=1"}).err,
      "duet model tasks: section ceiling 16: groups are 0 to 15\n");
}

}  // namespace
}  // namespace duet::cli
