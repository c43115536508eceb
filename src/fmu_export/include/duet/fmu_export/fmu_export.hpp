#pragma once
// `duet fmu export`: a model as an FMI 2.0 or 3.0 co-simulation FMU (docs/FMI.md, "Export"). Its library is the
// model's generated code, the code the firmware runs, built by the PC's C++ compiler with the FMU's glue.

#include <filesystem>
#include <string>
#include <vector>

#include "duet/fmi/model_description.hpp"
#include "duet/model/program.hpp"
#include "duet/support/result.hpp"

namespace duet::fmu_export {

struct ExportSummary {
  std::string model_identifier;
  std::size_t variables = 0;
  std::vector<std::string> notes;  // what the FMU leaves out of the model (interrupt tasks)
};

// Writes `fmu`, or fails with the reason (the compiler's output when the build fails). `model_file` is where the
// program's model came from: Code blocks' headers are found beside it.
[[nodiscard]] Result<ExportSummary> export_fmu(const model::Program& program, const std::filesystem::path& model_file,
                                               const std::filesystem::path& fmu, fmi::FmiVersion version);

}  // namespace duet::fmu_export
