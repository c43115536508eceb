#include <CLI/CLI.hpp>

#include <ostream>

#include "design_command.hpp"
#include "gen_command.hpp"
#include "model_command.hpp"
#include "pil_command.hpp"
#include "plant_command.hpp"
#include "sched_command.hpp"
#include "sim_command.hpp"
#include "subcommand.hpp"
#include "xcp_command.hpp"

namespace duet::cli {
namespace {

// Subcommands whose issue has not landed yet: they show up in --help and say where their work is planned.
template <int issue>
Action planned(CLI::App& command) {
  return [name = command.get_name()](Streams streams) {
    streams.err << "duet " << name << ": not implemented yet (planned in issue #" << issue << ")\n";
    return ExitCode::failure;
  };
}

constexpr Subcommand table[] = {
    {"xcp", "Talk XCP to a target: connect, read and write memory, record signals with DAQ", define_xcp_command},
    {"sim", "Simulate a model against a plant model on the PC", define_sim_command},
    {"gen", "Generate freestanding C++, the A2L file and the task table from a model", define_gen_command},
    {"sched", "Analyse the schedulability of an interrupt task set and assign NVIC priorities", define_sched_command},
    {"monitor", "Serve the dashboard for a target reached over XCP", planned<10>},
    {"model", "Check a model file and describe its blocks, signals and tasks", define_model_command},
    {"design", "Design LQR and steady-state Kalman gains and print them as model parameters", define_design_command},
    {"plant", "Serve a simulated plant to firmware in another process over the virtual-hardware link",
     define_plant_command},
    {"pil", "Processor in the loop: firmware on QEMU's emulated Cortex-M4 against a simulated plant, with the bridge",
     define_pil_command},
};

}  // namespace

std::span<const Subcommand> subcommands() { return table; }

}  // namespace duet::cli
