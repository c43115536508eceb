#pragma once
// Reads an FMU's modelDescription.xml and checks it against the rules of FMI 2.0 and 3.0 that an importer relies
// on (docs/FMI.md, "What duet checks"); a problem comes back as "modelDescription.xml:LINE: what is wrong".

#include <string_view>

#include "duet/fmi/model_description.hpp"
#include "duet/support/result.hpp"

namespace duet::fmi {

[[nodiscard]] Result<ModelDescription> read_model_description(std::string_view xml);

}  // namespace duet::fmi
