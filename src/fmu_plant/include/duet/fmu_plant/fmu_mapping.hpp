#pragma once
// The mapping file of an FMU plant (docs/FMI.md, "The mapping file"): which FMU variable meets which of the
// controller's resources, element by element, with optional units; values for parameters and start values; which
// locals to record. Read here, checked against the FMU's description, every problem as "FILE:LINE: what".

#include <cstddef>
#include <string>
#include <vector>

#include "duet/fmi/model_description.hpp"
#include "duet/support/result.hpp"

namespace duet::fmu_plant {

struct Connection {
  std::string variable;  // the FMU's
  std::string resource;  // the controller's: "pwm:TIM1/1", "adc:ADC1/6", "gpio:LED0"
  std::size_t element = 0;
  std::string unit;  // the controller's side, checked against the FMU variable's when both say one
  int line = 0;
};

struct Setting {
  std::string variable;
  double value = 0;
  std::string place;  // "FILE:LINE" or "--fmu-set 'T=1'", for messages
};

struct FmuMapping {
  std::string file;
  std::vector<Connection> inputs;     // FMU inputs, driven by what the controller writes to the resource
  std::vector<Connection> outputs;    // FMU outputs, answering the controller's reads of the resource
  std::vector<Setting> settings;      // in the file's order, then the command line's
  std::vector<std::string> observed;  // recorded beside the outputs
};

// Reads `file`; checks only its own form.
[[nodiscard]] Result<FmuMapping> read_fmu_mapping(const std::string& file);

// "NAME=VALUE" from the command line (a number, or true/false), added after the file's settings.
[[nodiscard]] Status add_setting(FmuMapping& mapping, const std::string& text);

// The mapping against the FMU: every variable known and of the right causality, units alike where both say one,
// values settable and numeric, every FMU input connected or given a value, nothing connected twice.
[[nodiscard]] Status check_fmu_mapping(const FmuMapping& mapping, const fmi::ModelDescription& description);

}  // namespace duet::fmu_plant
