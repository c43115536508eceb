#include "duet/simulink_import/builtin_defaults.hpp"

#include <array>
#include <charconv>

namespace duet::simulink_import {
namespace {

// A release as one number that orders them: R2019b -> 2019 * 2 + 1.
constexpr int newest = 1'000'000;
int release_order(std::string_view release) {
  int year = 0;
  if (release.size() != 6 || release[0] != 'R') return newest;
  const auto [end, error] = std::from_chars(release.data() + 1, release.data() + 5, year);
  if (error != std::errc{} || end != release.data() + 5 || (release[5] != 'a' && release[5] != 'b')) return newest;
  return year * 2 + (release[5] == 'b' ? 1 : 0);
}
constexpr int r2019b = 2019 * 2 + 1;
constexpr int r2020a = 2020 * 2;

struct Default {
  std::string_view type;
  std::string_view parameter;
  std::string_view value;
  int from = 0;  // the first release that writes this value; an older entry of the same parameter comes first
};

// The BlockParameterDefaults of the block types the importer maps, as files of each era carry them. Where a default
// changed, the older value comes first with from 0, the newer after it with its release.
constexpr std::array defaults{
    Default{"Gain", "Gain", "1"},
    Default{"Gain", "Multiplication", "Element-wise(K.*u)"},
    Default{"Gain", "ParamDataTypeStr", "Inherit: Same as input"},
    Default{"Gain", "ParamDataTypeStr", "Inherit: Inherit via internal rule", r2020a},
    Default{"Gain", "OutDataTypeStr", "Inherit: Same as input"},
    Default{"Gain", "OutDataTypeStr", "Inherit: Inherit via internal rule", r2020a},
    Default{"Gain", "SaturateOnIntegerOverflow", "on"},
    Default{"Gain", "SaturateOnIntegerOverflow", "off", r2020a},
    Default{"Gain", "RndMeth", "Floor"},
    Default{"Gain", "SampleTime", "-1"},
    Default{"Sum", "Inputs", "++"},
    Default{"Sum", "CollapseMode", "All dimensions"},
    Default{"Sum", "CollapseDim", "1"},
    Default{"Sum", "OutDataTypeStr", "Inherit: Same as first input"},
    Default{"Sum", "OutDataTypeStr", "Inherit: Inherit via internal rule", r2020a},
    Default{"Sum", "AccumDataTypeStr", "Inherit: Inherit via internal rule"},
    Default{"Sum", "SaturateOnIntegerOverflow", "on"},
    Default{"Sum", "SaturateOnIntegerOverflow", "off", r2020a},
    Default{"Sum", "RndMeth", "Floor"},
    Default{"Sum", "SampleTime", "-1"},
    Default{"Product", "Inputs", "2"},
    Default{"Product", "Multiplication", "Element-wise(.*)"},
    Default{"Product", "CollapseMode", "All dimensions"},
    Default{"Product", "OutDataTypeStr", "Inherit: Same as input"},
    Default{"Product", "OutDataTypeStr", "Inherit: Inherit via internal rule", r2020a},
    Default{"Product", "SaturateOnIntegerOverflow", "on"},
    Default{"Product", "SaturateOnIntegerOverflow", "off", r2020a},
    Default{"Product", "RndMeth", "Zero"},
    Default{"Product", "RndMeth", "Floor", r2020a},
    Default{"Product", "SampleTime", "-1"},
    Default{"Constant", "Value", "1"},
    Default{"Constant", "VectorParams1D", "on"},
    Default{"Constant", "OutDataTypeStr", "Inherit: Inherit from 'Constant value'"},
    Default{"Constant", "SampleTime", "inf"},
    Default{"UnitDelay", "InitialCondition", "0"},
    Default{"UnitDelay", "SampleTime", "1"},
    Default{"Delay", "DelayLength", "2"},
    Default{"Delay", "DelayLengthSource", "Dialog"},
    Default{"Delay", "InitialCondition", "0.0"},
    Default{"Delay", "InitialConditionSource", "Dialog"},
    Default{"Delay", "ExternalReset", "None"},
    Default{"Delay", "ShowEnablePort", "off"},
    Default{"Delay", "SampleTime", "-1"},
    Default{"DiscreteIntegrator", "IntegratorMethod", "Integration: Forward Euler"},
    Default{"DiscreteIntegrator", "gainval", "1.0"},
    Default{"DiscreteIntegrator", "ExternalReset", "none"},
    Default{"DiscreteIntegrator", "InitialConditionSource", "internal"},
    Default{"DiscreteIntegrator", "InitialCondition", "0"},
    Default{"DiscreteIntegrator", "InitialConditionSetting", "Output"},
    Default{"DiscreteIntegrator", "LimitOutput", "off"},
    Default{"DiscreteIntegrator", "UpperSaturationLimit", "inf"},
    Default{"DiscreteIntegrator", "LowerSaturationLimit", "-inf"},
    Default{"DiscreteIntegrator", "ShowSaturationPort", "off"},
    Default{"DiscreteIntegrator", "ShowStatePort", "off"},
    Default{"DiscreteIntegrator", "IgnoreLimit", "off"},
    Default{"DiscreteIntegrator", "SampleTime", "1"},
    Default{"DiscreteTransferFcn", "Numerator", "[1]"},
    Default{"DiscreteTransferFcn", "Denominator", "[1 0.5]"},
    Default{"DiscreteTransferFcn", "NumeratorSource", "Dialog"},
    Default{"DiscreteTransferFcn", "DenominatorSource", "Dialog"},
    Default{"DiscreteTransferFcn", "InitialStates", "0"},
    Default{"DiscreteTransferFcn", "FilterStructure", "Direct form II"},
    Default{"DiscreteTransferFcn", "ExternalReset", "None"},
    Default{"DiscreteTransferFcn", "a0EqualsOne", "off"},
    Default{"DiscreteTransferFcn", "SampleTime", "-1"},
    Default{"DiscreteFilter", "Numerator", "[1]"},
    Default{"DiscreteFilter", "Denominator", "[1 0.5]"},
    Default{"DiscreteFilter", "NumeratorSource", "Dialog"},
    Default{"DiscreteFilter", "DenominatorSource", "Dialog"},
    Default{"DiscreteFilter", "InitialStates", "0"},
    Default{"DiscreteFilter", "ExternalReset", "None"},
    Default{"DiscreteFilter", "a0EqualsOne", "off"},
    Default{"DiscreteFilter", "SampleTime", "-1"},
    Default{"DiscreteStateSpace", "A", "1"},
    Default{"DiscreteStateSpace", "B", "1"},
    Default{"DiscreteStateSpace", "C", "1"},
    Default{"DiscreteStateSpace", "D", "1"},
    Default{"DiscreteStateSpace", "InitialCondition", "0"},
    Default{"DiscreteStateSpace", "SampleTime", "1"},
    Default{"Saturate", "UpperLimit", "0.5"},
    Default{"Saturate", "LowerLimit", "-0.5"},
    Default{"Saturate", "UpperLimitSource", "Dialog"},
    Default{"Saturate", "LowerLimitSource", "Dialog"},
    Default{"Saturate", "OutDataTypeStr", "Inherit: Same as input"},
    Default{"Switch", "Criteria", "u2 >= Threshold"},
    Default{"Switch", "Threshold", "0"},
    Default{"RelationalOperator", "Operator", ">="},
    Default{"Logic", "Operator", "AND"},
    Default{"Logic", "Inputs", "2"},
    Default{"Abs", "SaturateOnIntegerOverflow", "on"},
    Default{"DeadZone", "LowerValue", "-0.5"},
    Default{"DeadZone", "UpperValue", "0.5"},
    Default{"MinMax", "Function", "min"},
    Default{"MinMax", "Inputs", "1"},
    Default{"Trigonometry", "Operator", "sin"},
    Default{"Trigonometry", "ApproximationMethod", "None"},
    Default{"Math", "Operator", "exp"},
    Default{"Sqrt", "Operator", "sqrt"},
    Default{"Lookup_n-D", "NumberOfTableDimensions", "2"},
    Default{"Lookup_n-D", "Table", "[4 5 6;16 19 20;10 18 23]"},
    Default{"Lookup_n-D", "BreakpointsForDimension1", "[10,22,31]"},
    Default{"Lookup_n-D", "BreakpointsSpecification", "Explicit values"},
    Default{"Lookup_n-D", "InterpMethod", "Linear"},
    Default{"Lookup_n-D", "InterpMethod", "Linear point-slope", r2019b},
    Default{"Lookup_n-D", "ExtrapMethod", "Linear"},
    Default{"Lookup_n-D", "DataSpecification", "Table and breakpoints"},
    Default{"Lookup_n-D", "UseLastTableValue", "off"},
    Default{"Mux", "Inputs", "4"},
    Default{"Demux", "Outputs", "4"},
    Default{"Selector", "NumberOfDimensions", "1"},
    Default{"Selector", "IndexMode", "One-based"},
    Default{"Selector", "IndexOptions", "Index vector (dialog)"},
    Default{"Selector", "Indices", "1"},
    Default{"Selector", "InputPortWidth", "-1"},
    Default{"DataTypeConversion", "OutDataTypeStr", "Inherit: Inherit via back propagation"},
    Default{"DataTypeConversion", "ConvertRealWorld", "Real World Value (RWV)"},
    Default{"DataTypeConversion", "RndMeth", "Zero"},
    Default{"DataTypeConversion", "SaturateOnIntegerOverflow", "on"},
    Default{"RateTransition", "Integrity", "on"},
    Default{"RateTransition", "Deterministic", "on"},
    Default{"RateTransition", "InitialCondition", "0"},
    Default{"RateTransition", "OutPortSampleTimeOpt", "Specify"},
    Default{"RateTransition", "OutPortSampleTime", "-1"},
    Default{"RateTransition", "OutPortSampleTimeMultiple", "1"},
    Default{"ZeroOrderHold", "SampleTime", "1"},
    Default{"Inport", "Port", "1"},
    Default{"Inport", "OutDataTypeStr", "Inherit: auto"},
    Default{"Inport", "PortDimensions", "-1"},
    Default{"Inport", "SampleTime", "-1"},
    Default{"Inport", "OutputFunctionCall", "off"},
    Default{"Outport", "Port", "1"},
    Default{"Outport", "OutputWhenDisabled", "held"},
    Default{"Outport", "InitialOutput", "[]"},
    Default{"Outport", "SampleTime", "-1"},
    Default{"SubSystem", "TreatAsAtomicUnit", "off"},
    Default{"SubSystem", "SystemSampleTime", "-1"},
    Default{"SubSystem", "SFBlockType", "NONE"},
    Default{"TriggerPort", "TriggerType", "rising"},
    Default{"TriggerPort", "StatesWhenEnabling", "held"},
    Default{"TriggerPort", "InitialTriggerSignalState", "compatibility (no trigger on first evaluation)"},
    Default{"TriggerPort", "ShowOutputPort", "off"},
    Default{"EnablePort", "StatesWhenEnabling", "held"},
    Default{"EnablePort", "ShowOutputPort", "off"},
    Default{"From", "GotoTag", "A"},
    Default{"Goto", "GotoTag", "A"},
    Default{"Goto", "TagVisibility", "local"},
};

}  // namespace

std::optional<std::string_view> builtin_default(std::string_view block_type, std::string_view parameter,
                                                std::string_view release) {
  const int saved_by = release_order(release);
  std::optional<std::string_view> value;
  for (const Default& entry : defaults) {
    if (entry.type == block_type && entry.parameter == parameter && entry.from <= saved_by) value = entry.value;
  }
  return value;
}

}  // namespace duet::simulink_import
