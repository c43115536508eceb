// libFuzzer target: arbitrary bytes as an FMU's modelDescription.xml. The reader refuses them with a line and a
// problem or reads them; what it reads, the writer writes and the reader reads back as the same description.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "duet/fmi/model_description_reader.hpp"
#include "duet/fmi/model_description_writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto description =
      duet::fmi::read_model_description(std::string_view{reinterpret_cast<const char*>(data), size});
  if (!description) return 0;
  const auto xml = duet::fmi::write_model_description(description.value());
  if (!xml) return 0;  // enumerations and clocks are read but not written
  const auto again = duet::fmi::read_model_description(xml.value());
  if (!again || !(again.value() == description.value())) std::abort();
  return 0;
}
