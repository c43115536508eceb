#pragma once
// What every reader of an opened FMU needs first: its description, read and checked, and where its Linux x86_64
// library is (binaries/linux64 for FMI 2.0, binaries/x86_64-linux for 3.0).

#include <filesystem>
#include <string>

#include "duet/fmi/archive.hpp"
#include "duet/fmi/model_description.hpp"
#include "duet/support/result.hpp"

namespace duet::fmi {

// `file` names the archive in the messages ("Lag.fmu: modelDescription.xml:3: ...").
[[nodiscard]] Result<ModelDescription> read_description(const Archive& archive, const std::filesystem::path& file);
[[nodiscard]] std::string linux_binary(const ModelDescription& description);  // the library's name in the archive

}  // namespace duet::fmi
