// `duet mdf info` and `duet mdf export` as a user types them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "duet/mdf4/writer.hpp"
#include "run_for_test.hpp"

namespace duet::cli {
namespace {

class MdfCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    mdf4::FileSpec spec{.groups = {{.name = "rate 1", .comment = "", .channels = {}}}};
    spec.groups[0].channels = {{.name = "theta", .type = mdf4::ValueType::f32, .unit = "deg", .comment = "tilt"},
                               {.name = "mode", .type = mdf4::ValueType::u8, .unit = "", .comment = ""}};
    auto writer = mdf4::Writer::create(file, spec);
    ASSERT_TRUE(writer);
    ASSERT_TRUE(writer.value().append(0, 0.0, std::vector<mdf4::Value>{1.5f, std::uint8_t{2}}));
    ASSERT_TRUE(writer.value().append(0, 0.001, std::vector<mdf4::Value>{-0.25f, mdf4::Value{}}));
  }
  void TearDown() override {
    std::filesystem::remove(file);
    std::filesystem::remove(csv);
  }
  static std::string read(const std::string& path) {
    std::ostringstream text;
    text << std::ifstream{path}.rdbuf();
    return text.str();
  }
  const std::string folder =
      std::filesystem::temp_directory_path().string() + "/duet_mdf_" + std::to_string(::getpid()) + "_";
  const std::string file = folder + "run.mf4";
  const std::string csv = folder + "run.csv";
};

TEST_F(MdfCommand, InfoDescribesTheFile) {
  const Outcome outcome = run({"mdf", "info", file});
  EXPECT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.out.rfind(file + ": MDF 4.20, program \"duet\", finalised\n", 0), 0u) << outcome.out;
  EXPECT_NE(outcome.out.find("group 0 \"rate 1\": 2 samples, 0 to 0.001 s\n  time: f64 [s], master\n"
                             "  theta: f32 [deg] (tilt)\n  mode: u8\n"),
            std::string::npos)
      << outcome.out;
  EXPECT_EQ(outcome.err, "");
}

TEST_F(MdfCommand, ExportWritesCsv) {
  const Outcome outcome = run({"mdf", "export", file, "--csv", csv});
  EXPECT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.out, "wrote " + csv + ": 2 rows, 2 channels\n");
  EXPECT_EQ(read(csv), "time_s,theta,mode\n0,1.5,2\n0.001,-0.25,\n");
  EXPECT_EQ(run({"mdf", "export", file, "--csv", csv, "--channel", "mode"}).exit_code, ExitCode::success);
  EXPECT_EQ(read(csv), "time_s,mode\n0,2\n0.001,\n");
}

TEST_F(MdfCommand, ErrorsNameTheFileAndFail) {
  Outcome outcome = run({"mdf", "info", "/nonexistent.mf4"});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.err, "duet mdf info: /nonexistent.mf4: cannot open: No such file or directory\n");
  std::ofstream{csv} << "time_s,x\n" << std::string(80, '0') << '\n';
  outcome = run({"mdf", "info", csv});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.err, "duet mdf info: " + csv + ": not an MDF file (it starts with \"time_s,x\", not \"MDF\")\n");
  outcome = run({"mdf", "export", file, "--csv", csv, "--channel", "phi"});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.err, "duet mdf export: no channel 'phi' in the file (duet mdf info lists them)\n");
  EXPECT_FALSE(std::filesystem::exists(csv));  // nothing half-written left behind
  outcome = run({"mdf", "export", file, "--csv", "/nonexistent/out.csv"});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.err, "duet mdf export: /nonexistent/out.csv: cannot create\n");
}

TEST_F(MdfCommand, AWrongCommandLineIsAUsageError) {
  EXPECT_EQ(run({"mdf"}).exit_code, ExitCode::usage);
  EXPECT_EQ(run({"mdf", "info"}).exit_code, ExitCode::usage);
  EXPECT_EQ(run({"mdf", "export", file}).exit_code, ExitCode::usage);  // no --csv
  EXPECT_EQ(run({"mdf", "show", file}).exit_code, ExitCode::usage);
}

}  // namespace
}  // namespace duet::cli
