#include "duet/fmi/fmu_contents.hpp"

#include "duet/fmi/model_description_reader.hpp"

namespace duet::fmi {

Result<ModelDescription> read_description(const Archive& archive, const std::filesystem::path& file) {
  if (!archive.contains("modelDescription.xml"))
    return Failure{file.string() + ": no modelDescription.xml at the archive's root"};
  auto xml = archive.read("modelDescription.xml");
  if (!xml) return Failure{xml.error()};
  auto description = read_model_description(xml.value());
  if (!description) return Failure{file.string() + ": " + description.error()};
  return description;
}

std::string linux_binary(const ModelDescription& description) {
  return std::string{"binaries/"} + (description.version == FmiVersion::v2 ? "linux64" : "x86_64-linux") + "/" +
         description.co_simulation.model_identifier + ".so";
}

}  // namespace duet::fmi
