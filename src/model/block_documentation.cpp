#include "duet/model/block_documentation.hpp"

#include <algorithm>
#include <array>

namespace duet::model {
namespace {

using Kind = ParameterDocumentation::Kind;

constexpr std::string_view data_types[] = {"double", "single", "int8",   "int16",  "int32",
                                           "uint8",  "uint16", "uint32", "boolean"};
constexpr std::string_view comparisons[] = {"<", "<=", "==", "!=", ">=", ">"};
constexpr std::string_view logic_operators[] = {"AND", "OR", "XOR", "NAND", "NOR"};
constexpr std::string_view extrema[] = {"min", "max"};
constexpr std::string_view byte_orders[] = {"little", "big"};
constexpr std::string_view edges[] = {"rising", "falling", "either"};
constexpr std::string_view anti_windups[] = {"none", "clamping"};
constexpr std::string_view transitions[] = {"deterministic", "latest"};
constexpr std::string_view interpolations[] = {"linear", "nearest", "flat", "above"};
constexpr std::string_view extrapolations[] = {"clip", "linear"};

constexpr ParameterDocumentation number(std::string_view name, std::string_view description) {
  return {.name = name, .description = description};
}
constexpr ParameterDocumentation at_least(std::string_view name, double minimum, std::string_view description) {
  return {.name = name, .description = description, .minimum = minimum};
}
constexpr ParameterDocumentation count(std::string_view name, double minimum, std::string_view description) {
  return {.name = name, .description = description, .minimum = minimum, .integer = true};
}
constexpr ParameterDocumentation word(std::string_view name, std::string_view description,
                                      std::span<const std::string_view> choices = {}) {
  return {.name = name, .description = description, .choices = choices, .kind = Kind::word};
}
constexpr ParameterDocumentation type(std::string_view description) {
  return {.name = "type", .description = description, .choices = data_types, .kind = Kind::data_type};
}

constexpr ParameterDocumentation constant[] = {
    number("value", "the value: a literal, a constant's name, or a tunable parameter's name"),
    type("its type (default: the parameter's, or double)")};
constexpr ParameterDocumentation gain[] = {number("k", "the factor: a scalar, or one per element")};
constexpr ParameterDocumentation sum[] = {word("signs", "one + or - per input, left to right (default all +)")};
constexpr ParameterDocumentation product[] = {word("signs", "one * or / per input (default all *)")};
constexpr ParameterDocumentation logic[] = {word("operator", "the operation on all inputs", logic_operators)};
constexpr ParameterDocumentation compare[] = {word("operator", "the comparison u OPERATOR value", comparisons),
                                              number("value", "what u is compared with")};
constexpr ParameterDocumentation relational[] = {word("operator", "the comparison u1 OPERATOR u2", comparisons)};
constexpr ParameterDocumentation dead_zone[] = {number("start", "where the zone starts (u below: u - start)"),
                                                number("end", "where it ends, start or above (u above: u - end)")};
constexpr ParameterDocumentation interpolation[] = {
    number("breakpoints", "the inputs of the table's values, strictly increasing, 2 or more"),
    number("table", "one value per breakpoint"),
    word("method", "linear (default), nearest, flat (the breakpoint at or below) or above", interpolations),
    word("extrapolation", "beyond the breakpoints: clip (default) or linear (with method linear)", extrapolations)};
constexpr ParameterDocumentation saturation[] = {number("lower", "the smallest output"),
                                                 number("upper", "the largest output")};
constexpr ParameterDocumentation minmax[] = {word("function", "minimum or maximum, element-wise", extrema)};
constexpr ParameterDocumentation convert[] = {type("the output's type (saturating; floating to integer truncates)")};
constexpr ParameterDocumentation byte_pack[] = {
    word("endian", "the byte order of each value (default little)", byte_orders)};
constexpr ParameterDocumentation byte_unpack[] = {
    type("the type of the values"), word("endian", "the byte order (default little)", byte_orders),
    count("offset", 0, "the first byte used (default 0)"), count("count", 1, "how many values (default 1)")};
constexpr ParameterDocumentation lookup[] = {number("table", "the values, indexed from 0 (clamped at the ends)")};
constexpr ParameterDocumentation counter[] = {count("limit", 1, "the last count before it starts again at 0"),
                                              count("initial", 0, "the first count (default 0)"),
                                              type("its type (default uint32)")};
constexpr ParameterDocumentation step[] = {at_least("time_s", 0, "when it steps, counted in steps of its rate"),
                                           number("initial", "the output before (default 0)"),
                                           number("final", "the output from time_s on"), type("its type")};
constexpr ParameterDocumentation pulse[] = {at_least("period_s", 0, "the pulse period"),
                                            at_least("width_s", 0, "how long each pulse is"),
                                            at_least("delay_s", 0, "when the first pulse starts (default 0)"),
                                            number("amplitude", "the pulse's value (default 1)"), type("its type")};
constexpr ParameterDocumentation unit_delay[] = {number("initial", "the output of the first step (default 0)")};
constexpr ParameterDocumentation integrator[] = {number("gain", "K in y += K Ts u (default 1)"),
                                                 number("initial", "the state at the start (default 0)"),
                                                 number("lower", "the state's lower limit (default none)"),
                                                 number("upper", "the state's upper limit (default none)")};
constexpr ParameterDocumentation derivative[] = {number("gain", "K in K (u - u before) / Ts (default 1)")};
constexpr ParameterDocumentation filtered_derivative[] = {number("gain", "the derivative gain (default 1)"),
                                                          at_least("n", 0, "the filter coefficient N, 1/s")};
constexpr ParameterDocumentation transfer_function[] = {
    number("numerator", "b0..bN, highest power of z first"),
    number("denominator", "a0..aN, highest power of z first (a0 not 0)")};
constexpr ParameterDocumentation state_space[] = {
    number("a", "the state matrix A"), number("b", "the input matrix B"), number("c", "the output matrix C"),
    number("d", "the feedthrough matrix D"), number("initial", "the initial state (default 0)")};
constexpr ParameterDocumentation moving_average[] = {count("window", 1, "how many inputs are averaged"),
                                                     number("initial", "the inputs assumed before the first")};
constexpr ParameterDocumentation kalman[] = {
    number("a", "the state transition A"),
    number("c", "the measurement matrix C"),
    number("g", "how the process noise enters, G"),
    number("q", "the process noise covariance Q"),
    number("r", "the measurement noise covariance R"),
    number("gain", "a steady-state gain (duet design kalman) instead of g, q, r"),
    number("initial", "the initial estimate (default 0)"),
    number("covariance", "the initial covariance P (default I)")};
constexpr ParameterDocumentation state_feedback[] = {number("k", "the gain K in y = -K x (duet design lqr)")};
constexpr ParameterDocumentation pid[] = {
    number("p", "the proportional gain (or the input p)"),
    number("i", "the integral gain (or the input i)"),
    number("d", "the derivative gain (or the input d)"),
    at_least("n", 0, "the derivative filter coefficient N, 1/s (default 100)"),
    number("lower", "the output's lower limit (default none)"),
    number("upper", "the output's upper limit (default none)"),
    word("anti_windup", "clamping stops integrating while the output is limited (default none)", anti_windups)};
constexpr ParameterDocumentation edge_detect[] = {word("edge", "which change of u gives true", edges)};
constexpr ParameterDocumentation rate_transition[] = {
    word("mode",
         "deterministic between periodic rates, latest where an interrupt task meets a rate (default: what the rates "
         "need)",
         transitions),
    number("initial", "the output before the first value arrives (default 0)")};
constexpr ParameterDocumentation gpio_in[] = {word("pin", "the pin, by the port's name for it (LED0, PE8)")};
constexpr ParameterDocumentation gpio_out[] = {word("pin", "the pin, by the port's name for it (LED0, PA5)")};
constexpr ParameterDocumentation pwm_out[] = {word("timer", "the timer (TIM1)"), word("channel", "its channel (1)"),
                                              at_least("frequency_hz", 0, "the PWM frequency")};
constexpr ParameterDocumentation input_capture[] = {word("timer", "the timer (TIM2)"),
                                                    word("channel", "its channel (1)")};
constexpr ParameterDocumentation spi_dma[] = {word("spi", "the SPI (SPI5)"), count("size", 1, "bytes per transfer")};
constexpr ParameterDocumentation exti[] = {word("line", "the external interrupt line (EXTI8)")};
constexpr ParameterDocumentation adc[] = {word("adc", "the converter (ADC1)"), word("channel", "its channel (6)"),
                                          count("count", 1, "conversions per DMA sequence")};
constexpr ParameterDocumentation ipc_send[] = {word("channel", "the application channel's name for the values")};
constexpr ParameterDocumentation ipc_receive[] = {word("channel", "the application channel's name for the values"),
                                                  count("size", 1, "how many values arrive")};
constexpr ParameterDocumentation plant_input[] = {word("resource", "the resource the controller writes (pwm:TIM1/3)"),
                                                  count("size", 1, "its elements (default 1)")};
constexpr ParameterDocumentation plant_output[] = {word("resource", "the resource the controller reads")};
constexpr ParameterDocumentation inport[] = {count("size", 1, "its elements (default 1)")};

constexpr BlockDocumentation table[] = {
    {"Constant", "sources", "A value: a literal, a constant, or a tunable parameter read where it is used", constant},
    {"Gain", "math", "k·u, element-wise", gain},
    {"Sum", "math", "u1 ± u2 ± ..., left to right", sum},
    {"Product", "math", "u1·u2·..., left to right; a / divides by that input", product},
    {"Not", "logic", "The boolean negation", {}},
    {"Logic", "logic", "AND, OR, XOR, NAND or NOR of the inputs (a number is true when not 0)", logic},
    {"Compare", "logic", "u compared with a value: a boolean", compare},
    {"Relational", "logic", "u1 compared with u2, element by element (a scalar with each element): a boolean",
     relational},
    {"Switch", "signals", "condition (not 0) ? on : off", {}},
    {"Saturation", "math", "u limited to lower..upper", saturation},
    {"DeadZone", "math", "0 for start <= u <= end, else u - start or u - end", dead_zone},
    {"Abs", "math", "|u|", {}},
    {"Sign", "math", "-1, 0 or 1 (a NaN gives 0)", {}},
    {"MinMax", "math", "The element-wise minimum or maximum of the inputs; a NaN loses to a number", minmax},
    {"Atan2", "math", "The angle of (x_in, y_in) in radians", {}},
    {"Convert", "signals", "u in another type, saturated", convert},
    {"Mux", "signals", "A vector of the inputs", {}},
    {"Demux", "signals", "The elements of a vector, one per output", {}},
    {"BytePack", "signals", "The inputs' bytes in order, as uint8 (a message, a register burst)", byte_pack},
    {"ByteUnpack", "signals", "Values of a type from bytes", byte_unpack},
    {"Selector", "signals", "The element of u at index (0-based, clamped)", {}},
    {"Lookup", "signals", "The table's element at index (0-based, clamped)", lookup},
    {"Interpolation", "math", "The table at u, interpolated between breakpoints (Simulink's 1-D Lookup Table)",
     interpolation},
    {"Counter", "sources", "0, 1, ..., limit, 0, ... one count per step", counter},
    {"Step", "sources", "initial, then from time_s on final", step},
    {"PulseGenerator", "sources", "amplitude for width_s of every period_s after delay_s, else 0", pulse},
    {"UnitDelay", "discrete", "u of the step before", unit_delay},
    {"DiscreteIntegrator", "discrete", "Forward Euler integral of u, the state limited", integrator},
    {"DiscreteDerivative", "discrete", "gain·(u - u before)/Ts", derivative},
    {"FilteredDerivative", "discrete", "The PID's filtered derivative on its own: gain·N/(1 + N·Ts/(z-1))",
     filtered_derivative},
    {"TransferFunction", "discrete", "A discrete transfer function in z, direct form II transposed", transfer_function},
    {"StateSpace", "discrete", "x(k+1) = A x + B u, y = C x + D u", state_space},
    {"Mean", "math", "The mean of a vector's elements", {}},
    {"MovingAverage", "discrete", "The mean of the last window inputs", moving_average},
    {"KalmanFilter", "control", "The filtered estimate x[k|k] from the measurements", kalman},
    {"StateFeedback", "control", "y = -K x", state_feedback},
    {"DiscretePid", "control",
     "Parallel PID with derivative filter N, forward Euler, output limits and anti-windup (Simulink's form)", pid},
    {"MatrixMultiply", "math", "a·b, row-major; a vector is a column", {}},
    {"EdgeDetect", "logic", "True in the step in which u changes as chosen", edge_detect},
    {"RateTransition", "rates", "Where two rates meet: hands a value from one task to another safely", rate_transition},
    {"Inport", "structure",
     "An input of the model: bound by a model reference, or read from the plant as inport:NAME on its own", inport},
    {"Outport",
     "structure",
     "An output of the model: bound by a model reference, or written to the plant as outport:NAME on its own",
     {}},
    {"GpioIn", "hardware", "A pin's level", gpio_in},
    {"GpioOut", "hardware", "Sets a pin's level", gpio_out},
    {"PwmOut", "hardware", "Sets a PWM channel's duty (0 to 1)", pwm_out},
    {"InputCapture", "hardware", "A timer channel's captured count and edge", input_capture},
    {"SpiDma", "hardware", "An SPI transfer by DMA: what it sends, and what came back", spi_dma},
    {"SpiReceive", "hardware", "What the last SPI transfer received (in the receive-complete task)", spi_dma},
    {"Exti", "hardware", "An external interrupt line's level", exti},
    {"AdcStart", "hardware", "Starts a DMA sequence of count conversions", adc},
    {"AdcDma", "hardware", "The samples of the last DMA sequence", adc},
    {"IpcSend", "hardware", "Sends the inputs to Linux over the application channel", ipc_send},
    {"IpcReceive", "hardware", "The values Linux sent last over the application channel", ipc_receive},
    {"PlantInput", "hardware", "A plant model's side of a resource the controller writes", plant_input},
    {"PlantOutput", "hardware", "A plant model's side of a resource the controller reads", plant_output},
    {"Subsystem",
     "structure",
     "Blocks of their own, with named ports; triggered by an interrupt or an edge, or enabled by a signal",
     {}},
    {"Code", "structure", "A C++ function beside the model, with declared ports, parameters and state", {}},
};

}  // namespace

const BlockDocumentation* find_block_documentation(std::string_view type) {
  const auto* const found = std::find_if(std::begin(table), std::end(table),
                                         [type](const BlockDocumentation& entry) { return entry.type == type; });
  return found == std::end(table) ? nullptr : found;
}

const ParameterDocumentation* find_parameter_documentation(const BlockDocumentation& block,
                                                           std::string_view parameter) {
  const auto found = std::find_if(block.parameters.begin(), block.parameters.end(),
                                  [parameter](const ParameterDocumentation& entry) { return entry.name == parameter; });
  return found == block.parameters.end() ? nullptr : &*found;
}

std::span<const std::string_view> data_type_names() { return data_types; }

}  // namespace duet::model
