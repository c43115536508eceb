#include "duet/model/block_types.hpp"

#include <algorithm>

namespace duet::model {
namespace {

// Sources have no inputs; delays and integrators' outputs come from their state (no direct feedthrough).
const std::vector<BlockType> table{
    {"Constant", {}, {"y"}, {{"value"}, {"type", false}}},
    {"Gain", {"u"}, {"y"}, {{"k"}}},
    {"Sum", {}, {"y"}, {{"signs", false}}, true, true},
    {"Product", {}, {"y"}, {{"signs", false}}, true, true},
    {"Not", {"u"}, {"y"}, {}},
    {"Logic", {}, {"y"}, {{"operator"}}, true, true},
    {"Compare", {"u"}, {"y"}, {{"operator"}, {"value"}}},
    {"Relational", {"u1", "u2"}, {"y"}, {{"operator"}}},
    {"Switch", {"on", "condition", "off"}, {"y"}, {}},
    {"Saturation", {"u"}, {"y"}, {{"lower"}, {"upper"}}},
    {"DeadZone", {"u"}, {"y"}, {{"start"}, {"end"}}},
    {"Abs", {"u"}, {"y"}, {}},
    {"Sign", {"u"}, {"y"}, {}},
    {"MinMax", {}, {"y"}, {{"function"}}, true, true},
    {"Atan2", {"y_in", "x_in"}, {"y"}, {}},
    {"Convert", {"u"}, {"y"}, {{"type"}}},
    {"Mux", {}, {"y"}, {}, true, true},
    {"Demux", {"u"}, {"y1", "y2", "y3", "y4", "y5", "y6", "y7", "y8"}, {}},
    // Bytes: a message or a register burst <-> values (Simulink's Byte Pack and Byte Unpack).
    {"BytePack", {}, {"y"}, {{"endian", false}}, true, true},
    {"ByteUnpack", {"u"}, {"y"}, {{"type"}, {"endian", false}, {"offset", false}, {"count", false}}},
    {"Selector", {"u", "index"}, {"y"}, {}},
    {"Lookup", {"index"}, {"y"}, {{"table"}}},
    {"Interpolation", {"u"}, {"y"}, {{"breakpoints"}, {"table"}, {"method", false}, {"extrapolation", false}}},
    {"Counter", {}, {"y"}, {{"limit"}, {"initial", false}, {"type", false}}, false},
    // Sources counting their own steps (Simulink's sample-based Step and Pulse Generator).
    {"Step", {}, {"y"}, {{"time_s"}, {"initial", false}, {"final"}, {"type", false}}, false},
    {"PulseGenerator",
     {},
     {"y"},
     {{"period_s"}, {"width_s"}, {"delay_s", false}, {"amplitude", false}, {"type", false}},
     false},
    {"UnitDelay", {"u"}, {"y"}, {{"initial", false}}, false},
    {"DiscreteIntegrator",
     {"u"},
     {"y"},
     {{"gain", false}, {"initial", false}, {"lower", false}, {"upper", false}},
     false},
    {"DiscreteDerivative", {"u"}, {"y"}, {{"gain", false}}},
    {"FilteredDerivative", {"u"}, {"y"}, {{"gain", false}, {"n"}}},
    {"TransferFunction", {"u"}, {"y"}, {{"numerator"}, {"denominator"}}},
    {"StateSpace", {"u"}, {"y"}, {{"a"}, {"b"}, {"c"}, {"d"}, {"initial", false}}},
    {"Mean", {"u"}, {"y"}, {}},
    {"MovingAverage", {"u"}, {"y"}, {{"window"}, {"initial", false}}},
    {"KalmanFilter",
     {"measured"},
     {"estimate"},
     {{"a"},
      {"c"},
      {"g", false},
      {"q", false},
      {"r", false},
      {"gain", false},
      {"initial", false},
      {"covariance", false}}},
    {"StateFeedback", {"x"}, {"y"}, {{"k"}}},
    // Its gains P, I, D are parameters, or inputs (Simulink's external gains) where those are connected; reset, where
    // connected, holds it at rest while true (Simulink's external reset, level).
    {"DiscretePid",
     {"error"},
     {"y"},
     {{"p", false},
      {"i", false},
      {"d", false},
      {"n", false},
      {"lower", false},
      {"upper", false},
      {"anti_windup", false}},
     true,
     false,
     false,
     {"p", "i", "d", "reset"}},
    {"MatrixMultiply", {"a", "b"}, {"y"}, {}},
    {"EdgeDetect", {"u"}, {"y"}, {{"edge"}}, true},
    {"RateTransition", {"u"}, {"y"}, {{"mode", false}, {"initial", false}}, false},
    {"Inport", {}, {"y"}, {{"size", false}}, false},
    {"Outport", {"u"}, {}, {}},
    // Hardware: each port implements them (docs/MODELS.md).
    {"GpioIn", {}, {"y"}, {{"pin"}}},
    {"GpioOut", {"u"}, {}, {{"pin"}}},
    {"PwmOut", {"duty"}, {}, {{"timer"}, {"channel"}, {"frequency_hz"}}},
    {"InputCapture", {}, {"count", "edge"}, {{"timer"}, {"channel"}}},
    {"SpiDma", {"transmit"}, {"received"}, {{"spi"}, {"size"}}},
    {"SpiReceive", {}, {"received"}, {{"spi"}, {"size"}}},
    {"Exti", {}, {"level"}, {{"line"}}},
    {"AdcStart", {}, {}, {{"adc"}, {"channel"}, {"count"}}},
    {"AdcDma", {}, {"samples"}, {{"adc"}, {"channel"}, {"count"}}},
    {"IpcSend", {}, {}, {{"channel"}}, true, true},
    {"IpcReceive", {}, {"y"}, {{"channel"}, {"size"}}},
    // A plant that is a model (docs/MODELS.md): what the controller writes to a resource, and what it reads from one.
    {"PlantInput", {}, {"y"}, {{"resource"}, {"size", false}}},
    {"PlantOutput", {"u"}, {}, {{"resource"}}},
    // Instances declare their own ports.
    {"Subsystem", {}, {}, {}, true, false, true},
    {"Code", {}, {}, {}, true, false, true},
};

}  // namespace

std::span<const BlockType> block_types() { return table; }

bool is_word_parameter(std::string_view parameter) {
  constexpr std::string_view words[] = {"pin",      "timer",  "spi",         "adc",    "line",         "channel",
                                        "operator", "mode",   "type",        "signs",  "edge",         "resource",
                                        "function", "endian", "anti_windup", "method", "extrapolation"};
  return std::find(std::begin(words), std::end(words), parameter) != std::end(words);
}

const BlockType* find_block_type(std::string_view name) {
  const auto found =
      std::find_if(table.begin(), table.end(), [name](const BlockType& type) { return type.name == name; });
  return found == table.end() ? nullptr : &*found;
}

bool is_plant_resource(std::string_view type) {
  return type == "PlantInput" || type == "PlantOutput" || type == "Inport" || type == "Outport";
}

}  // namespace duet::model
