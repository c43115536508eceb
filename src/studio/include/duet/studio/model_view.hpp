#pragma once
// What duet studio shows of a model's text (docs/STUDIO.md, the `model` message): the diagnostics of the same reader
// and checker as `duet model check`, each naming its file and tied to the block it lies in; the diagram (every system's
// blocks with their ports and every signal as a wire, coloured by task); and the task table. The page draws this; it
// never works out what the text means itself.

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "duet/model/diagnostic.hpp"
#include "duet/model/model.hpp"
#include "duet/model/program.hpp"

namespace duet::studio {

// A model's text read and checked: the model when it reads, the program when it also checks.
struct CheckedText {
  std::string file;                     // the model's, as check_text() was given it
  std::unique_ptr<model::Model> model;  // the program points into it
  std::optional<model::Program> program;
  std::vector<model::Diagnostic> diagnostics;
};

// `file` names the model in diagnostics and tells Code blocks where their headers are.
[[nodiscard]] CheckedText check_text(std::string_view text, const std::string& file);

// The `model` message's members: ok, diagnostics, diagram (null when the text does not read), tasks.
[[nodiscard]] nlohmann::json model_view(const CheckedText& checked, std::string_view text);

// The executive's task table (docs/STUDIO.md, "tasks").
[[nodiscard]] nlohmann::json tasks_json(const model::Program& program);

}  // namespace duet::studio
