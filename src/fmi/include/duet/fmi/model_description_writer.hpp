#pragma once
// Writes modelDescription.xml for FMI 2.0 or 3.0 from duet's data model, its elements in the schema's order.

#include <string>

#include "duet/fmi/model_description.hpp"
#include "duet/support/result.hpp"

namespace duet::fmi {

// Fails for what the data model cannot describe whole: enumerations (they need type definitions), clocks, and a
// type of the other FMI version.
[[nodiscard]] Result<std::string> write_model_description(const ModelDescription& description);

}  // namespace duet::fmi
