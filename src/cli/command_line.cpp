#include "command_line.hpp"

#include <CLI/CLI.hpp>

#include <ostream>
#include <vector>

#include "duet/support/closest_word.hpp"
#include "duet/version.hpp"

namespace duet::cli {
namespace {

constexpr std::string_view exit_codes = "Exit codes: 0 success, 1 the command failed, 2 the command line is wrong.";

std::vector<std::string_view> subcommand_names() {
  std::vector<std::string_view> names;
  for (const Subcommand& subcommand : subcommands()) names.push_back(subcommand.name);
  return names;
}

// Names the offending word where there is one, and suggests the subcommand probably meant.
void report_usage_error(const CLI::App& app, const CLI::ParseError& error, std::ostream& err) {
  const std::vector<std::string> extras = app.remaining(true);
  const std::vector<std::string_view> names = subcommand_names();
  if (app.get_subcommands().empty() && extras.empty()) {
    err << "duet: a command is required, one of:";
    for (std::string_view name : names) err << ' ' << name;
    err << ". See 'duet --help'.\n";
  } else if (app.get_subcommands().empty() && !extras.front().starts_with('-')) {
    err << "duet: '" << extras.front() << "' is not a duet command.";
    if (std::optional<std::string_view> meant = closest_word(extras.front(), names)) {
      err << " Did you mean '" << *meant << "'?";
    }
    err << " See 'duet --help'.\n";
  } else if (!extras.empty()) {
    err << "duet: unexpected argument";
    for (const std::string& extra : extras) err << " '" << extra << "'";
    err << ". See 'duet --help'.\n";
  } else {
    err << "duet: " << error.what() << ". See 'duet --help'.\n";
  }
}

}  // namespace

ExitCode run_command_line(std::span<const std::string> arguments, Streams streams) {
  CLI::App app{"duet: model-based real-time control for heterogeneous multicore chips", "duet"};
  app.set_version_flag("--version", "duet " + std::string{version});
  app.footer(std::string{exit_codes});
  app.require_subcommand(1);

  Action chosen;
  for (const Subcommand& subcommand : subcommands()) {
    CLI::App* command = app.add_subcommand(std::string{subcommand.name}, std::string{subcommand.summary});
    command->footer(std::string{exit_codes});
    command->callback([&chosen, action = subcommand.define(*command)] { chosen = action; });
  }

  // CLI11 parses a reversed vector of the arguments.
  std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::Success& success) {  // --help or --version
    app.exit(success, streams.out, streams.err);
    return ExitCode::success;
  } catch (const CLI::ParseError& error) {
    report_usage_error(app, error, streams.err);
    return ExitCode::usage;
  }
  return chosen(streams);
}

}  // namespace duet::cli
