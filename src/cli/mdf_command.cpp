#include "mdf_command.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "duet/mdf4/csv_export.hpp"
#include "duet/mdf4/reader.hpp"
#include "duet/mdf4/summary.hpp"

namespace duet::cli {
namespace {

struct MdfOptions {
  std::string file;
  std::string csv;
  std::vector<std::string> channels;
};

ExitCode info(const MdfOptions& options, Streams streams) {
  auto reader = mdf4::Reader::open(options.file);
  if (!reader) {
    streams.err << "duet mdf info: " << reader.error() << '\n';
    return ExitCode::failure;
  }
  auto summary = mdf4::summarise(reader.value());
  if (!summary) {
    streams.err << "duet mdf info: " << summary.error() << '\n';
    return ExitCode::failure;
  }
  streams.out << options.file << ": " << summary.value();
  return ExitCode::success;
}

ExitCode export_csv(const MdfOptions& options, Streams streams) {
  auto reader = mdf4::Reader::open(options.file);
  if (!reader) {
    streams.err << "duet mdf export: " << reader.error() << '\n';
    return ExitCode::failure;
  }
  std::ofstream csv{options.csv};
  if (!csv) {
    streams.err << "duet mdf export: " << options.csv << ": cannot create\n";
    return ExitCode::failure;
  }
  auto exported = mdf4::export_csv(reader.value(), options.channels, csv);
  csv.close();
  if (!exported || !csv) {
    streams.err << "duet mdf export: " << (exported ? options.csv + ": cannot write" : exported.error()) << '\n';
    std::remove(options.csv.c_str());  // no half-written CSV left to be taken for the whole
    return ExitCode::failure;
  }
  for (const std::string& channel : exported.value().not_decoded)
    streams.err << "duet mdf export: left out " << channel << '\n';
  streams.out << "wrote " << options.csv << ": " << exported.value().rows << " rows, " << exported.value().columns
              << " channels\n";
  return ExitCode::success;
}

}  // namespace

Action define_mdf_command(CLI::App& command) {
  auto options = std::make_shared<MdfOptions>();
  command.require_subcommand(1);
  CLI::App* info_command =
      command.add_subcommand("info", "Groups, channels, units, samples, time span, finalised or not");
  info_command->add_option("file", options->file, "The MDF 4 file")->required();
  CLI::App* export_command =
      command.add_subcommand("export", "Channels as CSV: a time column, the groups merged in time");
  export_command->add_option("file", options->file, "The MDF 4 file")->required();
  export_command->add_option("--csv", options->csv, "The CSV file to write")->required();
  export_command->add_option("--channel", options->channels,
                             "NAME or GROUP:NAME, in column order (default: every channel)");
  return [options, info_command](Streams streams) {
    return info_command->parsed() ? info(*options, streams) : export_csv(*options, streams);
  };
}

}  // namespace duet::cli
