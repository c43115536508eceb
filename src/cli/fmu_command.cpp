#include "fmu_command.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <ostream>
#include <string>

#include "checked_model.hpp"
#include "duet/fmi/fmu_info.hpp"
#include "duet/fmu_export/fmu_export.hpp"

namespace duet::cli {
namespace {

struct FmuOptions {
  std::string file;
  bool json = false;
  std::string model;
  std::string output;
  int fmi_version = 3;
};

ExitCode info(const FmuOptions& options, Streams streams) {
  auto info = fmi::read_fmu_info(options.file);
  if (!info) {
    streams.err << "duet fmu info: " << info.error() << '\n';
    return ExitCode::failure;
  }
  if (options.json) {
    streams.out << fmi::to_json(info.value());
  } else {
    streams.out << options.file << ": ";
    fmi::write_text(streams.out, info.value());
  }
  return ExitCode::success;
}

ExitCode export_model(const FmuOptions& options, Streams streams) {
  const auto checked = load_checked_model(options.model, streams.err);
  if (!checked) return ExitCode::failure;
  const fmi::FmiVersion version = options.fmi_version == 2 ? fmi::FmiVersion::v2 : fmi::FmiVersion::v3;
  auto exported = fmu_export::export_fmu(checked->program, options.model, options.output, version);
  if (!exported) {
    streams.err << "duet fmu export: " << options.model << ": " << exported.error() << '\n';
    return ExitCode::failure;
  }
  for (const std::string& note : exported.value().notes) streams.err << options.model << ": note: " << note << '\n';
  streams.out << "exported " << checked->model->name << " as " << options.output << " (FMI " << options.fmi_version
              << ".0 co-simulation, " << exported.value().variables << " variables)\n";
  return ExitCode::success;
}

}  // namespace

Action define_fmu_command(CLI::App& command) {
  auto options = std::make_shared<FmuOptions>();
  command.require_subcommand(1);
  CLI::App* info_command = command.add_subcommand(
      "info", "FMI version, model, identifier, token, capabilities, binaries, default experiment, variables");
  info_command->add_option("file", options->file, "The FMU (.fmu)")->required();
  info_command->add_flag("--json", options->json, "One JSON object instead of text, for scripts");
  CLI::App* export_command = command.add_subcommand(
      "export", "A model as a co-simulation FMU: its generated code built by the PC's compiler (docs/FMI.md)");
  export_command->add_option("model", options->model, "The model file (docs/MODELS.md)")->required();
  export_command->add_option("-o,--output", options->output, "The FMU to write (NAME.fmu)")->required();
  export_command->add_option("--fmi", options->fmi_version, "The FMI version: 3 (the default) or 2")
      ->check(CLI::IsMember({2, 3}));
  return [options, info_command](Streams streams) {
    return info_command->parsed() ? info(*options, streams) : export_model(*options, streams);
  };
}

}  // namespace duet::cli
