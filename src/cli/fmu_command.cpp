#include "fmu_command.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <ostream>
#include <string>

#include "duet/fmi/fmu_info.hpp"

namespace duet::cli {
namespace {

struct FmuOptions {
  std::string file;
  bool json = false;
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

}  // namespace

Action define_fmu_command(CLI::App& command) {
  auto options = std::make_shared<FmuOptions>();
  command.require_subcommand(1);
  CLI::App* info_command = command.add_subcommand(
      "info", "FMI version, model, identifier, token, capabilities, binaries, default experiment, variables");
  info_command->add_option("file", options->file, "The FMU (.fmu)")->required();
  info_command->add_flag("--json", options->json, "One JSON object instead of text, for scripts");
  return [options](Streams streams) { return info(*options, streams); };
}

}  // namespace duet::cli
