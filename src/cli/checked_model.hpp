#pragma once
// What model, sim and gen do first: read a model file and check it, printing every diagnostic.

#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include "duet/model/model.hpp"
#include "duet/model/program.hpp"

namespace duet::cli {

struct CheckedModel {
  std::unique_ptr<model::Model> model;  // the program points into it
  model::Program program;
};

// The model ready to simulate or generate, or nothing once its errors are on `err` (its warnings go there either way).
std::optional<CheckedModel> load_checked_model(const std::string& file, std::ostream& err);

}  // namespace duet::cli
