#pragma once
// The block diagram of a model in Graphviz's language: a box per block with its ports, an arrow per connection
// labelled with the signal, a frame per subsystem (with its trigger). `duet model render` turns it into SVG with dot.

#include <string>

#include "duet/model/model.hpp"

namespace duet::model {

[[nodiscard]] std::string to_dot(const Model& model);

}  // namespace duet::model
