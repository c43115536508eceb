#include "duet/model/signal_names.hpp"

#include "flat_model.hpp"

namespace duet::model {

SignalNames::SignalNames(const Model& model) : flat_(std::make_unique<FlatModel>(model)) {}
SignalNames::~SignalNames() = default;

std::string SignalNames::model_wide(const std::string& scope, const std::string& name) const {
  return flat_->outermost_name(flat_->resolve(scope + name));
}

}  // namespace duet::model
