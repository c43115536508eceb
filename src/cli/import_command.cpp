#include "import_command.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "checked_model.hpp"
#include "duet/simulink_import/import.hpp"
#include "duet/simulink_import/import_options.hpp"
#include "duet/simulink_import/simulink_file.hpp"

namespace duet::cli {
namespace {

namespace simulink = simulink_import;

struct ImportCommandOptions {
  std::string file;
  std::string output;
  std::vector<std::string> variables;
  std::vector<std::string> interrupts;
  std::uint32_t base_period_us = 0;
  bool report = false;
};

constexpr std::string_view prefix = "duet import simulink: ";

void write_report(const simulink::ImportResult& result, std::ostream& out) {
  std::size_t imported = 0;
  for (const simulink::Verdict& verdict : result.report) {
    imported += verdict.imported ? 1 : 0;
    std::string path = verdict.path;
    for (char& c : path)
      if (c == '\n') c = ' ';
    out << (verdict.imported ? "  ok       " : "  refused  ") << path << " (" << verdict.type << "): " << verdict.what
        << '\n';
  }
  out << imported << " of " << result.report.size() << " blocks imported\n";
}

ExitCode import_simulink(const ImportCommandOptions& options, Streams streams) {
  const auto fail = [&streams](const std::string& message) {
    streams.err << prefix << message << '\n';
    return ExitCode::failure;
  };
  auto model = simulink::read_simulink_file(options.file);
  if (!model) return fail(model.error());
  simulink::ImportOptions import;
  auto variables = simulink::read_variable_files(options.variables);
  if (!variables) return fail(variables.error());
  import.variables = std::move(variables).value();
  if (options.base_period_us != 0) import.base_period_us = options.base_period_us;
  for (const std::string& text : options.interrupts) {
    auto mapping = simulink::parse_interrupt_mapping(text);
    if (!mapping) {
      streams.err << prefix << mapping.error() << '\n';
      return ExitCode::usage;
    }
    import.interrupts.insert(std::move(mapping).value());
  }
  const simulink::ImportResult result = simulink::import_simulink(model.value(), import);
  if (options.report) write_report(result, streams.out);
  if (!result.problems.empty()) {
    for (const std::string& problem : result.problems) streams.err << prefix << problem << '\n';
    streams.err << prefix << "nothing written: " << result.problems.size() << " problem(s)"
                << (options.report ? "" : " (--report lists every block with its verdict)") << '\n';
    return ExitCode::failure;
  }
  std::ofstream file{options.output};
  file << result.model_text;
  if (!file) return fail("cannot write " + options.output);
  file.close();
  // The result is a model like any other: checked as `duet model check` checks it.
  const auto checked = load_checked_model(options.output, streams.err);
  if (!checked) return fail(options.output + " does not check (above)");
  // What only the checked model's types can refuse.
  const model::Program& program = checked->program;
  const auto problems = simulink::integer_problems(result, [&program](const std::string& path) {
    for (const model::ProgramBlock& block : program.blocks)
      if (block.path == path && !block.outputs.empty()) return model::describe(program.signals[block.outputs[0]].type);
    return std::string{};
  });
  if (!problems.empty()) {
    for (const std::string& problem : problems) streams.err << prefix << problem << '\n';
    std::filesystem::remove(options.output);
    return fail("nothing written: " + std::to_string(problems.size()) + " problem(s)");
  }
  streams.out << "imported " << model.value().name << " (" << model.value().format << ") as " << options.output << '\n';
  return ExitCode::success;
}

}  // namespace

Action define_import_command(CLI::App& command) {
  auto options = std::make_shared<ImportCommandOptions>();
  command.require_subcommand(1);
  CLI::App* simulink_command = command.add_subcommand(
      "simulink", "A Simulink model (.slx, .mdl) as a duet model: its discrete subset, strictly (docs/IMPORT.md)");
  simulink_command->add_option("file", options->file, "The Simulink model (.slx or .mdl)")
      ->required()
      ->check(CLI::ExistingFile);
  simulink_command->add_option("-o,--output", options->output, "The duet model to write (MODEL.yaml)")->required();
  simulink_command
      ->add_option("--variables", options->variables,
                   "Variables the parameters name: a .m script of assignments or a .yaml file (repeat; later files "
                   "see and replace earlier names)")
      ->type_name("FILE")
      ->check(CLI::ExistingFile);
  simulink_command
      ->add_option("--base-period-us", options->base_period_us, "The base period, instead of the solver's fixed step")
      ->check(CLI::Range(1U, 4'000'000'000U));
  simulink_command
      ->add_option("--interrupt", options->interrupts,
                   "A function-call subsystem as an interrupt task: BLOCK_PATH=IRQ:PRIORITY (repeat)")
      ->type_name("PATH=IRQ:P");
  simulink_command->add_flag("--report", options->report, "List every block with what it became, or why not");
  return [options](Streams streams) { return import_simulink(*options, streams); };
}

}  // namespace duet::cli
