#pragma once
// The model-wide name of a signal as one scope of the model names it: what simulation records and the A2L measures
// ("theta", "imu/raw" for raw inside subsystem imu). Inside a subsystem its input ports are the parent's signals
// connected to them; a parent's signal that a subsystem's output drives is known by the parent's name.

#include <memory>
#include <string>

#include "duet/model/model.hpp"

namespace duet::model {

class FlatModel;

class SignalNames {
 public:
  explicit SignalNames(const Model& model);  // `model` must outlive this
  ~SignalNames();
  SignalNames(const SignalNames&) = delete;
  SignalNames& operator=(const SignalNames&) = delete;

  // `scope`: "" at the top level, "imu/" inside subsystem imu; `name` as that scope writes it.
  [[nodiscard]] std::string model_wide(const std::string& scope, const std::string& name) const;

 private:
  std::unique_ptr<FlatModel> flat_;
};

}  // namespace duet::model
