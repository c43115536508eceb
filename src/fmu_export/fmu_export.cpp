#include "duet/fmu_export/fmu_export.hpp"

#include <fstream>

#include "duet/fmi/archive_writer.hpp"
#include "duet/fmi/model_description_writer.hpp"
#include "duet/fmu_export/fmu_interface.hpp"
#include "duet/model/generate.hpp"
#include "duet/support/compiler.hpp"
#include "duet/support/content_hash.hpp"
#include "duet/support/temporary_folder.hpp"
#include "model_table.hpp"

namespace duet::fmu_export {
namespace {

Status write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out{path, std::ios::binary};
  out << text;
  if (!out) return Failure{"cannot write " + path.string()};
  return done();
}

// The glue and the headers the generated code includes, in duet's source tree (DUET_SOURCE_DIR, where this duet was
// built from).
std::vector<std::string> build_command(const std::filesystem::path& folder, const std::filesystem::path& model_folder,
                                       const std::string& identifier, fmi::FmiVersion version) {
  const std::filesystem::path source = DUET_SOURCE_DIR;
  const std::filesystem::path runtime = source / "src/fmu_export/runtime";
  std::vector<std::string> command{cxx_compiler(), "-std=c++20", "-O2",
                                   "-ffp-contract=off",  // as duet_blocks: the rounding of `duet sim` and the firmware
                                   "-fno-exceptions", "-fno-rtti",  // as the firmware: nothing to throw or ask
                                   "-fPIC", "-shared", "-fvisibility=hidden", "-fvisibility-inlines-hidden",
                                   // Loads into any process: no libstdc++ of the importer's needed, none of ours shown.
                                   "-static-libstdc++", "-static-libgcc", "-Wl,--exclude-libs,ALL",
                                   "-Wl,--no-undefined"};
  for (const std::filesystem::path& include :
       {folder, model_folder, runtime, source / "src/fmi/include", source / "src/blocks/include",
        source / "src/rt/include", source / "src/base/include", source / "src/hardware/include",
        source / "ports/host/include"}) {
    command.push_back("-I" + include.string());
  }
  for (const std::filesystem::path& file :
       {folder / (identifier + ".cpp"), folder / "fmu_model.cpp", runtime / "instance.cpp",
        runtime / (version == fmi::FmiVersion::v3 ? "fmi3_functions.cpp" : "fmi2_functions.cpp"),
        source / "ports/fmu/hardware.cpp"}) {
    command.push_back(file.string());
  }
  command.push_back("-o");
  command.push_back((folder / (identifier + ".so")).string());
  return command;
}

}  // namespace

Result<ExportSummary> export_fmu(const model::Program& program, const std::filesystem::path& model_file,
                                 const std::filesystem::path& fmu, fmi::FmiVersion version) {
  FmuInterface interface = fmu_interface(program, version);
  const std::string identifier = interface.description.co_simulation.model_identifier;
  auto generated = model::generate(program, model_file.filename().string(), "..", model::Storage::per_instance);
  if (!generated) return Failure{generated.error()};
  const std::string& header = generated.value().at(0).text;
  const std::string& source = generated.value().at(1).text;
  // The token ties a description to the library built with it: the code, the FMI version, the variables.
  std::string identity = header + source + (version == fmi::FmiVersion::v3 ? "3.0" : "2.0");
  for (const fmi::Variable& variable : interface.description.variables) identity += variable.name + '\n';
  interface.description.token = "{duet-" + identifier + "-" + content_hash(identity) + "}";

  auto folder = TemporaryFolder::make("duet_fmu_");
  if (!folder) return Failure{folder.error()};
  const std::filesystem::path& here = folder.value().path();
  for (const auto& [name, text] : {std::pair{identifier + ".hpp", header}, std::pair{identifier + ".cpp", source},
                                   std::pair{std::string{"fmu_model.cpp"},
                                             model_table_source(interface, identifier, interface.description.token)}}) {
    if (auto written = write_file(here / name, text); !written) return Failure{written.error()};
  }
  const std::filesystem::path model_folder = std::filesystem::absolute(model_file).parent_path();
  if (auto built =
          compile(build_command(here, model_folder, identifier, version), here / "compiler.txt", "the FMU's library");
      !built) {
    return Failure{built.error()};
  }
  auto xml = fmi::write_model_description(interface.description);
  if (!xml) return Failure{xml.error()};
  const std::string platform = version == fmi::FmiVersion::v3 ? "x86_64-linux" : "linux64";
  const std::vector<fmi::ArchiveInput> entries{
      {"modelDescription.xml", xml.value()},
      {"binaries/" + platform + "/" + identifier + ".so", here / (identifier + ".so")}};
  if (auto packed = fmi::write_archive(fmu, entries); !packed) return Failure{packed.error()};

  ExportSummary summary{.model_identifier = identifier, .variables = interface.description.variables.size()};
  for (const model::ProgramTask& task : program.tasks) {
    if (task.rate.kind == model::Rate::Kind::interrupt) {
      summary.notes.push_back("task '" + task.name + "' runs on interrupt " + task.rate.interrupt +
                              ": the importer raises it by counting up the input interrupt:" + task.rate.interrupt);
    }
  }
  return summary;
}

}  // namespace duet::fmu_export
