// Importing the hand-written test FMUs (src/fmi/testing): the analytic responses of both FMI versions, a stop
// request and a failure with their times and messages, and every refusal with its exact message.
#include "duet/fmi/imported_fmu.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "duet/fmi/archive_writer.hpp"
#include "duet/support/temporary_folder.hpp"

namespace duet::fmi {
namespace {

const std::filesystem::path fmus = DUET_TEST_FMU_DIR;

std::unique_ptr<ImportedFmu> open_fmu(const std::string& name, std::vector<std::string>& log) {
  auto opened = ImportedFmu::open(fmus / name, [&log](std::string_view line) { log.emplace_back(line); });
  EXPECT_TRUE(opened) << opened.error();
  return opened ? std::move(opened).value() : nullptr;
}

std::string refusal(const std::filesystem::path& file) {
  auto opened = ImportedFmu::open(file, nullptr);
  EXPECT_FALSE(opened);
  return opened ? "" : opened.error();
}

double get(ImportedFmu& fmu, const std::string& name) {
  const Variable* variable = fmu.variable(name);
  EXPECT_NE(variable, nullptr) << name;
  auto value = fmu.get(*variable);
  EXPECT_TRUE(value) << value.error();
  return value ? value.value() : NAN;
}

void set(ImportedFmu& fmu, const std::string& name, double value) {
  auto done = fmu.set(*fmu.variable(name), value);
  EXPECT_TRUE(done) << done.error();
}

class BothVersions : public ::testing::TestWithParam<int> {
 protected:
  [[nodiscard]] std::string file(const std::string& model) const {
    return model + "_fmi" + std::to_string(GetParam()) + ".fmu";
  }
  std::vector<std::string> log;
};

// y_n = k·u·(1 - a^n), a = exp(-h/T): the lag's exact discrete response to a step of u.
TEST_P(BothVersions, FirstOrderLagGivesTheDiscreteStepResponse) {
  auto fmu = open_fmu(file("FirstOrderLag"), log);
  ASSERT_TRUE(fmu);
  EXPECT_EQ(fmu->description().version, GetParam() == 2 ? FmiVersion::v2 : FmiVersion::v3);
  set(*fmu, "T", 0.25);  // a parameter before initialisation
  const double h = 0.01;
  ASSERT_TRUE(fmu->initialize(0.0, h, [&fmu] { return fmu->set(*fmu->variable("u"), 1.5); }).ok());
  EXPECT_EQ(get(*fmu, "y"), 0.0);
  const double a = std::exp(-h / 0.25);
  for (int n = 1; n <= 100; ++n) {
    ASSERT_TRUE(fmu->advance_to(n * h).ok());
    EXPECT_NEAR(get(*fmu, "y"), 2.0 * 1.5 * (1.0 - std::pow(a, n)), 1e-12) << "step " << n;
  }
  EXPECT_EQ(fmu->steps(), 100u);
  EXPECT_DOUBLE_EQ(fmu->time(), 1.0);
  EXPECT_FALSE(fmu->stop_request());
  EXPECT_TRUE(log.empty());
}

// x = a·t²/2, v = a·t, exactly at every communication point, whatever the step's rounding.
TEST_P(BothVersions, DoubleIntegratorGivesTheParabola) {
  auto fmu = open_fmu(file("DoubleIntegrator"), log);
  ASSERT_TRUE(fmu);
  ASSERT_TRUE(fmu->initialize(0.0, 0.001, nullptr).ok());
  set(*fmu, "a", 3.0);
  ASSERT_TRUE(fmu->advance_to(0.5).ok());
  EXPECT_EQ(fmu->steps(), 500u);
  EXPECT_NEAR(get(*fmu, "x"), 3.0 * 0.5 * 0.5 / 2, 1e-12);
  EXPECT_NEAR(get(*fmu, "v"), 3.0 * 0.5, 1e-12);
  ASSERT_TRUE(fmu->advance_to(0.5 + 1e-12).ok());  // not yet the next point
  EXPECT_EQ(fmu->steps(), 500u);
}

TEST_P(BothVersions, TerminatingFmusRequestIsReportedWithItsTime) {
  auto fmu = open_fmu(file("Terminating"), log);
  ASSERT_TRUE(fmu);
  set(*fmu, "stop_at", 0.3);
  ASSERT_TRUE(fmu->initialize(0.0, 0.1, nullptr).ok());
  ASSERT_TRUE(fmu->advance_to(1.0).ok());
  ASSERT_TRUE(fmu->stop_request());
  EXPECT_EQ(*fmu->stop_request(), "Terminating asked to stop at t = 0.3 s");
  EXPECT_EQ(fmu->steps(), 3u);
  ASSERT_TRUE(fmu->advance_to(2.0).ok());  // no step after the request
  EXPECT_EQ(fmu->steps(), 3u);
}

TEST_P(BothVersions, FailingFmusErrorIsReportedWithItsTimeAndMessage) {
  auto fmu = open_fmu(file("Failing"), log);
  ASSERT_TRUE(fmu);
  ASSERT_TRUE(fmu->initialize(0.0, 0.1, nullptr).ok());
  auto advanced = fmu->advance_to(1.0);
  ASSERT_FALSE(advanced);
  const std::string call = GetParam() == 2 ? "fmi2DoStep" : "fmi3DoStep";
  EXPECT_EQ(advanced.error(), "Failing at t = 0.4 s: " + call + " returned Error: The model failed in this step");
  ASSERT_EQ(log.size(), 1u);
  EXPECT_EQ(log[0], "Failing: Error: The model failed in this step");  // forwarded as the FMU logged it
  EXPECT_EQ(fmu->steps(), 4u);
  EXPECT_EQ(fmu->advance_to(2.0).error(), advanced.error());  // and no call after the error
  EXPECT_EQ(fmu->get(*fmu->variable("y")).error(), "Failing failed before: duet calls it no more");
}

INSTANTIATE_TEST_SUITE_P(Fmi, BothVersions, ::testing::Values(2, 3),
                         [](const auto& version) { return "fmi" + std::to_string(version.param); });

TEST(ImportedFmu, RefusesBrokenFmusWithTheReason) {
  EXPECT_EQ(refusal(fmus / "Malformed.fmu"),
            (fmus / "Malformed.fmu").string() +
                ": modelDescription.xml:2: <fmiModelDescription> has no instantiationToken attribute");
  EXPECT_EQ(refusal(fmus / "NoBinary.fmu"), (fmus / "NoBinary.fmu").string() +
                                                ": no binaries/x86_64-linux/FirstOrderLag.so: the FMU has no library "
                                                "for Linux x86_64 (FMI 3.0), so duet cannot run it");
  EXPECT_EQ(refusal(fmus / "NoDescription.fmu"),
            (fmus / "NoDescription.fmu").string() + ": no modelDescription.xml at the archive's root");
  EXPECT_EQ(refusal(fmus / "PathTraversal.fmu"),
            (fmus / "PathTraversal.fmu").string() +
                ": entry \"../evil\": '..' in the path (it would leave the folder it is unpacked into)");
  EXPECT_EQ(refusal(fmus / "MissingSymbol.fmu"),
            (fmus / "MissingSymbol.fmu").string() +
                ": binaries/x86_64-linux/FirstOrderLag.so: the library lacks fmi3InstantiateCoSimulation, "
                "fmi3FreeInstance, fmi3EnterInitializationMode, fmi3ExitInitializationMode, fmi3Terminate, fmi3DoStep, "
                "fmi3GetFloat32, fmi3SetFloat32, fmi3GetFloat64, fmi3SetFloat64, fmi3GetInt8, fmi3SetInt8, "
                "fmi3GetUInt8, fmi3SetUInt8, fmi3GetInt16, fmi3SetInt16, fmi3GetUInt16, fmi3SetUInt16, fmi3GetInt32, "
                "fmi3SetInt32, fmi3GetUInt32, fmi3SetUInt32, fmi3GetInt64, fmi3SetInt64, fmi3GetUInt64, "
                "fmi3SetUInt64, fmi3GetBoolean, fmi3SetBoolean, which duet calls");
}

TEST(ImportedFmu, RefusesAModelExchangeOnlyFmu) {
  auto folder = TemporaryFolder::make("duet-import-test-").value();
  const std::filesystem::path file = folder.path() / "Exchange.fmu";
  const std::vector<ArchiveInput> inputs = {
      {"modelDescription.xml", std::filesystem::path{DUET_FMI_TESTING_DIR} / "malformed/no_co_simulation.xml"}};
  ASSERT_TRUE(write_archive(file, inputs).ok());
  EXPECT_EQ(refusal(file),
            file.string() + ": modelDescription.xml:2: no <CoSimulation> element: duet runs co-simulation FMUs only");
}

TEST(ImportedFmu, KeepsToOneInstanceWhenTheFmuAsks) {
  std::vector<std::string> log;
  {
    auto first = open_fmu("FirstOrderLag_only_once.fmu", log);
    ASSERT_TRUE(first);
    const std::filesystem::path file = fmus / "FirstOrderLag_only_once.fmu";
    EXPECT_EQ(refusal(file), file.string() +
                                 ": FirstOrderLag can be instantiated only once per process "
                                 "(canBeInstantiatedOnlyOncePerProcess), and an instance is alive");
    auto other = open_fmu("FirstOrderLag_fmi3.fmu", log);  // another FMU is not concerned
    EXPECT_TRUE(other);
  }
  EXPECT_TRUE(open_fmu("FirstOrderLag_only_once.fmu", log));  // the first one gone, a new one may come
}

TEST(ImportedFmu, TwoInstancesOfOneFmuAreIndependent) {
  std::vector<std::string> log;
  auto slow = open_fmu("FirstOrderLag_fmi2.fmu", log);
  auto fast = open_fmu("FirstOrderLag_fmi2.fmu", log);
  ASSERT_TRUE(slow && fast);
  set(*fast, "T", 0.1);
  ASSERT_TRUE(slow->initialize(0.0, 0.1, [&slow] { return slow->set(*slow->variable("u"), 1.0); }).ok());
  ASSERT_TRUE(fast->initialize(0.0, 0.1, [&fast] { return fast->set(*fast->variable("u"), 1.0); }).ok());
  ASSERT_TRUE(slow->advance_to(0.1).ok());
  ASSERT_TRUE(fast->advance_to(0.1).ok());
  EXPECT_NEAR(get(*slow, "y"), 2.0 * (1 - std::exp(-0.1 / 0.5)), 1e-12);
  EXPECT_NEAR(get(*fast, "y"), 2.0 * (1 - std::exp(-1.0)), 1e-12);
}

TEST(ImportedFmu, StepsAtTheFixedInternalStepSeveralTimesPerPeriod) {
  std::vector<std::string> log;
  auto fmu = open_fmu("FirstOrderLag_fixed_step.fmu", log);
  ASSERT_TRUE(fmu);
  ASSERT_TRUE(fmu->initialize(0.0, 0.01, nullptr).ok());
  ASSERT_TRUE(fmu->advance_to(0.05).ok());
  EXPECT_EQ(fmu->steps(), 50u);  // ten steps of 1 ms per period of 10 ms

  auto misfit = open_fmu("FirstOrderLag_fixed_step.fmu", log);
  ASSERT_TRUE(misfit);
  EXPECT_EQ(misfit->initialize(0.0, 0.0025, nullptr).error(),
            "FirstOrderLag steps at its fixedInternalStepSize of 0.001 s, which does not divide the step of "
            "0.0025 s");
}

TEST(ImportedFmu, RefusesAValueTheVariableCannotHold) {
  std::vector<std::string> log;
  auto fmu = open_fmu("FirstOrderLag_fmi3.fmu", log);
  ASSERT_TRUE(fmu);
  Variable count{.name = "n", .value_reference = 9, .type = VariableType::int8};
  EXPECT_EQ(fmu->set(count, 300).error(), "n is Int8: 300.000000 is not one of its values");
  EXPECT_EQ(fmu->set(count, 1.5).error(), "n is Int8: 1.500000 is not one of its values");
}

}  // namespace
}  // namespace duet::fmi
