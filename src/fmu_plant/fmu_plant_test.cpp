// An FMU as a plant, driven the way a simulation drives it: advance to the tick's time, then the controller's
// reads and writes of resources.
#include "duet/fmu_plant/fmu_plant.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace duet::fmu_plant {
namespace {

const std::filesystem::path fmus = DUET_TEST_FMU_DIR;
const plant::RaiseInterrupt no_interrupts = [](std::string_view) {};

FmuMapping lag_mapping() { return read_fmu_mapping(DUET_FMU_PLANT_TESTING_DIR "/lag.connect.yaml").value(); }

std::unique_ptr<FmuPlant> load(const std::string& fmu, FmuMapping mapping, std::vector<std::string>* log = nullptr) {
  auto plant = FmuPlant::load({.fmu = fmus / fmu, .mapping = std::move(mapping), .log = [log](std::string_view line) {
                                 if (log != nullptr) log->emplace_back(line);
                               }});
  EXPECT_TRUE(plant) << plant.error();
  if (!plant) return nullptr;
  const Status started = plant.value()->start(0.01);
  EXPECT_TRUE(started) << started.error();
  return started ? std::move(plant).value() : nullptr;
}

class LagPlant : public ::testing::TestWithParam<std::string> {};

// The controller holds the duty at 0.8 from tick 0: the lag's output read at tick n is 2·0.8·(1 - a^n).
TEST_P(LagPlant, AnswersReadsWithTheStepResponse) {
  auto plant = load(GetParam(), lag_mapping());
  ASSERT_TRUE(plant);
  const double a = std::exp(-0.01 / 0.05);
  for (int tick = 0; tick <= 50; ++tick) {
    plant->advance(tick * 0.01, no_interrupts);
    double sample = -1;
    plant->read("adc:ADC1/6", {&sample, 1});
    EXPECT_NEAR(sample, 1.6 * (1 - std::pow(a, tick)), 1e-12) << "tick " << tick;
    const double duty = 0.8;
    plant->write("pwm:TIM1/1", {&duty, 1});
    plant->write("gpio:LED0", {&duty, 1});  // a resource the FMU does not take: ignored
  }
  EXPECT_FALSE(plant->halted());
  ASSERT_EQ(plant->observables().size(), 1u);
  EXPECT_EQ(plant->observables()[0].name, "y");
  double observed = 0;
  plant->observe({&observed, 1});
  EXPECT_NEAR(observed, 1.6 * (1 - std::pow(a, 50)), 1e-12);  // as at the last tick
}

INSTANTIATE_TEST_SUITE_P(Fmi, LagPlant, ::testing::Values("FirstOrderLag_fmi2.fmu", "FirstOrderLag_fmi3.fmu"));

TEST(FmuPlant, RecordsTheLocalsTheMappingAsksFor) {
  FmuMapping mapping = lag_mapping();
  mapping.observed = {"T", "y"};
  auto plant = load("FirstOrderLag_fmi3.fmu", mapping);
  ASSERT_TRUE(plant);
  ASSERT_EQ(plant->observables().size(), 2u);
  EXPECT_EQ(plant->observables()[1].name, "T");
  EXPECT_EQ(plant->observables()[1].unit, "s");
  std::array<double, 2> values{};
  plant->observe(values);
  EXPECT_EQ(values[1], 0.05);
}

TEST(FmuPlant, HaltsWhenTheFmuAsksToStop) {
  FmuMapping mapping{.file = "m.yaml"};
  ASSERT_TRUE(add_setting(mapping, "stop_at=0.05").ok());
  auto plant = load("Terminating_fmi3.fmu", mapping);
  ASSERT_TRUE(plant);
  for (int tick = 0; tick <= 10 && !plant->halted(); ++tick) plant->advance(tick * 0.01, no_interrupts);
  ASSERT_TRUE(plant->halted());
  EXPECT_FALSE(plant->halted()->failed);
  EXPECT_EQ(plant->halted()->reason, "Terminating asked to stop at t = 0.05 s");
}

TEST(FmuPlant, FailsWithTheFmusErrorAndForwardsItsLog) {
  std::vector<std::string> log;
  FmuMapping mapping{.file = "m.yaml"};
  ASSERT_TRUE(add_setting(mapping, "fail_at=0.03").ok());
  auto plant = load("Failing_fmi2.fmu", mapping, &log);
  ASSERT_TRUE(plant);
  for (int tick = 0; tick <= 10; ++tick) plant->advance(tick * 0.01, no_interrupts);
  ASSERT_TRUE(plant->halted());
  EXPECT_TRUE(plant->halted()->failed);
  EXPECT_EQ(plant->halted()->reason, "Failing at t = 0.02 s: fmi2DoStep returned Error: The model failed in this step");
  EXPECT_EQ(log, std::vector<std::string>{"Failing: Error: The model failed in this step"});
}

TEST(FmuPlant, FailsOnAReadNoOutputAnswers) {
  auto plant = load("FirstOrderLag_fmi3.fmu", lag_mapping());
  ASSERT_TRUE(plant);
  std::array<double, 2> samples{};
  plant->read("adc:ADC1/6", samples);
  ASSERT_TRUE(plant->halted());
  EXPECT_EQ(plant->halted()->reason, std::string{DUET_FMU_PLANT_TESTING_DIR} +
                                         "/lag.connect.yaml: the controller reads adc:ADC1/6 element 1, which no "
                                         "FMU output answers (under outputs)");
}

TEST(FmuPlant, RefusesAMappingThatDoesNotFitTheFmu) {
  auto plant = FmuPlant::load({.fmu = fmus / "DoubleIntegrator_fmi3.fmu", .mapping = lag_mapping()});
  ASSERT_FALSE(plant);
  EXPECT_EQ(plant.error(),
            std::string{DUET_FMU_PLANT_TESTING_DIR} + "/lag.connect.yaml:4: the FMU has no variable 'u'");
}

// Only the model knows its base period: the FMU is initialised when the simulation starts the plant, once.
TEST(FmuPlant, StepsOnlyOnceStartedAndStartsOnce) {
  auto loaded = FmuPlant::load({.fmu = fmus / "FirstOrderLag_fmi3.fmu", .mapping = lag_mapping()});
  ASSERT_TRUE(loaded) << loaded.error();
  FmuPlant& plant = *loaded.value();
  plant.advance(0.01, no_interrupts);
  ASSERT_TRUE(plant.halted());
  EXPECT_EQ(plant.halted()->reason, "the FMU plant was advanced before it was started");

  auto again = FmuPlant::load({.fmu = fmus / "FirstOrderLag_fmi3.fmu", .mapping = lag_mapping()});
  ASSERT_TRUE(again) << again.error();
  ASSERT_TRUE(again.value()->start(0.01));
  const Status twice = again.value()->start(0.01);
  ASSERT_FALSE(twice);
  EXPECT_EQ(twice.error(), "the FMU plant was started twice");
}

}  // namespace
}  // namespace duet::fmu_plant
