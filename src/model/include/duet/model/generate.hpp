#pragma once
// `duet gen`: freestanding C++ for the executive from a Program (docs/MODELS.md, "Generated code"):
//   NAME.hpp      the parameter structure (the calibration segment: a working page in RAM and a reference page in
//                 flash), the signal and state structures, initialize/terminate, a step function per task, and the
//                 task table (duet::rt::ModelDescription) checked at compile time;
//   NAME.cpp      their definitions; hardware blocks call the port's duet/hardware/hardware.hpp;
//   NAME_xcp.hpp  the memory XCP may reach and the events, for the XCP slave;
//   NAME.a2l      the A2L for XCP masters, with the generator's fixed layout (checked by static_assert);
//   NAME.cmake    a CMake fragment that adds the library NAME_model.
// Each file says which generator and model made it.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "duet/model/program.hpp"
#include "duet/support/result.hpp"
#include "duet/xcp/host/a2l.hpp"

namespace duet::model {

struct GeneratedFile {
  std::string name;
  std::string text;
};

// The XCP addresses of the layout: parameters and signals start here, each field at its offset; the executive's
// account (duet/rt/executive_account.hpp) after them.
inline constexpr std::uint32_t parameters_xcp_address = 0x0001'0000;
inline constexpr std::uint32_t signals_xcp_address = 0x0002'0000;
inline constexpr std::uint32_t executive_xcp_address = 0x0003'0000;
inline constexpr std::uint32_t epk_xcp_address = 0x0004'0000;  // the EPK string, read-only

// The A2L's memory segment of the executive's account.
inline constexpr std::string_view executive_segment = "executive";

// A task's name in the executive's account (`executive.NAME.max_cycles` in the A2L; the dashboard's task table):
// its name with every character but letters and digits as '_' ("rate 1" is rate_1, "EXTI8" stays).
[[nodiscard]] std::string account_task_name(const ProgramTask& task);

// Whether `measurement` is part of the executive's account: it lies in `a2l`'s segment "executive". Every other
// MEASUREMENT (all the others of a generated A2L; all of another's) is the application's. By place, not by name: a
// model's subsystem may be called "executive" too.
[[nodiscard]] bool is_executive_account(const xcp::host::A2lDescription& a2l, const xcp::host::Variable& measurement);

// Where the program computes in double precision though its model does not say `precision: double`: a warning for
// each parameter in double and each block where double starts, since the Cortex-M4's FPU is single precision and
// `duet gen` writes code for it (program.cpp).
[[nodiscard]] std::vector<Diagnostic> precision_warnings(const Program& program);

// Where the generated code keeps its parameters, signals and state: in global objects (the firmware: one model per
// core, at the A2L's addresses), or per instance, through a thread-local pointer to the instance the caller works on
// (an FMU: several instances in one process; the header's `Instance` and `instance`).
enum class Storage { global, per_instance };

// `source` names the model file in the files' first lines; `model_folder` is the model's folder relative to where the
// files go, for the CMake fragment to find the Code blocks' headers.
[[nodiscard]] Result<std::vector<GeneratedFile>> generate(const Program& program, const std::string& source,
                                                          const std::string& model_folder = "..",
                                                          Storage storage = Storage::global);

}  // namespace duet::model
