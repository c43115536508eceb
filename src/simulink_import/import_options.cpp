#include "duet/simulink_import/import_options.hpp"

#include <charconv>

#include "duet/simulink_import/matlab_script.hpp"
#include "duet/simulink_import/yaml_variables.hpp"
#include "duet/support/text_file.hpp"

namespace duet::simulink_import {

Result<Workspace> read_variable_files(const std::vector<std::string>& files) {
  Workspace workspace;
  for (const std::string& file : files) {
    if (file.ends_with(".m")) {
      auto text = read_text_file(file);
      if (!text) return Failure{text.error()};
      auto read = read_m_script(text.value(), file, std::move(workspace));
      if (!read) return Failure{read.error()};
      workspace = std::move(read).value();
    } else if (file.ends_with(".yaml") || file.ends_with(".yml")) {
      auto read = read_variables_yaml(file);
      if (!read) return Failure{read.error()};
      for (auto& [name, value] : read.value()) workspace.insert_or_assign(name, std::move(value));
    } else {
      return Failure{file + ": variables come from a .m script or a .yaml file"};
    }
  }
  return workspace;
}

Result<std::pair<std::string, InterruptTask>> parse_interrupt_mapping(const std::string& text) {
  const std::size_t equals = text.rfind('=');
  const std::size_t colon = text.rfind(':');
  if (equals == std::string::npos || equals == 0 || colon == std::string::npos || colon < equals + 2) {
    return Failure{"--interrupt '" + text + "': write BLOCK_PATH=IRQ:PRIORITY (model/ISR=TIM2:3)"};
  }
  InterruptTask task{.interrupt = text.substr(equals + 1, colon - equals - 1), .priority = 0};
  const std::string priority = text.substr(colon + 1);
  const auto [end, error] = std::from_chars(priority.data(), priority.data() + priority.size(), task.priority);
  if (error != std::errc{} || end != priority.data() + priority.size() || task.priority < 0 || task.priority > 15) {
    return Failure{"--interrupt '" + text + "': the priority '" + priority + "' is not 0 to 15"};
  }
  return std::pair{text.substr(0, equals), task};
}

}  // namespace duet::simulink_import
