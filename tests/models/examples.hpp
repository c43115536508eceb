#pragma once
// The example models whose generated code the tests build (tests/models/CMakeLists.txt).

#include <string>
#include <vector>

namespace duet::model {

inline const std::vector<std::string> example_models{"step_time", "transfer_test", "pid_demo",      "thermostat",
                                                     "balbot",    "block_tour",    "tilt_reference"};

inline std::string example_file(const std::string& model) {
  return std::string{DUET_SOURCE_DIR} + "/apps/" + model + "/" + model + ".yaml";
}

inline std::string generated_folder(const std::string& model) {
  return std::string{DUET_SOURCE_DIR} + "/apps/" + model + "/generated";
}

}  // namespace duet::model
