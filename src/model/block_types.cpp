#include "duet/model/block_types.hpp"

#include <algorithm>

namespace duet::model {
namespace {

// Sources have no inputs; delays and integrators' outputs come from their state (no direct feedthrough).
const std::vector<BlockType> table{
    {"Constant", {}, {"y"}, {{"value"}, {"type", false}}},
    {"Gain", {"u"}, {"y"}, {{"k"}}},
    {"Sum", {}, {"y"}, {{"signs", false}}, true, true},
    {"Product", {}, {"y"}, {}, true, true},
    {"Not", {"u"}, {"y"}, {}},
    {"Logic", {}, {"y"}, {{"operator"}}, true, true},
    {"Compare", {"u"}, {"y"}, {{"operator"}, {"value"}}},
    {"Switch", {"on", "condition", "off"}, {"y"}, {}},
    {"Saturation", {"u"}, {"y"}, {{"lower"}, {"upper"}}},
    {"Abs", {"u"}, {"y"}, {}},
    {"Atan2", {"y_in", "x_in"}, {"y"}, {}},
    {"Convert", {"u"}, {"y"}, {{"type"}}},
    {"Mux", {}, {"y"}, {}, true, true},
    {"Demux", {"u"}, {"y1", "y2", "y3", "y4"}, {}},
    {"Selector", {"u", "index"}, {"y"}, {}},
    {"Lookup", {"index"}, {"y"}, {{"table"}}},
    {"Counter", {}, {"y"}, {{"limit"}, {"initial", false}, {"type", false}}, false},
    {"UnitDelay", {"u"}, {"y"}, {{"initial", false}}, false},
    {"DiscreteIntegrator",
     {"u"},
     {"y"},
     {{"gain", false}, {"initial", false}, {"lower", false}, {"upper", false}},
     false},
    {"DiscreteDerivative", {"u"}, {"y"}, {{"gain", false}}},
    {"DiscretePid",
     {"error"},
     {"y"},
     {{"p"}, {"i", false}, {"d", false}, {"n", false}, {"lower", false}, {"upper", false}}},
    {"MatrixMultiply", {"a", "b"}, {"y"}, {}},
    {"EdgeDetect", {"u"}, {"y"}, {{"edge"}}, true},
    {"RateTransition", {"u"}, {"y"}, {{"mode", false}, {"initial", false}}, false},
    {"Outport", {"u"}, {}, {}},
    // Hardware: each port implements them (docs/MODELS.md).
    {"GpioIn", {}, {"y"}, {{"pin"}}},
    {"GpioOut", {"u"}, {}, {{"pin"}}},
    {"PwmOut", {"duty"}, {}, {{"timer"}, {"channel"}, {"frequency_hz"}}},
    {"InputCapture", {}, {"count", "edge"}, {{"timer"}, {"channel"}}},
    {"SpiDma", {"transmit"}, {"received"}, {{"spi"}, {"size"}}},
    {"Exti", {}, {"level"}, {{"line"}}},
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
  constexpr std::string_view words[] = {"pin",      "timer", "spi",  "adc",   "line", "channel",
                                        "operator", "mode",  "type", "signs", "edge", "resource"};
  return std::find(std::begin(words), std::end(words), parameter) != std::end(words);
}

const BlockType* find_block_type(std::string_view name) {
  const auto found =
      std::find_if(table.begin(), table.end(), [name](const BlockType& type) { return type.name == name; });
  return found == table.end() ? nullptr : &*found;
}

}  // namespace duet::model
