// One mapping per Simulink block type the importer brings over (docs/IMPORT.md, "Blocks"): each checks that every
// option the block has is one whose semantics duet's block has exactly, and refuses otherwise, naming the option.

#include <algorithm>
#include <cmath>
#include <map>
#include <string_view>

#include "import_context.hpp"

namespace duet::simulink_import {
namespace {

std::string quoted(const std::string& text) { return "\"" + text + "\""; }

// Input ports u1..un of a variadic duet block.
std::optional<TextPairs> numbered_inputs(ImportContext& context, std::size_t count) {
  TextPairs inputs;
  for (std::size_t port = 1; port <= count; ++port) {
    const auto signal = context.input(port);
    if (!signal) return std::nullopt;
    inputs.emplace_back("u" + std::to_string(port), *signal);
  }
  return inputs;
}

// Whether the block computes in its inputs' type, as duet's arithmetic blocks do: an output type set explicitly
// (OutDataTypeStr "single" on a Gain fed doubles) is a conversion duet's blocks do not make, and refused.
bool inherits_type(ImportContext& context) {
  const auto found = context.block().parameters.find("OutDataTypeStr");
  if (found == context.block().parameters.end() || found->second.starts_with("Inherit:")) return true;
  context.refuse("OutDataTypeStr '" + found->second + "': duet's " + context.block().type +
                 " computes in its input's type (convert with a DataTypeConversion block)");
  return false;
}

// Whether an option that only newer releases write is, where the block has it, `expected`; refuses with `what`
// otherwise. A file of an older release, without it, computes as `expected` does.
bool absent_or(ImportContext& context, const std::string& name, const std::string& expected, const std::string& what) {
  const Block& block = context.block();
  const bool stored = block.mask_parameters.count(name) != 0 || block.parameters.count(name) != 0;
  return !stored || context.require(name, expected, what);
}

// Whether a logic block's output is a boolean, as duet's Logic, Not, Compare and Relational give: its OutDataTypeStr
// boolean, or the default "Inherit: Logical" (a boolean where the model implements logic signals as booleans, the
// default). Another type (uint8, a fixed-point type) holds the same 0 and 1, but arithmetic after it would not be
// duet's boolean arithmetic: refused.
bool boolean_output(ImportContext& context) {
  const auto found = context.block().parameters.find("OutDataTypeStr");
  if (found == context.block().parameters.end() || found->second == "boolean" ||
      found->second.starts_with("Inherit: Logical"))
    return true;
  context.refuse("OutDataTypeStr '" + found->second +
                 "': duet's logic blocks output booleans (set it to boolean, or convert after it with a "
                 "DataTypeConversion block)");
  return false;
}

// A block of one input u and one output y, its parameters given, at its SampleTime when it has one.
void unary(ImportContext& context, const std::string& type, TextPairs parameters, bool sampled,
           const std::string& what) {
  const auto u = context.input(1);
  const auto period = sampled ? context.period() : std::optional<std::string>{std::string{}};
  if (!u || !period || context.refused()) return;
  context.emit({.type = type,
                .parameters = std::move(parameters),
                .inputs = {{"u", *u}},
                .outputs = {{"y", context.output(1)}},
                .period = *period},
               what);
}

// A count of ports, a whole number from 1 to `most`; refuses anything else (a huge, negative or fractional value
// would be no count of ports at all).
std::optional<std::size_t> port_count(ImportContext& context, const std::string& name, std::size_t most) {
  const auto value = context.scalar(name);
  if (!value) return std::nullopt;
  if (!(*value >= 1 && *value <= static_cast<double>(most) && *value == std::floor(*value))) {
    context.refuse(name + " '" + *context.raw(name) + "' is not a whole number from 1 to " + std::to_string(most));
    return std::nullopt;
  }
  return static_cast<std::size_t>(*value);
}

// The signs of a Sum ("|+-", "++" or a count) or a Product ("*/" or a count), `|` being only the icon's spacing.
std::optional<std::string> signs(ImportContext& context, char sign_of_count) {
  const auto text = context.raw("Inputs");
  if (!text) return std::nullopt;
  std::string signs;
  if (!text->empty() && (*text)[0] >= '0' && (*text)[0] <= '9') {
    const auto count = port_count(context, "Inputs", 64);
    if (!count) return std::nullopt;
    signs.assign(*count, sign_of_count);
  } else {
    for (const char c : *text)
      if (c != '|') signs += c;
  }
  if (signs.size() < 2) {
    context.refuse("one input (Inputs '" + *text + "') combines its elements, which duet's " +
                   (sign_of_count == '+' ? "Sum" : "Product") + " does not: use two inputs or a Mux");
    return std::nullopt;
  }
  return signs;
}

void constant(ImportContext& context) {
  const auto value = context.parameter("Value");
  const auto evaluated = context.value("Value");
  const auto type_text = context.raw("OutDataTypeStr");
  const auto period = context.period();
  if (!value || !evaluated || !type_text || !period) return;
  TextPairs parameters{{"value", *value}};
  std::string type;
  if (*type_text == "Inherit: Inherit from 'Constant value'") {
    if (evaluated->type != MatlabClass::double_class) type = std::string{class_name(evaluated->type)};
  } else if (*type_text != "double") {
    type = *type_text;
  }
  if (type == "logical") type = "boolean";
  if (!type.empty()) parameters.emplace_back("type", type);
  context.emit({.type = "Constant", .parameters = parameters, .outputs = {{"y", context.output(1)}}, .period = *period},
               "Constant " + *value);
}

void gain(ImportContext& context) {
  if (!inherits_type(context)) return;
  const auto multiplication = context.raw("Multiplication");
  const auto gain_type = context.raw("ParamDataTypeStr");
  if (!multiplication || !gain_type) return;
  // A gain of its own type (single, say) is rounded to it before it multiplies; duet's k has the block's type.
  if (!gain_type->starts_with("Inherit:")) {
    context.refuse("ParamDataTypeStr '" + *gain_type + "': duet's Gain keeps k in its input's type");
    return;
  }
  if (*multiplication == "Matrix(K*u)" || *multiplication == "Matrix(K*u) (u vector)") {
    // K times the input taken as a column: a Constant K and a MatrixMultiply.
    const auto k = context.parameter("Gain");
    const auto u = context.input(1);
    const auto period = context.period();
    if (!k || !u || !period) return;
    const std::string matrix = context.new_signal_name(context.block_name + "_k");
    context.emit({.name = context.new_block_name(context.block_name + "_k"),
                  .type = "Constant",
                  .parameters = {{"value", *k}},
                  .outputs = {{"y", matrix}}},
                 "Constant K " + *k);
    context.emit({.type = "MatrixMultiply",
                  .inputs = {{"a", matrix}, {"b", *u}},
                  .outputs = {{"y", context.output(1)}},
                  .period = *period},
                 "MatrixMultiply K u");
    return;
  }
  if (*multiplication != "Element-wise(K.*u)") {
    context.refuse("Multiplication '" + *multiplication + "': duet multiplies element-wise or K*u (Matrix(K*u))");
    return;
  }
  const auto k = context.parameter("Gain");
  if (!k) return;
  unary(context, "Gain", {{"k", *k}}, true, "Gain k: " + *k);
}

void sum(ImportContext& context) {
  if (!inherits_type(context)) return;
  const auto sum_signs = signs(context, '+');
  if (!sum_signs) return;
  const auto inputs = numbered_inputs(context, sum_signs->size());
  const auto period = context.period();
  if (!inputs || !period) return;
  context.emit({.type = "Sum",
                .parameters = {{"signs", quoted(*sum_signs)}},
                .inputs = *inputs,
                .outputs = {{"y", context.output(1)}},
                .period = *period},
               "Sum " + *sum_signs);
}

void product(ImportContext& context) {
  if (!inherits_type(context)) return;
  const auto multiplication = context.raw("Multiplication");
  if (!multiplication) return;
  const bool matrix = *multiplication == "Matrix(*)";
  if (!matrix && *multiplication != "Element-wise(.*)") {
    context.refuse("Multiplication '" + *multiplication + "': duet multiplies element-wise or as matrices (Matrix(*))");
    return;
  }
  const auto product_signs = signs(context, '*');
  if (!product_signs) return;
  if (matrix) {
    // u1 * u2 as matrices; a division would be a matrix inverse, and a longer chain is not imported.
    if (*product_signs != "**") {
      context.refuse("Inputs '" + *context.raw("Inputs") +
                     "' with Matrix(*): duet's matrix product is of two inputs "
                     "(**), without inverses");
      return;
    }
    const auto a = context.input(1);
    const auto b = context.input(2);
    const auto period = context.period();
    if (!a || !b || !period) return;
    context.emit({.type = "MatrixMultiply",
                  .inputs = {{"a", *a}, {"b", *b}},
                  .outputs = {{"y", context.output(1)}},
                  .period = *period},
                 "MatrixMultiply u1 u2");
    return;
  }
  const auto inputs = numbered_inputs(context, product_signs->size());
  const auto period = context.period();
  if (!inputs || !period) return;
  context.emit({.type = "Product",
                .parameters = {{"signs", quoted(*product_signs)}},
                .inputs = *inputs,
                .outputs = {{"y", context.output(1)}},
                .period = *period},
               "Product " + *product_signs);
}

void abs(ImportContext& context) {
  if (inherits_type(context)) unary(context, "Abs", {}, false, "Abs");
}
void sign(ImportContext& context) { unary(context, "Sign", {}, false, "Sign"); }

// A mapping of a block with SaturateOnIntegerOverflow, whose duet block wraps an integer overflow (Gain, Sum, Product)
// or saturates it (Abs). Where Simulink's block does the other, the two agree in floating point only; the import has
// no types, so it says so and the checked model refuses an integer type there (integer_problems).
template <BlockMapping map, bool duet_saturates>
void on_integer_overflow(ImportContext& context) {
  map(context);
  if (context.refused() || context.emitted().empty()) return;
  const auto saturates = context.raw("SaturateOnIntegerOverflow");
  if (!saturates || (*saturates == "on") == duet_saturates) return;
  context.floating_only(std::string{"Simulink "} + (duet_saturates ? "wraps" : "saturates") +
                        " an integer overflow (SaturateOnIntegerOverflow " + *saturates + "), duet's " +
                        context.emitted().back().type + (duet_saturates ? " saturates" : " wraps") + " (set it " +
                        (duet_saturates ? "on" : "off") + " in Simulink, or compute in floating point)");
}

void saturation(ImportContext& context) {
  if (!inherits_type(context)) return;
  for (const char* source : {"UpperLimitSource", "LowerLimitSource"}) {
    if (!absent_or(context, source, "Dialog", "limits from input ports are not duet's Saturation's")) return;
  }
  const auto upper = context.parameter("UpperLimit");
  const auto lower = context.parameter("LowerLimit");
  if (!upper || !lower) return;
  unary(context, "Saturation", {{"lower", *lower}, {"upper", *upper}}, false,
        "Saturation [" + *lower + ", " + *upper + "]");
}

void unit_delay(ImportContext& context) {
  const auto initial = context.parameter("InitialCondition");
  if (!initial) return;
  unary(context, "UnitDelay", {{"initial", *initial}}, true, "UnitDelay from " + *initial);
}

void discrete_integrator(ImportContext& context) {
  if (!context.require("IntegratorMethod", "Integration: Forward Euler",
                       "duet's DiscreteIntegrator integrates by forward Euler only") ||
      !context.require("ExternalReset", "none", "duet's DiscreteIntegrator has no external reset") ||
      !context.require("InitialConditionSource", "internal", "the initial condition must be the block's own") ||
      !context.require("ShowSaturationPort", "off", "duet's DiscreteIntegrator has no saturation port") ||
      !context.require("ShowStatePort", "off", "duet's DiscreteIntegrator has no state port"))
    return;
  TextPairs parameters;
  const auto gain_value = context.parameter("gainval");
  const auto initial = context.parameter("InitialCondition");
  const auto limited = context.raw("LimitOutput");
  if (!gain_value || !initial || !limited) return;
  parameters = {{"gain", *gain_value}, {"initial", *initial}};
  if (*limited == "on") {
    const auto lower = context.parameter("LowerSaturationLimit");
    const auto upper = context.parameter("UpperSaturationLimit");
    if (!lower || !upper) return;
    parameters.emplace_back("lower", *lower);
    parameters.emplace_back("upper", *upper);
  }
  unary(context, "DiscreteIntegrator", parameters, true, "DiscreteIntegrator (forward Euler)");
}

void ground(ImportContext& context) {
  context.emit({.type = "Constant", .parameters = {{"value", "0"}}, .outputs = {{"y", context.output(1)}}},
               "Constant 0");
}

// Nothing: duet needs no sink for a signal nobody reads.
void terminator(ImportContext& context) { (void)context.input(1); }

void switch_block(ImportContext& context) {
  const auto criteria = context.raw("Criteria");
  if (!criteria) return;
  std::string comparison;
  std::optional<std::string> threshold = std::string{"0"};
  if (*criteria == "u2 >= Threshold") {
    comparison = ">=";
    threshold = context.parameter("Threshold");
  } else if (*criteria == "u2 > Threshold") {
    comparison = ">";
    threshold = context.parameter("Threshold");
  } else if (*criteria == "u2 ~= 0") {
    comparison = "!=";
  } else {
    context.refuse("Criteria '" + *criteria + "' is not one duet knows");
    return;
  }
  const auto on = context.input(1);
  const auto control = context.input(2);
  const auto off = context.input(3);
  if (!threshold || !on || !control || !off) return;
  const std::string condition = context.new_signal_name(context.block_name + "_condition");
  context.emit({.name = context.new_block_name(context.block_name + "_criteria"),
                .type = "Compare",
                .parameters = {{"operator", quoted(comparison)}, {"value", *threshold}},
                .inputs = {{"u", *control}},
                .outputs = {{"y", condition}}},
               "Compare u2 " + comparison + " " + *threshold);
  context.emit({.type = "Switch",
                .inputs = {{"on", *on}, {"condition", condition}, {"off", *off}},
                .outputs = {{"y", context.output(1)}}},
               "Switch");
}

void logic(ImportContext& context) {
  const auto operation = context.raw("Operator");
  if (!operation || !boolean_output(context)) return;
  if (*operation == "NOT") {
    unary(context, "Not", {}, false, "Not");
    return;
  }
  if (*operation != "AND" && *operation != "OR" && *operation != "XOR" && *operation != "NAND" && *operation != "NOR") {
    context.refuse("Operator " + *operation + " is not one of duet's Logic (AND, OR, XOR, NAND, NOR, NOT)");
    return;
  }
  const auto count = port_count(context, "Inputs", 64);
  if (!count) return;
  if (*count < 2) {
    context.refuse("one input applies " + *operation +
                   " across its elements, which duet's Logic does not: use two "
                   "inputs or more");
    return;
  }
  const auto inputs = numbered_inputs(context, *count);
  if (!inputs) return;
  context.emit({.type = "Logic",
                .parameters = {{"operator", *operation}},
                .inputs = *inputs,
                .outputs = {{"y", context.output(1)}}},
               "Logic " + *operation);
}

void min_max(ImportContext& context) {
  if (!inherits_type(context)) return;
  const auto function = context.raw("Function");
  const auto count = port_count(context, "Inputs", 64);
  if (!function || !count) return;
  if (*count < 2) {
    context.refuse("one input takes the extreme of its elements, which duet's MinMax does not");
    return;
  }
  const auto inputs = numbered_inputs(context, *count);
  if (!inputs) return;
  context.emit({.type = "MinMax",
                .parameters = {{"function", *function}},
                .inputs = *inputs,
                .outputs = {{"y", context.output(1)}}},
               "MinMax " + *function);
}

void compare_to_constant(ImportContext& context) {
  const auto relop = context.raw("relop");
  const auto constant_value = context.parameter("const");
  if (!relop || !constant_value || !boolean_output(context)) return;
  const std::string operation = *relop == "~=" ? "!=" : *relop;
  unary(context, "Compare", {{"operator", quoted(operation)}, {"value", *constant_value}}, false,
        "Compare " + operation + " " + *constant_value);
}

// Whether every data type the PID's dialog sets (PParamDataTypeStr, SumOutDataTypeStr, ...) is inherited: duet's
// DiscretePid computes in its input's type throughout, Simulink's in the types set there.
bool pid_types_inherited(ImportContext& context) {
  for (const auto* values : {&context.block().mask_parameters, &context.block().parameters}) {
    for (const auto& [name, text] : *values) {
      if (!name.ends_with("DataTypeStr") || trimmed(text).starts_with("Inherit:")) continue;
      context.refuse(name + " '" + text + "': duet's DiscretePid computes in its input's type throughout");
      return false;
    }
  }
  return true;
}

// The Discrete PID Controller (a library link, SourceType "PID 1dof"), for the options duet's DiscretePid has.
// Whether the parameter evaluates to 0 (`0`, `0.0`, a variable holding 0); refuses with `what` otherwise.
bool zero(ImportContext& context, const std::string& name, const std::string& what) {
  const auto value = context.scalar(name);
  if (!value) return false;
  if (*value == 0) return true;
  context.refuse(name + " is " + yaml_number(*value) + ": " + what);
  return false;
}

void pid(ImportContext& context) {
  if (!context.require("TimeDomain", "Discrete-time", "a continuous-time PID is not discrete") ||
      !context.require("Form", "Parallel", "duet's DiscretePid is the parallel form") ||
      !context.require("ControllerParametersSource", "internal", "gains from ports: not imported yet") ||
      !context.require("ExternalReset", "none", "an external reset is not imported yet") ||
      !context.require("InitialConditionSource", "internal", "the initial conditions must be the block's own") ||
      !context.require("TrackingMode", "off", "duet's DiscretePid has no tracking mode") ||
      !absent_or(context, "UseExternalTs", "off", "a sample time from a port is not imported") ||
      !pid_types_inherited(context))
    return;
  const auto controller = context.raw("Controller");
  if (!controller) return;
  if (*controller != "P" && *controller != "I" && *controller != "PI" && *controller != "PD" && *controller != "PID") {
    context.refuse("Controller '" + *controller + "' is not one of P, I, PI, PD, PID");
    return;
  }
  const bool has_p = controller->find('P') != std::string::npos;
  const bool has_i = controller->find('I') != std::string::npos;
  const bool has_d = controller->find('D') != std::string::npos;
  TextPairs parameters;
  // An I controller has no proportional term, whatever its dialog's P holds.
  const auto p = has_p ? context.parameter("P") : std::optional<std::string>{"0"};
  if (!p) return;
  parameters.emplace_back("p", *p);
  if (has_i) {
    if (!context.require("IntegratorMethod", "Forward Euler", "duet's DiscretePid integrates by forward Euler") ||
        !absent_or(context, "UseKiTs", "off", "the integral gain given as I*Ts is not imported") ||
        !absent_or(context, "LimitIntegrator", "off", "duet's DiscretePid does not limit its integrator"))
      return;
    const auto i = context.parameter("I");
    if (!i || !zero(context, "InitialConditionForIntegrator", "duet's integrator starts at 0")) return;
    parameters.emplace_back("i", *i);
  } else {
    parameters.emplace_back("i", "0");
  }
  if (has_d) {
    const auto d = context.parameter("D");
    if (!d || !context.require("UseFilter", "on", "duet's derivative is always filtered") ||
        !context.require("FilterMethod", "Forward Euler", "duet's derivative filter is forward Euler") ||
        !zero(context, "InitialConditionForFilter", "duet's filter starts at 0") ||
        !absent_or(context, "UseExternalDerivativeSource", "off", "a derivative from a port is not imported"))
      return;
    const auto n = context.parameter("N");
    if (!n) return;
    parameters.emplace_back("d", *d);
    parameters.emplace_back("n", *n);
  } else {
    parameters.emplace_back("d", "0");
  }
  const auto limited = context.raw("LimitOutput");
  if (!limited) return;
  if (*limited == "on") {
    const auto lower = context.parameter("LowerSaturationLimit");
    const auto upper = context.parameter("UpperSaturationLimit");
    const auto anti_windup = context.raw("AntiWindupMode");
    if (!lower || !upper || !anti_windup ||
        !absent_or(context, "SatLimitsSource", "internal", "output limits from ports are not imported"))
      return;
    if (*anti_windup != "none" && *anti_windup != "clamping") {
      context.refuse("AntiWindupMode " + *anti_windup + ": duet's DiscretePid clamps or does nothing");
      return;
    }
    parameters.emplace_back("lower", *lower);
    parameters.emplace_back("upper", *upper);
    parameters.emplace_back("anti_windup", *anti_windup);
  }
  const auto error = context.input(1);
  const auto period = context.period();
  if (!error || !period) return;
  context.emit({.type = "DiscretePid",
                .parameters = parameters,
                .inputs = {{"error", *error}},
                .outputs = {{"y", context.output(1)}},
                .period = *period},
               "DiscretePid (" + *controller + ")");
}

void data_type_conversion(ImportContext& context) {
  const auto type = context.raw("OutDataTypeStr");
  if (!type) return;
  if (!is_duet_type(*type)) {
    context.refuse("OutDataTypeStr '" + *type +
                   "': duet's Convert needs the output type written out (double, "
                   "single, int8 ... uint32, boolean)");
    return;
  }
  if (!context.require("ConvertRealWorld", "Real World Value (RWV)", "duet converts values, not stored integers"))
    return;
  const bool to_integer = *type != "double" && *type != "single" && *type != "boolean";
  if (to_integer && (!context.require("RndMeth", "Zero", "duet's Convert rounds toward zero") ||
                     !context.require("SaturateOnIntegerOverflow", "on", "duet's Convert saturates")))
    return;
  // Its SampleTime, where the block stores one (a hidden parameter, written only when not -1); inherited otherwise.
  const bool sampled = context.block().parameters.count("SampleTime") != 0;
  unary(context, "Convert", {{"type", *type}}, sampled, "Convert to " + *type);
}

void mux(ImportContext& context) {
  const auto count = port_count(context, "Inputs", 64);
  if (!count) return;
  const auto inputs = numbered_inputs(context, *count);
  if (!inputs) return;
  context.emit({.type = "Mux", .inputs = *inputs, .outputs = {{"y", context.output(1)}}}, "Mux");
}

void demux(ImportContext& context) {
  const auto count = port_count(context, "Outputs", 8);  // duet's Demux: one to eight outputs, an element each
  const auto u = context.input(1);
  if (!count || !u) return;
  TextPairs outputs;
  for (std::size_t port = 1; port <= *count; ++port)
    outputs.emplace_back("y" + std::to_string(port), context.output(port));
  context.emit({.type = "Demux", .inputs = {{"u", *u}}, .outputs = outputs}, "Demux, an element per output");
}

// Simulink's single-tasking mode passes a rate transition's value on at once; duet's executive hands a slow value to
// a fast task a slow period late, as Simulink's multitasking mode does.
bool multitasking(ImportContext& context) {
  const auto& solver = context.model().source().solver.parameters;
  const auto setting = [&solver](const char* name) {
    const auto found = solver.find(name);
    return found == solver.end() ? std::string{} : found->second;
  };
  if (setting("EnableMultiTasking") == "off" || setting("SolverMode") == "SingleTasking") {
    context.refuse(
        "the model runs single-tasking, where a rate transition passes its value on at once; duet's rate "
        "transitions are those of multitasking (set the solver's tasking mode to multitasking)");
    return false;
  }
  return true;
}

void rate_transition(ImportContext& context) {
  if (!multitasking(context) ||
      !context.require("Integrity", "on", "duet's rate transitions always keep the data whole") ||
      !context.require("Deterministic", "on", "duet hands values over deterministically between periodic rates"))
    return;
  const auto option = context.raw("OutPortSampleTimeOpt");
  if (!option) return;
  std::optional<std::string> period = std::string{};
  if (*option == "Specify") {
    period = context.period("OutPortSampleTime");
  } else if (*option != "Inherit") {
    context.refuse("OutPortSampleTimeOpt '" + *option + "': give the output's period (Specify) or inherit it");
    return;
  }
  const auto initial = context.parameter("InitialCondition");
  const auto u = context.input(1);
  if (!period || !initial || !u) return;
  context.emit({.type = "RateTransition",
                .parameters = {{"initial", *initial}},
                .inputs = {{"u", *u}},
                .outputs = {{"y", context.output(1)}},
                .period = *period},
               "RateTransition");
}

void zero_order_hold(ImportContext& context) {
  if (!multitasking(context)) return;
  unary(context, "RateTransition", {}, true, "RateTransition (a zero-order hold samples at its period)");
}

// Simulink's Discrete Transfer Fcn takes its coefficients in descending powers of z, its Discrete Filter in
// ascending powers of z^-1; either becomes duet's TransferFunction (descending powers of z, both of one length).
void transfer_function_of(ImportContext& context, bool powers_of_inverse_z) {
  for (const char* source : {"NumeratorSource", "DenominatorSource"}) {
    if (!context.require(source, "Dialog", "coefficients from ports are not duet's TransferFunction's")) return;
  }
  if (!context.require("ExternalReset", "None", "duet's TransferFunction has no external reset")) return;
  const auto numerator = context.value("Numerator");
  const auto denominator = context.value("Denominator");
  const auto initial = context.scalar("InitialStates");
  const auto a0_is_one = context.raw("a0EqualsOne");
  if (!numerator || !denominator || !initial || !a0_is_one) return;
  if (*initial != 0) {
    context.refuse("InitialStates " + yaml_number(*initial) + ": duet's TransferFunction starts at rest");
    return;
  }
  if (numerator->rows != 1 || denominator->rows != 1 || numerator->count() > denominator->count()) {
    context.refuse(
        "the numerator and denominator must be row vectors, the numerator no longer (a proper transfer "
        "function)");
    return;
  }
  if (*a0_is_one == "on" && denominator->elements.front() != 1) {
    context.refuse("a0EqualsOne on with a0 = " + yaml_number(denominator->elements.front()) +
                   ": Simulink then ignores a0, duet divides by it");
    return;
  }
  // Both in descending powers of z, as long as the denominator: a transfer function's numerator padded with leading
  // zeros; a filter's coefficients multiplied by z^N, which pads each at its end.
  Value padded = *denominator;
  std::fill(padded.elements.begin(), padded.elements.end(), 0.0);
  if (powers_of_inverse_z) {
    std::copy(numerator->elements.begin(), numerator->elements.end(), padded.elements.begin());
  } else {
    std::copy(numerator->elements.begin(), numerator->elements.end(),
              padded.elements.end() - static_cast<std::ptrdiff_t>(numerator->count()));
  }
  const auto as_text = [](const Value& value) {
    std::string text = "[";
    for (std::size_t k = 0; k < value.count(); ++k) text += (k == 0 ? "" : ", ") + yaml_number(value.elements[k]);
    return text + "]";
  };
  unary(context, "TransferFunction", {{"numerator", as_text(padded)}, {"denominator", as_text(*denominator)}}, true,
        "TransferFunction " + as_text(padded) + " / " + as_text(*denominator));
}

void transfer_function(ImportContext& context) { transfer_function_of(context, false); }
void discrete_filter(ImportContext& context) { transfer_function_of(context, true); }

void state_space(ImportContext& context) {
  TextPairs parameters;
  for (const auto& [simulink, duet] : {std::pair{"A", "a"}, std::pair{"B", "b"}, std::pair{"C", "c"},
                                       std::pair{"D", "d"}, std::pair{"InitialCondition", "initial"}}) {
    const auto text = context.parameter(simulink);
    if (!text) return;
    parameters.emplace_back(duet, *text);
  }
  unary(context, "StateSpace", parameters, true, "StateSpace");
}

// A delay of N steps as N UnitDelays in a row, each from the initial condition.
void delay(ImportContext& context) {
  if (!context.require("DelayLengthSource", "Dialog", "a delay length from a port is not imported") ||
      !context.require("InitialConditionSource", "Dialog", "an initial condition from a port is not imported") ||
      !context.require("ExternalReset", "None", "a delay with an external reset is not imported") ||
      !context.require("ShowEnablePort", "off", "a delay with an enable port is not imported"))
    return;
  const auto length = context.scalar("DelayLength");
  const auto initial = context.parameter("InitialCondition");
  const auto initial_value = context.value("InitialCondition");
  const auto u = context.input(1);
  const auto period = context.period();
  if (!length || !initial || !initial_value || !u || !period) return;
  if (*length < 1 || *length > 64 || *length != std::floor(*length)) {
    context.refuse("DelayLength " + yaml_number(*length) + ": duet imports delays of 1 to 64 steps");
    return;
  }
  if (!initial_value->is_scalar()) {
    context.refuse("InitialCondition is " + initial_value->size_text() + ": one value for every step is imported");
    return;
  }
  const auto steps = static_cast<std::size_t>(*length);
  std::string signal = *u;
  for (std::size_t step = 1; step <= steps; ++step) {
    // The last delay is the block's own name, as the signal it drives: late_1 -> late_2 -> late.
    const bool last = step == steps;
    const std::string stem = context.block_name + "_" + std::to_string(step);
    const std::string next = last ? context.output(1) : context.new_signal_name(stem);
    context.emit({.name = last ? context.block_name : context.new_block_name(stem),
                  .type = "UnitDelay",
                  .parameters = {{"initial", *initial}},
                  .inputs = {{"u", signal}},
                  .outputs = {{"y", next}},
                  .period = *period},
                 step == 1 ? std::to_string(steps) + " UnitDelays in a row" : "");
    signal = next;
  }
}

void relational(ImportContext& context) {
  const auto operation = context.raw("Operator");
  if (!operation || !boolean_output(context)) return;
  static const std::map<std::string, std::string, std::less<>> operators{{"==", "=="}, {"~=", "!="}, {"<", "<"},
                                                                         {"<=", "<="}, {">", ">"},   {">=", ">="}};
  const auto found = operators.find(*operation);
  if (found == operators.end()) {
    context.refuse("Operator " + *operation + ": duet's Relational compares two inputs (==, ~=, <, <=, >, >=)");
    return;
  }
  const auto inputs = numbered_inputs(context, 2);
  if (!inputs) return;
  context.emit({.type = "Relational",
                .parameters = {{"operator", quoted(found->second)}},
                .inputs = *inputs,
                .outputs = {{"y", context.output(1)}}},
               "Relational " + found->second);
}

void dead_zone(ImportContext& context) {
  const auto start = context.parameter("LowerValue");
  const auto end = context.parameter("UpperValue");
  if (!start || !end) return;
  unary(context, "DeadZone", {{"start", *start}, {"end", *end}}, false, "DeadZone [" + *start + ", " + *end + "]");
}

// The n-D Lookup Table with one dimension and explicit breakpoints.
void lookup(ImportContext& context) {
  if (!context.require("NumberOfTableDimensions", "1", "duet's Interpolation has one dimension") ||
      !context.require("DataSpecification", "Table and breakpoints",
                       "the table and breakpoints must be the block's own, not a lookup table object's") ||
      !context.require("BreakpointsSpecification", "Explicit values", "give the breakpoints explicitly") ||
      !context.require("UseLastTableValue", "off", "duet's Interpolation does not use the last value that way"))
    return;
  // Newer releases can take the table or the breakpoints from input ports; older files do not have the option.
  for (const char* source : {"TableSource", "BreakpointsForDimension1Source"}) {
    if (!absent_or(context, source, "Dialog", "a table or breakpoints from input ports are not duet's Interpolation's"))
      return;
  }
  static const std::map<std::string, std::string, std::less<>> methods{{"Linear point-slope", "linear"},
                                                                       {"Linear", "linear"},
                                                                       {"Nearest", "nearest"},
                                                                       {"Flat", "flat"},
                                                                       {"Above", "above"}};
  const auto method_text = context.raw("InterpMethod");
  const auto extrapolation_text = context.raw("ExtrapMethod");
  if (!method_text || !extrapolation_text) return;
  const auto method = methods.find(*method_text);
  if (method == methods.end()) {
    context.refuse("InterpMethod '" + *method_text + "': duet interpolates linearly, to the nearest, flat or above");
    return;
  }
  if (*extrapolation_text != "Clip" && !(*extrapolation_text == "Linear" && method->second == "linear")) {
    context.refuse("ExtrapMethod '" + *extrapolation_text +
                   "': duet clips, or continues the end segments of a linear interpolation");
    return;
  }
  const auto breakpoints = context.parameter("BreakpointsForDimension1");
  const auto table = context.parameter("Table");
  if (!breakpoints || !table) return;
  unary(context, "Interpolation",
        {{"breakpoints", *breakpoints},
         {"table", *table},
         {"method", method->second},
         {"extrapolation", *extrapolation_text == "Clip" ? "clip" : "linear"}},
        true, "Interpolation (" + method->second + ")");
}

void trigonometry(ImportContext& context) {
  const auto operation = context.raw("Operator");
  if (!operation || !context.require("ApproximationMethod", "None", "duet computes without approximation methods"))
    return;
  if (*operation != "atan2") {
    context.refuse("Operator " + *operation + ": of the trigonometric functions duet has atan2");
    return;
  }
  const auto y = context.input(1);
  const auto x = context.input(2);
  if (!y || !x) return;
  context.emit({.type = "Atan2", .inputs = {{"y_in", *y}, {"x_in", *x}}, .outputs = {{"y", context.output(1)}}},
               "Atan2");
}

// The functions of the Math block that are duet's arithmetic: the square, and the reciprocal.
void math(ImportContext& context) {
  const auto operation = context.raw("Operator");
  const auto u = context.input(1);
  if (!operation || !u) return;
  if (*operation == "square") {
    context.emit({.type = "Product",
                  .parameters = {{"signs", quoted("**")}},
                  .inputs = {{"u1", *u}, {"u2", *u}},
                  .outputs = {{"y", context.output(1)}}},
                 "Product u u");
  } else if (*operation == "reciprocal") {
    // Newton-Raphson approximates 1/u in a number of iterations; duet divides.
    if (!absent_or(context, "AlgorithmType", "Exact", "duet's reciprocal is the exact division 1/u")) return;
    const std::string one = context.new_signal_name(context.block_name + "_one");
    context.emit({.name = context.new_block_name(context.block_name + "_one"),
                  .type = "Constant",
                  .parameters = {{"value", "1"}},
                  .outputs = {{"y", one}}},
                 "Constant 1");
    context.emit({.type = "Product",
                  .parameters = {{"signs", quoted("*/")}},
                  .inputs = {{"u1", one}, {"u2", *u}},
                  .outputs = {{"y", context.output(1)}}},
                 "Product 1 / u");
  } else {
    context.refuse("Operator " + *operation + ": of the Math block's functions duet has square and reciprocal");
  }
}

// The Discrete Derivative (a library link): K (u(k) - u(k-1)) / Ts, from a previous input of 0.
void discrete_derivative(ImportContext& context) {
  const auto initial = context.scalar("ICPrevScaledInput");
  const auto gain_value = context.parameter("gainval");
  if (!initial || !gain_value) return;
  if (*initial != 0) {
    context.refuse("ICPrevScaledInput " + yaml_number(*initial) + ": duet's DiscreteDerivative starts from 0");
    return;
  }
  // Its sample time, where the link's values name one; inherited otherwise.
  const bool sampled = context.block().mask_parameters.count("SampleTime") != 0;
  unary(context, "DiscreteDerivative", {{"gain", *gain_value}}, sampled, "DiscreteDerivative K " + *gain_value);
}

// A Selector with its indices in the dialog: each index a Constant and duet's Selector (which counts from 0), a Mux
// of them where there are several.
void selector(ImportContext& context) {
  if (!context.require("NumberOfDimensions", "1", "duet selects from vectors") ||
      !context.require("IndexOptions", "Index vector (dialog)", "the indices must be in the dialog"))
    return;
  const auto mode = context.raw("IndexMode");
  const auto indices = context.value("Indices");
  const auto u = context.input(1);
  if (!mode || !indices || !u) return;
  if (*mode != "One-based" && *mode != "Zero-based") {
    context.refuse("IndexMode '" + *mode + "' is neither One-based nor Zero-based");
    return;
  }
  if (indices->count() < 1 || indices->count() > 8) {
    context.refuse("Indices '" + *context.raw("Indices") + "': duet selects one to eight elements");
    return;
  }
  const double first = *mode == "One-based" ? 1 : 0;
  std::vector<std::string> picked;
  for (std::size_t k = 0; k < indices->count(); ++k) {
    const bool alone = indices->count() == 1;
    const std::string stem = context.block_name + (alone ? std::string{} : "_" + std::to_string(k + 1));
    const std::string index = context.new_signal_name(stem + "_index");
    context.emit({.name = context.new_block_name(stem + "_index"),
                  .type = "Constant",
                  .parameters = {{"value", yaml_number(indices->elements[k] - first)}},
                  .outputs = {{"y", index}}},
                 "");
    const std::string out = alone ? context.output(1) : context.new_signal_name(stem);
    context.emit({.name = alone ? context.block_name : context.new_block_name(stem),
                  .type = "Selector",
                  .inputs = {{"u", *u}, {"index", index}},
                  .outputs = {{"y", out}}},
                 "");
    picked.push_back(out);
  }
  if (picked.size() > 1) {
    TextPairs inputs;
    for (std::size_t k = 0; k < picked.size(); ++k) inputs.emplace_back("u" + std::to_string(k + 1), picked[k]);
    context.emit({.type = "Mux", .inputs = inputs, .outputs = {{"y", context.output(1)}}}, "");
  }
  context.emit_note("Selector of " + std::to_string(picked.size()) + " element(s), counted from 0");
}

}  // namespace

BlockMapping mapping_for(const std::string& type) {
  static const std::map<std::string, BlockMapping, std::less<>> mappings{
      {"Constant", constant},
      {"Gain", on_integer_overflow<gain, false>},
      {"Sum", on_integer_overflow<sum, false>},
      {"Product", on_integer_overflow<product, false>},
      {"Abs", on_integer_overflow<abs, true>},
      {"Signum", sign},
      {"Saturate", saturation},
      {"UnitDelay", unit_delay},
      {"DiscreteIntegrator", discrete_integrator},
      {"Ground", ground},
      {"Terminator", terminator},
      {"Switch", switch_block},
      {"Logic", logic},
      {"MinMax", min_max},
      {"Compare To Constant", compare_to_constant},
      {"PID 1dof", pid},
      {"DataTypeConversion", data_type_conversion},
      {"Mux", mux},
      {"Demux", demux},
      {"RateTransition", rate_transition},
      {"ZeroOrderHold", zero_order_hold},
      {"DiscreteTransferFcn", transfer_function},
      {"DiscreteStateSpace", state_space},
      {"Delay", delay},
      {"RelationalOperator", relational},
      {"DeadZone", dead_zone},
      {"Lookup_n-D", lookup},
      {"Trigonometry", trigonometry},
      {"Math", math},
      {"Discrete Derivative", discrete_derivative},
      {"DiscreteFilter", discrete_filter},
      {"Selector", selector},
  };
  const auto found = mappings.find(type);
  return found == mappings.end() ? nullptr : found->second;
}

}  // namespace duet::simulink_import
