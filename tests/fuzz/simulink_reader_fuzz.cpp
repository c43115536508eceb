// libFuzzer target: arbitrary bytes through the Simulink importer's readers. The first byte chooses which: the
// classic .mdl reader, the packaged text .mdl (its parts, then the .slx reader over them), the .slx reader over a
// lone blockdiagram.xml, the MATLAB expression evaluator, or the .m script reader. Each either reads its input or
// refuses it with a message; none may crash, hang or grow without bound. A model read is imported too, which must
// end the same way.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "duet/simulink_import/classic_mdl.hpp"
#include "duet/simulink_import/import.hpp"
#include "duet/simulink_import/matlab_expression.hpp"
#include "duet/simulink_import/matlab_script.hpp"
#include "duet/simulink_import/slx_model.hpp"
#include "duet/simulink_import/slx_parts.hpp"

namespace simulink = duet::simulink_import;

namespace {

void import(const duet::Result<simulink::SimulinkModel>& model) {
  if (model)
    (void)simulink::import_simulink(model.value(), {.variables = {}, .base_period_us = 1000, .interrupts = {}});
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view bytes{reinterpret_cast<const char*>(data) + 1, size - 1};
  switch (data[0] % 5) {
    case 0: import(simulink::read_classic_mdl(bytes, "fuzz.mdl")); break;
    case 1: {
      const auto parts = simulink::read_packaged_mdl_parts(bytes, "fuzz.mdl");
      if (parts) import(simulink::read_slx_model(parts.value(), "fuzz.mdl"));
      break;
    }
    case 2:
      import(simulink::read_slx_model({{ "simulink/blockdiagram.xml", std::string { bytes } }}, "fuzz.slx"));
      break;
    case 3: (void)simulink::evaluate(bytes, {}); break;
    default: (void)simulink::read_m_script(bytes, "fuzz.m"); break;
  }
  return 0;
}
