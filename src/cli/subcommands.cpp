#include <CLI/CLI.hpp>

#include <ostream>

#include "a2l_command.hpp"
#include "design_command.hpp"
#include "fmu_command.hpp"
#include "gen_command.hpp"
#include "import_command.hpp"
#include "mdf_command.hpp"
#include "model_command.hpp"
#include "monitor_command.hpp"
#include "pil_command.hpp"
#include "plant_command.hpp"
#include "sched_command.hpp"
#include "sim_command.hpp"
#include "studio_command.hpp"
#include "subcommand.hpp"
#include "xcp_command.hpp"

namespace duet::cli {
namespace {

constexpr Subcommand table[] = {
    {"xcp", "Talk XCP to a target: connect, read and write memory, record signals with DAQ", define_xcp_command},
    {"sim", "Simulate a model against a plant model on the PC", define_sim_command},
    {"gen", "Generate freestanding C++, the A2L file and the task table from a model", define_gen_command},
    {"sched", "Analyse the schedulability of an interrupt task set and assign NVIC priorities", define_sched_command},
    {"monitor", "Serve the dashboard for a target reached over XCP", define_monitor_command},
    {"model", "Check a model file and describe its blocks, signals and tasks", define_model_command},
    {"design", "Design LQR and steady-state Kalman gains and print them as model parameters", define_design_command},
    {"plant", "Serve a simulated plant to firmware in another process over the virtual-hardware link",
     define_plant_command},
    {"pil", "Processor in the loop: firmware on QEMU's emulated Cortex-M4 against a simulated plant, with the bridge",
     define_pil_command},
    {"studio", "See, edit, simulate and watch a model in the browser", define_studio_command},
    {"a2l", "Check A2L files against ASAP2 1.71 and XCP's IF_DATA", define_a2l_command},
    {"mdf", "Describe an ASAM MDF 4 measurement file, export its channels as CSV", define_mdf_command},
    {"fmu", "Describe an FMI co-simulation FMU (FMI 2.0 or 3.0)", define_fmu_command},
    {"import", "Bring a Simulink model (.slx, .mdl) over as a duet model", define_import_command},
};

}  // namespace

std::span<const Subcommand> subcommands() { return table; }

}  // namespace duet::cli
