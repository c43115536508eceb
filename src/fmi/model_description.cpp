#include "duet/fmi/model_description.hpp"

namespace duet::fmi {

std::string_view xml_name(VariableType type) {
  switch (type) {
    case VariableType::real: return "Real";
    case VariableType::integer: return "Integer";
    case VariableType::boolean: return "Boolean";
    case VariableType::string: return "String";
    case VariableType::enumeration: return "Enumeration";
    case VariableType::float32: return "Float32";
    case VariableType::float64: return "Float64";
    case VariableType::int8: return "Int8";
    case VariableType::uint8: return "UInt8";
    case VariableType::int16: return "Int16";
    case VariableType::uint16: return "UInt16";
    case VariableType::int32: return "Int32";
    case VariableType::uint32: return "UInt32";
    case VariableType::int64: return "Int64";
    case VariableType::uint64: return "UInt64";
    case VariableType::binary: return "Binary";
    case VariableType::clock: return "Clock";
  }
  return "";
}

std::string_view xml_name(Causality causality) {
  switch (causality) {
    case Causality::parameter: return "parameter";
    case Causality::calculated_parameter: return "calculatedParameter";
    case Causality::structural_parameter: return "structuralParameter";
    case Causality::input: return "input";
    case Causality::output: return "output";
    case Causality::local: return "local";
    case Causality::independent: return "independent";
  }
  return "";
}

std::string_view xml_name(Variability variability) {
  switch (variability) {
    case Variability::constant: return "constant";
    case Variability::fixed: return "fixed";
    case Variability::tunable: return "tunable";
    case Variability::discrete: return "discrete";
    case Variability::continuous: return "continuous";
  }
  return "";
}

std::string_view xml_name(Initial initial) {
  switch (initial) {
    case Initial::none: return "";
    case Initial::exact: return "exact";
    case Initial::approx: return "approx";
    case Initial::calculated: return "calculated";
  }
  return "";
}

bool is_float(VariableType type) {
  return type == VariableType::real || type == VariableType::float32 || type == VariableType::float64;
}

}  // namespace duet::fmi
