#pragma once
// Which plant a command runs against: a plant by name (for the robot a scenario file and a seed), a plant model
// (.yaml), or a co-simulation FMU (.fmu) with its mapping file. Shared by `duet sim`, `duet plant serve` and
// `duet pil`, so that all three make exactly the same plant from the same words.

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "duet/plant/balbot/balbot_scenario.hpp"
#include "duet/plant/plant.hpp"
#include "duet/support/result.hpp"

namespace CLI {  // NOLINT(readability-identifier-naming): CLI11's namespace, declared here only
class App;
}

namespace duet::cli {

struct PlantChoice {
  std::string name;      // a plant's name, a plant model file (.yaml) or an FMU (.fmu)
  std::string scenario;  // a balbot scenario file, or empty
  std::uint64_t seed = 1;
  bool seed_given = false;                // --seed replaces the scenario's seed only when given
  std::string connect;                    // an FMU's mapping file (docs/FMI.md)
  std::vector<std::string> fmu_settings;  // an FMU's parameters and start values, NAME=VALUE
};

// Makes a fresh plant each time it is called, so that every session starts alike.
using PlantMaker = std::function<Result<std::unique_ptr<plant::Plant>>()>;

struct ChosenPlant {
  PlantMaker make;
  std::optional<plant::BalbotScenario> scenario;  // the robot's scenario when --scenario gave one
};

// Where a plant's own messages go, a line at a time: a plant model's warnings, an imported FMU's log. Called from
// the thread that runs the plant.
using PlantLog = std::function<void(std::string_view line)>;

// Each line to `out`, one whole line at a time whichever thread says it.
[[nodiscard]] PlantLog log_lines_to(std::ostream& out);

// Declares --scenario FILE, --seed N, --connect FILE and --fmu-set NAME=VALUE on `command`, bound to `choice`.
void add_plant_options(CLI::App& command, PlantChoice& choice);

// What is wrong with the options taken together (an FMU without a mapping file, a mapping file without an FMU), for
// a usage error; nothing when they fit.
[[nodiscard]] std::optional<std::string> plant_options_misuse(const PlantChoice& choice);

// Checks the choice once, making the plant (an unknown plant, a scenario for a plant that takes none, a file that
// cannot be read, an FMU that cannot run or a mapping that does not fit it), and says how to make it again.
[[nodiscard]] Result<ChosenPlant> choose_plant(const PlantChoice& choice, const PlantLog& log);

// "none, balbot, a plant model (.yaml) or a co-simulation FMU (.fmu) with --connect": for help texts.
[[nodiscard]] std::string plant_list();

}  // namespace duet::cli
