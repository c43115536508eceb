// `duet plant serve` as a user types it: command lines it refuses, and the program itself serving a firmware that
// connects over TCP (the program runs as a child process, its first line of output read to learn its port).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "duet/link/remote_plant.hpp"
#include "duet/link/stream.hpp"
#include "duet/link/tcp.hpp"
#include "duet/model/model_file.hpp"
#include "duet/model/model_plant.hpp"
#include "duet/model/program.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plot/csv.hpp"
#include "duet/support/text_file.hpp"
#include "run_for_test.hpp"

extern char** environ;  // NOLINT(readability-redundant-declaration): for posix_spawn

namespace duet::cli {
namespace {

using namespace std::chrono_literals;

TEST(PlantCommand, BadCommandLinesSayWhatIsWrong) {
  const Outcome unknown = run({"plant", "serve", "nonee"});
  EXPECT_EQ(unknown.exit_code, ExitCode::failure);
  EXPECT_EQ(unknown.err, "duet plant serve: unknown plant 'nonee' (did you mean 'none'?)\n");
  EXPECT_EQ(unknown.out, "");

  const Outcome no_port = run({"plant", "serve", "none", "--listen", "127.0.0.1"});
  EXPECT_EQ(no_port.exit_code, ExitCode::usage);
  EXPECT_NE(no_port.err.find("'127.0.0.1' is not HOST:PORT (no ':' before the port)"), std::string::npos)
      << no_port.err;

  const Outcome no_name = run({"plant", "serve"});
  EXPECT_EQ(no_name.exit_code, ExitCode::usage);
  EXPECT_NE(no_name.err.find("name is required"), std::string::npos) << no_name.err;

  const Outcome no_action = run({"plant"});
  EXPECT_EQ(no_action.exit_code, ExitCode::usage);

  const Outcome negative = run({"plant", "serve", "none", "--timeout", "-1"});
  EXPECT_EQ(negative.exit_code, ExitCode::usage);

  const Outcome scenario_for_none = run({"plant", "serve", "none", "--scenario", "robot.yaml"});
  EXPECT_EQ(scenario_for_none.exit_code, ExitCode::failure);
  EXPECT_EQ(scenario_for_none.err, "duet plant serve: --scenario is for the balbot plant; plant 'none' takes none\n");

  const Outcome unwritable = run({"plant", "serve", "none", "--csv", "/nonexistent/plant.csv"});
  EXPECT_EQ(unwritable.exit_code, ExitCode::failure);
  EXPECT_EQ(unwritable.err, "duet plant serve: cannot write /nonexistent/plant.csv\n");

  const Outcome missing_scenario = run({"plant", "serve", "balbot", "--scenario", "/nonexistent/robot.yaml"});
  EXPECT_EQ(missing_scenario.exit_code, ExitCode::failure);
  EXPECT_NE(missing_scenario.err.find("/nonexistent/robot.yaml"), std::string::npos) << missing_scenario.err;
}

TEST(PlantCommand, APortInUse) {
  auto taken = link::TcpListener::open({"127.0.0.1", 0});
  ASSERT_TRUE(taken.ok()) << taken.error();
  const std::string address = link::to_string(taken.value().address());
  const Outcome outcome = run({"plant", "serve", "none", "--listen", address});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.err, "duet plant serve: cannot listen on " + address + ": Address already in use\n");
}

// The program as a child process, its standard output and error on pipes.
class Child {
 public:
  explicit Child(const std::vector<std::string>& arguments) {
    int out[2] = {-1, -1};
    int err[2] = {-1, -1};
    if (::pipe2(out, O_CLOEXEC) != 0 || ::pipe2(err, O_CLOEXEC) != 0) return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, err[1], STDERR_FILENO);
    std::vector<std::string> words{DUET_PROGRAM};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    argv.reserve(words.size() + 1);
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    if (posix_spawn(&pid_, DUET_PROGRAM, &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
    ::close(out[1]);
    ::close(err[1]);
    output_ = std::make_unique<link::FdStream>(out[0], out[0], 20s);
    errors_ = std::make_unique<link::FdStream>(err[0], err[0], 20s);
  }
  ~Child() {
    if (pid_ > 0) (void)wait();
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  // One line of its standard output, without the newline.
  std::string line() { return read_line(*output_); }
  // One line of its standard error.
  std::string error_line() { return read_line(*errors_); }
  // Its exit code.
  int wait() {
    int status = 0;
    ::waitpid(std::exchange(pid_, -1), &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  [[nodiscard]] bool started() const { return pid_ > 0; }

 private:
  static std::string read_line(link::Stream& stream) {
    std::string text;
    std::uint8_t byte = 0;
    while (stream.read_exactly({&byte, 1}).ok() && byte != '\n') text += static_cast<char>(byte);
    return text;
  }

  pid_t pid_ = -1;
  std::unique_ptr<link::FdStream> output_;
  std::unique_ptr<link::FdStream> errors_;
};

// The address after `prefix` at the start of the child's next line.
link::HostPort address_in_line(Child& program, const std::string& prefix) {
  const std::string line = program.line();
  EXPECT_TRUE(line.starts_with(prefix)) << line;
  const std::string rest = line.substr(std::min(prefix.size(), line.size()));
  auto address = link::parse_host_port(rest.substr(0, rest.find(' ')));
  EXPECT_TRUE(address.ok()) << line;
  return address ? address.value() : link::HostPort{};
}

// Where the child listens, from its first line ("plant NAME listening on HOST:PORT"); for a plant that offers
// disturbances (the robot), the next line says where it takes them ("plant NAME control on HOST:PORT (...)").
link::HostPort listening_address(Child& program, const std::string& name) {
  const link::HostPort address = address_in_line(program, "plant " + name + " listening on ");
  if (name == "balbot") (void)address_in_line(program, "plant balbot control on ");
  return address;
}

TEST(PlantCommand, TheProgramServesOneFirmwareAndSaysHowItWent) {
  Child program{{"plant", "serve", "none", "--listen", "127.0.0.1:0", "--once"}};
  ASSERT_TRUE(program.started());
  const link::HostPort address = listening_address(program, "none");
  EXPECT_EQ(address.host, "127.0.0.1");
  auto stream = link::connect_tcp(address, 10s);
  ASSERT_TRUE(stream.ok()) << stream.error();
  auto connected = link::RemotePlant::connect(std::move(stream).value(), {link::LinkMode::lock_step, 2'000'000});
  ASSERT_TRUE(connected.ok()) << connected.error();
  link::RemotePlant& plant = *connected.value();
  const double duty = 0.75;
  plant.write("pwm:TIM1/1", {&duty, 1});
  plant.advance(0, {});
  double back = 0;
  plant.read("pwm:TIM1/1", {&back, 1});
  EXPECT_EQ(back, 0.75);  // the plant "none" answers what was written
  ASSERT_TRUE(plant.ok()) << plant.error();
  EXPECT_TRUE(plant.close().ok());
  const std::string served = program.line();
  EXPECT_TRUE(served.starts_with("served 127.0.0.1:")) << served;
  EXPECT_TRUE(served.ends_with(": 1 ticks, 0 interrupts, 1 writes, 1 reads (lock-step, base period 2000 us)"))
      << served;
  EXPECT_EQ(program.wait(), 0);
}

TEST(PlantCommand, TheRobotOfAScenario) {
  const std::filesystem::path scenario =
      std::filesystem::temp_directory_path() / ("duet_plant_serve_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream{scenario} << "initial_tilt_deg: 3\nnoise: false\n";
  Child program{{"plant", "serve", "balbot", "--scenario", scenario.string(), "--listen", ":0", "--once"}};
  ASSERT_TRUE(program.started());
  auto stream = link::connect_tcp(listening_address(program, "balbot"), 10s);
  ASSERT_TRUE(stream.ok()) << stream.error();
  auto connected = link::RemotePlant::connect(std::move(stream).value(), {link::LinkMode::lock_step, 1'000'000});
  ASSERT_TRUE(connected.ok()) << connected.error();
  for (int tick = 0; tick < 20; ++tick) connected.value()->advance(tick * 0.001, [](std::string_view) {});
  EXPECT_TRUE(connected.value()->ok()) << connected.value()->error();
  connected.value().reset();
  const std::string served = program.line();
  EXPECT_NE(served.find(": 20 ticks, "), std::string::npos) << served;
  EXPECT_EQ(program.wait(), 0);
  std::filesystem::remove(scenario);
}

TEST(PlantCommand, TheRobotsOwnQuantitiesATickAfterATickAsCsvAndPlot) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path();
  const std::string stem = "duet_plant_record_" + std::to_string(::getpid());
  const std::filesystem::path scenario = folder / (stem + ".yaml");
  const std::filesystem::path csv = folder / (stem + ".csv");
  const std::filesystem::path svg = folder / (stem + ".svg");
  std::ofstream{scenario} << "initial_tilt_deg: 3\nrelease_time_s: 1\nnoise: false\n";
  Child program{{"plant", "serve", "balbot", "--scenario", scenario.string(), "--listen", ":0", "--once", "--csv",
                 csv.string(), "--plot", svg.string()}};
  ASSERT_TRUE(program.started());
  auto stream = link::connect_tcp(listening_address(program, "balbot"), 10s);
  ASSERT_TRUE(stream.ok()) << stream.error();
  auto connected = link::RemotePlant::connect(std::move(stream).value(), {link::LinkMode::lock_step, 1'000'000});
  ASSERT_TRUE(connected.ok()) << connected.error();
  for (int tick = 0; tick < 30; ++tick) connected.value()->advance(tick * 0.001, [](std::string_view) {});
  EXPECT_TRUE(connected.value()->close().ok());
  EXPECT_NE(program.line().find(": 30 ticks, "), std::string::npos);
  EXPECT_EQ(program.wait(), 0);

  auto text = read_text_file(csv.string());
  ASSERT_TRUE(text.ok()) << text.error();
  EXPECT_TRUE(text.value().starts_with("time_s,theta_deg,theta_dot_deg_s,x_m,")) << text.value().substr(0, 100);
  auto recorded = plot::read_csv(text.value(), csv.string());
  ASSERT_TRUE(recorded.ok()) << recorded.error();
  ASSERT_EQ(recorded.value().time.size(), 30U);  // a row per TICK, at the TICK's time
  EXPECT_EQ(recorded.value().time[29], 29 * 0.001);
  const auto& series = recorded.value().series;
  const auto theta =
      std::find_if(series.begin(), series.end(), [](const auto& one) { return one.name == "theta_deg"; });
  ASSERT_NE(theta, series.end());
  EXPECT_EQ(theta->values.front(), 3.0);  // held at the scenario's tilt
  for (const char* name : {"left_drive", "wheel_rev_s", "wall_distance_m", "battery_v"}) {
    EXPECT_NE(std::find_if(series.begin(), series.end(), [name](const auto& one) { return one.name == name; }),
              series.end())
        << name;
  }
  auto plot = read_text_file(svg.string());
  ASSERT_TRUE(plot.ok()) << plot.error();
  EXPECT_NE(plot.value().find("<svg"), std::string::npos);
  EXPECT_NE(plot.value().find("theta_deg"), std::string::npos);
  for (const auto& path : {scenario, csv, svg}) std::filesystem::remove(path);
}

// A line of JSON from the plant-control endpoint.
nlohmann::json next_message(link::Stream& stream) {
  std::string text;
  std::uint8_t byte = 0;
  while (stream.read_exactly({&byte, 1}).ok() && byte != '\n') text += static_cast<char>(byte);
  return nlohmann::json::parse(text, nullptr, false);
}
void send_line(link::Stream& stream, const nlohmann::json& message) {
  const std::string text = message.dump() + "\n";
  EXPECT_TRUE(stream.write_all({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()}).ok());
}

TEST(PlantCommand, TheRobotTakesAPushWhileAFirmwareIsServedAtTheTimeOfItsNextTick) {
  Child program{{"plant", "serve", "balbot", "--listen", ":0", "--once", "--plant-control", "127.0.0.1:0"}};
  ASSERT_TRUE(program.started());
  const link::HostPort address = address_in_line(program, "plant balbot listening on ");
  const link::HostPort control_address = address_in_line(program, "plant balbot control on ");
  auto control = link::connect_tcp(control_address, 10s);
  ASSERT_TRUE(control.ok()) << control.error();
  EXPECT_EQ(next_message(*control.value())["plant"], "balbot");  // the description first
  send_line(*control.value(), {{"type", "plant"}, {"action", "push"}, {"id", 1}});
  EXPECT_EQ(next_message(*control.value())["error"], "the plant is not running (no firmware is connected to it)");

  auto stream = link::connect_tcp(address, 10s);
  ASSERT_TRUE(stream.ok()) << stream.error();
  auto connected = link::RemotePlant::connect(std::move(stream).value(), {link::LinkMode::lock_step, 1'000'000});
  ASSERT_TRUE(connected.ok()) << connected.error();
  connected.value()->advance(0, [](std::string_view) {});
  send_line(*control.value(), {{"type", "plant"}, {"action", "push"}, {"force_n", 3}, {"id", 2}});
  ::usleep(200'000);  // the request waits for the next tick
  connected.value()->advance(0.001, [](std::string_view) {});
  const nlohmann::json answer = next_message(*control.value());
  EXPECT_EQ(answer["id"], 2);
  EXPECT_EQ(answer["time_s"], 0.001) << answer.dump();
  EXPECT_EQ(answer["arguments"]["force_n"], 3.0);
  EXPECT_TRUE(connected.value()->close().ok());
  EXPECT_NE(program.line().find(": 2 ticks, "), std::string::npos);
  EXPECT_EQ(program.wait(), 0);
}

TEST(PlantCommand, AFirmwareThatBreaksTheLinkFailsTheSession) {
  Child program{{"plant", "serve", "none", "--listen", ":0", "--once"}};
  ASSERT_TRUE(program.started());
  auto stream = link::connect_tcp(listening_address(program, "none"), 10s);
  ASSERT_TRUE(stream.ok()) << stream.error();
  const std::array<std::uint8_t, 3> garbage{0x42, 0, 0};
  EXPECT_TRUE(stream.value()->write_all(garbage).ok());
  const std::string error = program.error_line();
  EXPECT_TRUE(error.starts_with("duet plant serve: 127.0.0.1:")) << error;
  EXPECT_TRUE(error.ends_with(": the firmware sent a bad frame (unknown frame kind 0x42) while awaiting HELLO"))
      << error;
  EXPECT_EQ(program.wait(), 1);
}

// The thermostat (apps/thermostat) in this process for 5 s, lock-step, against `plant`: its signals as CSV.
std::string thermostat_against(plant::Plant& plant) {
  auto model = model::load_model(std::string{DUET_SOURCE_DIR} + "/apps/thermostat/thermostat.yaml");
  EXPECT_TRUE(model) << model.error();
  if (!model) return {};
  const model::ProgramBuild build = model::build_program(model.value());
  EXPECT_TRUE(build.program);
  if (!build.program) return {};
  auto simulated = model::simulate(*build.program, plant, {.duration_s = 5, .record_plant = false});
  EXPECT_TRUE(simulated) << simulated.error();
  return simulated ? model::to_csv(simulated.value().recording) : std::string{};
}

// Issue #25, "the SIL paths that take a plant": the heater exported as an FMU and served by `duet plant serve`
// closes the thermostat's loop over the link bit for bit as the heater model does in the thermostat's own process.
// The FMU is initialised when the firmware's HELLO gives the base period (10 ms), and its log is the server's.
TEST(PlantCommand, AnFmuServedOverTheLinkClosesTheSameLoopAsThePlantModelInProcess) {
  const std::string examples = std::string{DUET_SOURCE_DIR} + "/apps/thermostat/";
  auto heater = model::ModelPlant::load(examples + "heater.yaml");
  ASSERT_TRUE(heater) << heater.error();
  const std::string native = thermostat_against(*heater.value());
  ASSERT_NE(native.find(",0\n"), std::string::npos);  // the heating switches: a loop worth comparing

  const std::string fmu =
      (std::filesystem::temp_directory_path() / ("duet_served_heater_" + std::to_string(::getpid()) + ".fmu")).string();
  const Outcome exported = run({"fmu", "export", examples + "heater.yaml", "-o", fmu});
  ASSERT_EQ(exported.exit_code, ExitCode::success) << exported.err;
  Child program{{"plant", "serve", fmu, "--connect", examples + "heater.connect.yaml", "--listen", ":0", "--once"}};
  ASSERT_TRUE(program.started());
  auto stream = link::connect_tcp(listening_address(program, fmu), 10s);
  ASSERT_TRUE(stream.ok()) << stream.error();
  auto connected = link::RemotePlant::connect(std::move(stream).value(), {link::LinkMode::lock_step, 10'000'000});
  ASSERT_TRUE(connected.ok()) << connected.error();
  EXPECT_EQ(thermostat_against(*connected.value()), native);
  ASSERT_TRUE(connected.value()->ok()) << connected.value()->error();
  EXPECT_TRUE(connected.value()->close().ok());
  EXPECT_TRUE(
      program.line().ends_with(": 501 ticks, 0 interrupts, 501 writes, 501 reads (lock-step, base period "
                               "10000 us)"));
  EXPECT_EQ(program.wait(), 0);
  std::filesystem::remove(fmu);
}

// A plant that asks to stop ends the session at that tick: the firmware is told (ERROR, the only ending a plant
// can give a tick), and the server says why and counts it no failure.
TEST(PlantCommand, AnFmuThatAsksToStopEndsTheSession) {
  const std::string mapping =
      (std::filesystem::temp_directory_path() / ("duet_stop_" + std::to_string(::getpid()) + ".yaml")).string();
  std::ofstream{mapping} << "outputs:\n  - {variable: y, resource: \"adc:ADC1/6\"}\nset:\n  stop_at: 0.005\n";
  Child program{{"plant", "serve", std::string{DUET_TEST_FMU_DIR} + "/Terminating_fmi3.fmu", "--connect", mapping,
                 "--listen", ":0", "--once"}};
  ASSERT_TRUE(program.started());
  auto stream =
      link::connect_tcp(listening_address(program, std::string{DUET_TEST_FMU_DIR} + "/Terminating_fmi3.fmu"), 10s);
  ASSERT_TRUE(stream.ok()) << stream.error();
  auto connected = link::RemotePlant::connect(std::move(stream).value(), {link::LinkMode::lock_step, 1'000'000});
  ASSERT_TRUE(connected.ok()) << connected.error();
  link::RemotePlant& plant = *connected.value();
  for (int tick = 0; tick <= 10 && plant.ok(); ++tick) plant.advance(tick * 0.001, {});
  ASSERT_FALSE(plant.ok());
  EXPECT_EQ(plant.ticks(), 6U);  // 0 to 5 ms, the last answered with ERROR
  EXPECT_NE(plant.error().find("the plant asked to stop at t = 0.005 s: "), std::string::npos) << plant.error();
  const std::string served = program.line();
  EXPECT_TRUE(served.ends_with("; the plant asked to stop at t = 0.005 s: Terminating asked to stop at t = 0.005 s"))
      << served;
  EXPECT_EQ(program.wait(), 0);
  std::filesystem::remove(mapping);
}

}  // namespace
}  // namespace duet::cli
