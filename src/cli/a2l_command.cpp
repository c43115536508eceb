#include "a2l_command.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "duet/xcp/host/a2l_check.hpp"

namespace duet::cli {
namespace {

// One line per problem, FILE:LINE:COLUMN: error|warning: message, in the order of the files.
ExitCode run_check(const std::vector<std::string>& files, Streams streams) {
  bool errors = false;
  for (const std::string& file : files) {
    const std::vector<xcp::host::A2lProblem> problems = xcp::host::check_a2l_file(file);
    for (const xcp::host::A2lProblem& problem : problems) streams.out << problem.text() << '\n';
    errors = errors || xcp::host::has_errors(problems);
  }
  return errors ? ExitCode::failure : ExitCode::success;
}

}  // namespace

Action define_a2l_command(CLI::App& command) {
  auto files = std::make_shared<std::vector<std::string>>();
  command.require_subcommand(1);
  CLI::App* check = command.add_subcommand(
      "check", "Check A2L files against ASAP2 1.71 and XCP's IF_DATA: one line per problem, exit 1 on any error");
  check->add_option("files", *files, "The A2L files")->required();
  return [files](Streams streams) { return run_check(*files, streams); };
}

}  // namespace duet::cli
