#pragma once
// The model's table for an exported FMU's glue (runtime/fmu_model.hpp): fmu_model.cpp, compiled with the model's
// generated code (per-instance storage) into the FMU's library.

#include <string>

#include "duet/fmu_export/fmu_interface.hpp"

namespace duet::fmu_export {

[[nodiscard]] std::string model_table_source(const FmuInterface& interface, const std::string& model_name,
                                             const std::string& token);

}  // namespace duet::fmu_export
