// The FMI 3.0 functions of an exported co-simulation FMU (docs/FMI.md, "Export"): every function fmi3_api.h
// declares, with default visibility; the ones co-simulation without event mode does not need log and return Error.

#include <cstring>
#include <new>

#include "duet/fmi/fmi3_api.h"
#include "instance.hpp"

#define DUET_FMI_EXPORT __attribute__((visibility("default")))

namespace {

using duet::fmu::Instance;
using duet::fmu::Status;
using duet::fmu::ValueType;

void log_to_importer(const duet::fmu::Logger& logger, const char*, Status status, const char* category,
                     const char* message) {
  reinterpret_cast<fmi3LogMessageCallback>(logger.callback)(logger.environment, static_cast<fmi3Status>(status),
                                                            category, message);
}

const duet::fmu::Rules rules{.get_when_instantiated = true,
                             .phase_names = {"Instantiated", "InitializationMode", "StepMode", "Terminated"}};

Instance* as_instance(fmi3Instance instance) { return static_cast<Instance*>(instance); }

fmi3Status status(Status value) { return static_cast<fmi3Status>(value); }

// What this FMU does not offer: model exchange, event mode, clocks, FMU state, derivatives.
fmi3Status unsupported(fmi3Instance instance, const char* function) {
  if (instance == nullptr) return fmi3Error;
  return status(as_instance(instance)->refuse(function, "not offered by this FMU (co-simulation without event mode)"));
}

template <typename T>
fmi3Status get(fmi3Instance instance, const char* function, const fmi3ValueReference references[], size_t count,
               T values[], size_t value_count, duet::fmu::TypeSet accepted) {
  if (instance == nullptr) return fmi3Error;
  if (value_count != count)
    return status(as_instance(instance)->refuse(function, "nValues differs from nValueReferences"));
  return status(as_instance(instance)->get(function, {references, count}, values, accepted));
}

template <typename T>
fmi3Status set(fmi3Instance instance, const char* function, const fmi3ValueReference references[], size_t count,
               const T values[], size_t value_count, duet::fmu::TypeSet accepted) {
  if (instance == nullptr) return fmi3Error;
  if (value_count != count)
    return status(as_instance(instance)->refuse(function, "nValues differs from nValueReferences"));
  return status(as_instance(instance)->set(function, {references, count}, values, accepted));
}

constexpr duet::fmu::TypeSet only(ValueType type) { return duet::fmu::types({type}); }

}  // namespace

extern "C" {

DUET_FMI_EXPORT fmi3GetVersionTYPE fmi3GetVersion;
DUET_FMI_EXPORT fmi3SetDebugLoggingTYPE fmi3SetDebugLogging;
DUET_FMI_EXPORT fmi3InstantiateModelExchangeTYPE fmi3InstantiateModelExchange;
DUET_FMI_EXPORT fmi3InstantiateCoSimulationTYPE fmi3InstantiateCoSimulation;
DUET_FMI_EXPORT fmi3InstantiateScheduledExecutionTYPE fmi3InstantiateScheduledExecution;
DUET_FMI_EXPORT fmi3FreeInstanceTYPE fmi3FreeInstance;
DUET_FMI_EXPORT fmi3EnterInitializationModeTYPE fmi3EnterInitializationMode;
DUET_FMI_EXPORT fmi3ExitInitializationModeTYPE fmi3ExitInitializationMode;
DUET_FMI_EXPORT fmi3EnterEventModeTYPE fmi3EnterEventMode;
DUET_FMI_EXPORT fmi3TerminateTYPE fmi3Terminate;
DUET_FMI_EXPORT fmi3ResetTYPE fmi3Reset;
DUET_FMI_EXPORT fmi3GetFloat32TYPE fmi3GetFloat32;
DUET_FMI_EXPORT fmi3GetFloat64TYPE fmi3GetFloat64;
DUET_FMI_EXPORT fmi3GetInt8TYPE fmi3GetInt8;
DUET_FMI_EXPORT fmi3GetUInt8TYPE fmi3GetUInt8;
DUET_FMI_EXPORT fmi3GetInt16TYPE fmi3GetInt16;
DUET_FMI_EXPORT fmi3GetUInt16TYPE fmi3GetUInt16;
DUET_FMI_EXPORT fmi3GetInt32TYPE fmi3GetInt32;
DUET_FMI_EXPORT fmi3GetUInt32TYPE fmi3GetUInt32;
DUET_FMI_EXPORT fmi3GetInt64TYPE fmi3GetInt64;
DUET_FMI_EXPORT fmi3GetUInt64TYPE fmi3GetUInt64;
DUET_FMI_EXPORT fmi3GetBooleanTYPE fmi3GetBoolean;
DUET_FMI_EXPORT fmi3GetStringTYPE fmi3GetString;
DUET_FMI_EXPORT fmi3GetBinaryTYPE fmi3GetBinary;
DUET_FMI_EXPORT fmi3GetClockTYPE fmi3GetClock;
DUET_FMI_EXPORT fmi3SetFloat32TYPE fmi3SetFloat32;
DUET_FMI_EXPORT fmi3SetFloat64TYPE fmi3SetFloat64;
DUET_FMI_EXPORT fmi3SetInt8TYPE fmi3SetInt8;
DUET_FMI_EXPORT fmi3SetUInt8TYPE fmi3SetUInt8;
DUET_FMI_EXPORT fmi3SetInt16TYPE fmi3SetInt16;
DUET_FMI_EXPORT fmi3SetUInt16TYPE fmi3SetUInt16;
DUET_FMI_EXPORT fmi3SetInt32TYPE fmi3SetInt32;
DUET_FMI_EXPORT fmi3SetUInt32TYPE fmi3SetUInt32;
DUET_FMI_EXPORT fmi3SetInt64TYPE fmi3SetInt64;
DUET_FMI_EXPORT fmi3SetUInt64TYPE fmi3SetUInt64;
DUET_FMI_EXPORT fmi3SetBooleanTYPE fmi3SetBoolean;
DUET_FMI_EXPORT fmi3SetStringTYPE fmi3SetString;
DUET_FMI_EXPORT fmi3SetBinaryTYPE fmi3SetBinary;
DUET_FMI_EXPORT fmi3SetClockTYPE fmi3SetClock;
DUET_FMI_EXPORT fmi3GetNumberOfVariableDependenciesTYPE fmi3GetNumberOfVariableDependencies;
DUET_FMI_EXPORT fmi3GetVariableDependenciesTYPE fmi3GetVariableDependencies;
DUET_FMI_EXPORT fmi3GetFMUStateTYPE fmi3GetFMUState;
DUET_FMI_EXPORT fmi3SetFMUStateTYPE fmi3SetFMUState;
DUET_FMI_EXPORT fmi3FreeFMUStateTYPE fmi3FreeFMUState;
DUET_FMI_EXPORT fmi3SerializedFMUStateSizeTYPE fmi3SerializedFMUStateSize;
DUET_FMI_EXPORT fmi3SerializeFMUStateTYPE fmi3SerializeFMUState;
DUET_FMI_EXPORT fmi3DeserializeFMUStateTYPE fmi3DeserializeFMUState;
DUET_FMI_EXPORT fmi3GetDirectionalDerivativeTYPE fmi3GetDirectionalDerivative;
DUET_FMI_EXPORT fmi3GetAdjointDerivativeTYPE fmi3GetAdjointDerivative;
DUET_FMI_EXPORT fmi3EnterConfigurationModeTYPE fmi3EnterConfigurationMode;
DUET_FMI_EXPORT fmi3ExitConfigurationModeTYPE fmi3ExitConfigurationMode;
DUET_FMI_EXPORT fmi3GetIntervalDecimalTYPE fmi3GetIntervalDecimal;
DUET_FMI_EXPORT fmi3GetIntervalFractionTYPE fmi3GetIntervalFraction;
DUET_FMI_EXPORT fmi3GetShiftDecimalTYPE fmi3GetShiftDecimal;
DUET_FMI_EXPORT fmi3GetShiftFractionTYPE fmi3GetShiftFraction;
DUET_FMI_EXPORT fmi3SetIntervalDecimalTYPE fmi3SetIntervalDecimal;
DUET_FMI_EXPORT fmi3SetIntervalFractionTYPE fmi3SetIntervalFraction;
DUET_FMI_EXPORT fmi3SetShiftDecimalTYPE fmi3SetShiftDecimal;
DUET_FMI_EXPORT fmi3SetShiftFractionTYPE fmi3SetShiftFraction;
DUET_FMI_EXPORT fmi3EvaluateDiscreteStatesTYPE fmi3EvaluateDiscreteStates;
DUET_FMI_EXPORT fmi3UpdateDiscreteStatesTYPE fmi3UpdateDiscreteStates;
DUET_FMI_EXPORT fmi3EnterContinuousTimeModeTYPE fmi3EnterContinuousTimeMode;
DUET_FMI_EXPORT fmi3CompletedIntegratorStepTYPE fmi3CompletedIntegratorStep;
DUET_FMI_EXPORT fmi3SetTimeTYPE fmi3SetTime;
DUET_FMI_EXPORT fmi3SetContinuousStatesTYPE fmi3SetContinuousStates;
DUET_FMI_EXPORT fmi3GetContinuousStateDerivativesTYPE fmi3GetContinuousStateDerivatives;
DUET_FMI_EXPORT fmi3GetEventIndicatorsTYPE fmi3GetEventIndicators;
DUET_FMI_EXPORT fmi3GetContinuousStatesTYPE fmi3GetContinuousStates;
DUET_FMI_EXPORT fmi3GetNominalsOfContinuousStatesTYPE fmi3GetNominalsOfContinuousStates;
DUET_FMI_EXPORT fmi3GetNumberOfEventIndicatorsTYPE fmi3GetNumberOfEventIndicators;
DUET_FMI_EXPORT fmi3GetNumberOfContinuousStatesTYPE fmi3GetNumberOfContinuousStates;
DUET_FMI_EXPORT fmi3EnterStepModeTYPE fmi3EnterStepMode;
DUET_FMI_EXPORT fmi3GetOutputDerivativesTYPE fmi3GetOutputDerivatives;
DUET_FMI_EXPORT fmi3DoStepTYPE fmi3DoStep;
DUET_FMI_EXPORT fmi3ActivateModelPartitionTYPE fmi3ActivateModelPartition;

const char* fmi3GetVersion(void) { return "3.0"; }

fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn, size_t, const fmi3String[]) {
  if (instance == nullptr) return fmi3Error;
  as_instance(instance)->set_logging(loggingOn);
  return fmi3OK;
}

fmi3Instance fmi3InstantiateCoSimulation(fmi3String instanceName, fmi3String instantiationToken, fmi3String,
                                         fmi3Boolean, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed, fmi3Boolean,
                                         const fmi3ValueReference[], size_t,
                                         fmi3InstanceEnvironment instanceEnvironment, fmi3LogMessageCallback logMessage,
                                         fmi3IntermediateUpdateCallback) {
  const auto refuse = [&](const char* reason) -> fmi3Instance {
    if (loggingOn && logMessage != nullptr) logMessage(instanceEnvironment, fmi3Error, "logStatusError", reason);
    return nullptr;
  };
  if (instanceName == nullptr) return refuse("fmi3InstantiateCoSimulation: no instanceName");
  if (instantiationToken == nullptr || std::strcmp(instantiationToken, duet::fmu::model.token) != 0) {
    return refuse("fmi3InstantiateCoSimulation: the instantiationToken is not this FMU's");
  }
  if (eventModeUsed) return refuse("fmi3InstantiateCoSimulation: this FMU has no event mode");
  const duet::fmu::Logger logger{.log = logMessage == nullptr ? nullptr : log_to_importer,
                                 .callback = reinterpret_cast<void*>(logMessage),
                                 .environment = instanceEnvironment};
  return new (std::nothrow) Instance{instanceName, logger, loggingOn, rules};
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String, fmi3String, fmi3String, fmi3Boolean, fmi3Boolean loggingOn,
                                          fmi3InstanceEnvironment instanceEnvironment,
                                          fmi3LogMessageCallback logMessage) {
  if (loggingOn && logMessage != nullptr) {
    logMessage(instanceEnvironment, fmi3Error, "logStatusError", "this FMU offers co-simulation only");
  }
  return nullptr;
}

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String, fmi3String, fmi3String, fmi3Boolean, fmi3Boolean loggingOn,
                                               fmi3InstanceEnvironment instanceEnvironment,
                                               fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback,
                                               fmi3LockPreemptionCallback, fmi3UnlockPreemptionCallback) {
  if (loggingOn && logMessage != nullptr) {
    logMessage(instanceEnvironment, fmi3Error, "logStatusError", "this FMU offers co-simulation only");
  }
  return nullptr;
}

void fmi3FreeInstance(fmi3Instance instance) { delete as_instance(instance); }

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean, fmi3Float64, fmi3Float64 startTime,
                                       fmi3Boolean, fmi3Float64) {
  if (instance == nullptr) return fmi3Error;
  const char* function = "fmi3EnterInitializationMode";
  const Status started = as_instance(instance)->set_start_time(function, startTime);
  if (started != Status::ok) return status(started);
  return status(as_instance(instance)->enter_initialization(function));
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {
  if (instance == nullptr) return fmi3Error;
  return status(as_instance(instance)->exit_initialization("fmi3ExitInitializationMode"));
}

fmi3Status fmi3EnterEventMode(fmi3Instance instance) { return unsupported(instance, "fmi3EnterEventMode"); }

fmi3Status fmi3Terminate(fmi3Instance instance) {
  if (instance == nullptr) return fmi3Error;
  return status(as_instance(instance)->terminate("fmi3Terminate"));
}

fmi3Status fmi3Reset(fmi3Instance instance) {
  if (instance == nullptr) return fmi3Error;
  as_instance(instance)->reset();
  return fmi3OK;
}

fmi3Status fmi3GetFloat32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Float32 values[],
                          size_t n) {
  return get(instance, "fmi3GetFloat32", vr, nvr, values, n, only(ValueType::float32));
}
fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Float64 values[],
                          size_t n) {
  return get(instance, "fmi3GetFloat64", vr, nvr, values, n, only(ValueType::float64));
}
fmi3Status fmi3GetInt8(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Int8 values[], size_t n) {
  return get(instance, "fmi3GetInt8", vr, nvr, values, n, only(ValueType::int8));
}
fmi3Status fmi3GetUInt8(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3UInt8 values[],
                        size_t n) {
  return get(instance, "fmi3GetUInt8", vr, nvr, values, n, only(ValueType::uint8));
}
fmi3Status fmi3GetInt16(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Int16 values[],
                        size_t n) {
  return get(instance, "fmi3GetInt16", vr, nvr, values, n, only(ValueType::int16));
}
fmi3Status fmi3GetUInt16(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3UInt16 values[],
                         size_t n) {
  return get(instance, "fmi3GetUInt16", vr, nvr, values, n, only(ValueType::uint16));
}
fmi3Status fmi3GetInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Int32 values[],
                        size_t n) {
  return get(instance, "fmi3GetInt32", vr, nvr, values, n, only(ValueType::int32));
}
fmi3Status fmi3GetUInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3UInt32 values[],
                         size_t n) {
  return get(instance, "fmi3GetUInt32", vr, nvr, values, n, only(ValueType::uint32));
}
// No model type is 64-bit integer: every value reference is refused, with the variable's name.
fmi3Status fmi3GetInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Int64 values[],
                        size_t n) {
  return get(instance, "fmi3GetInt64", vr, nvr, values, n, 0);
}
fmi3Status fmi3GetUInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3UInt64 values[],
                         size_t n) {
  return get(instance, "fmi3GetUInt64", vr, nvr, values, n, 0);
}
fmi3Status fmi3GetBoolean(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, fmi3Boolean values[],
                          size_t n) {
  return get(instance, "fmi3GetBoolean", vr, nvr, values, n, only(ValueType::boolean));
}
fmi3Status fmi3GetString(fmi3Instance instance, const fmi3ValueReference[], size_t, fmi3String[], size_t) {
  return unsupported(instance, "fmi3GetString");
}
fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference[], size_t, size_t[], fmi3Binary[], size_t) {
  return unsupported(instance, "fmi3GetBinary");
}
fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference[], size_t, fmi3Clock[]) {
  return unsupported(instance, "fmi3GetClock");
}

fmi3Status fmi3SetFloat32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Float32 values[],
                          size_t n) {
  return set(instance, "fmi3SetFloat32", vr, nvr, values, n, only(ValueType::float32));
}
fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Float64 values[],
                          size_t n) {
  return set(instance, "fmi3SetFloat64", vr, nvr, values, n, only(ValueType::float64));
}
fmi3Status fmi3SetInt8(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Int8 values[],
                       size_t n) {
  return set(instance, "fmi3SetInt8", vr, nvr, values, n, only(ValueType::int8));
}
fmi3Status fmi3SetUInt8(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3UInt8 values[],
                        size_t n) {
  return set(instance, "fmi3SetUInt8", vr, nvr, values, n, only(ValueType::uint8));
}
fmi3Status fmi3SetInt16(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Int16 values[],
                        size_t n) {
  return set(instance, "fmi3SetInt16", vr, nvr, values, n, only(ValueType::int16));
}
fmi3Status fmi3SetUInt16(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3UInt16 values[],
                         size_t n) {
  return set(instance, "fmi3SetUInt16", vr, nvr, values, n, only(ValueType::uint16));
}
fmi3Status fmi3SetInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Int32 values[],
                        size_t n) {
  return set(instance, "fmi3SetInt32", vr, nvr, values, n, only(ValueType::int32));
}
fmi3Status fmi3SetUInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3UInt32 values[],
                         size_t n) {
  return set(instance, "fmi3SetUInt32", vr, nvr, values, n, only(ValueType::uint32));
}
fmi3Status fmi3SetInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Int64 values[],
                        size_t n) {
  return set(instance, "fmi3SetInt64", vr, nvr, values, n, 0);
}
fmi3Status fmi3SetUInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3UInt64 values[],
                         size_t n) {
  return set(instance, "fmi3SetUInt64", vr, nvr, values, n, 0);
}
fmi3Status fmi3SetBoolean(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const fmi3Boolean values[],
                          size_t n) {
  return set(instance, "fmi3SetBoolean", vr, nvr, values, n, only(ValueType::boolean));
}
fmi3Status fmi3SetString(fmi3Instance instance, const fmi3ValueReference[], size_t, const fmi3String[], size_t) {
  return unsupported(instance, "fmi3SetString");
}
fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference[], size_t, const size_t[], const fmi3Binary[],
                         size_t) {
  return unsupported(instance, "fmi3SetBinary");
}
fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference[], size_t, const fmi3Clock[]) {
  return unsupported(instance, "fmi3SetClock");
}

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance, fmi3ValueReference, size_t*) {
  return unsupported(instance, "fmi3GetNumberOfVariableDependencies");
}
fmi3Status fmi3GetVariableDependencies(fmi3Instance instance, fmi3ValueReference, size_t[], fmi3ValueReference[],
                                       size_t[], fmi3DependencyKind[], size_t) {
  return unsupported(instance, "fmi3GetVariableDependencies");
}
fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState*) { return unsupported(instance, "fmi3GetFMUState"); }
fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState) { return unsupported(instance, "fmi3SetFMUState"); }
fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState*) { return unsupported(instance, "fmi3FreeFMUState"); }
fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance, fmi3FMUState, size_t*) {
  return unsupported(instance, "fmi3SerializedFMUStateSize");
}
fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState, fmi3Byte[], size_t) {
  return unsupported(instance, "fmi3SerializeFMUState");
}
fmi3Status fmi3DeserializeFMUState(fmi3Instance instance, const fmi3Byte[], size_t, fmi3FMUState*) {
  return unsupported(instance, "fmi3DeserializeFMUState");
}
fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance, const fmi3ValueReference[], size_t,
                                        const fmi3ValueReference[], size_t, const fmi3Float64[], size_t, fmi3Float64[],
                                        size_t) {
  return unsupported(instance, "fmi3GetDirectionalDerivative");
}
fmi3Status fmi3GetAdjointDerivative(fmi3Instance instance, const fmi3ValueReference[], size_t,
                                    const fmi3ValueReference[], size_t, const fmi3Float64[], size_t, fmi3Float64[],
                                    size_t) {
  return unsupported(instance, "fmi3GetAdjointDerivative");
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance) {
  return unsupported(instance, "fmi3EnterConfigurationMode");
}
fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance) {
  return unsupported(instance, "fmi3ExitConfigurationMode");
}
fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t, fmi3Float64[],
                                  fmi3IntervalQualifier[]) {
  return unsupported(instance, "fmi3GetIntervalDecimal");
}
fmi3Status fmi3GetIntervalFraction(fmi3Instance instance, const fmi3ValueReference[], size_t, fmi3UInt64[],
                                   fmi3UInt64[], fmi3IntervalQualifier[]) {
  return unsupported(instance, "fmi3GetIntervalFraction");
}
fmi3Status fmi3GetShiftDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t, fmi3Float64[]) {
  return unsupported(instance, "fmi3GetShiftDecimal");
}
fmi3Status fmi3GetShiftFraction(fmi3Instance instance, const fmi3ValueReference[], size_t, fmi3UInt64[], fmi3UInt64[]) {
  return unsupported(instance, "fmi3GetShiftFraction");
}
fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t, const fmi3Float64[]) {
  return unsupported(instance, "fmi3SetIntervalDecimal");
}
fmi3Status fmi3SetIntervalFraction(fmi3Instance instance, const fmi3ValueReference[], size_t, const fmi3UInt64[],
                                   const fmi3UInt64[]) {
  return unsupported(instance, "fmi3SetIntervalFraction");
}
fmi3Status fmi3SetShiftDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t, const fmi3Float64[]) {
  return unsupported(instance, "fmi3SetShiftDecimal");
}
fmi3Status fmi3SetShiftFraction(fmi3Instance instance, const fmi3ValueReference[], size_t, const fmi3UInt64[],
                                const fmi3UInt64[]) {
  return unsupported(instance, "fmi3SetShiftFraction");
}
fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance) {
  return unsupported(instance, "fmi3EvaluateDiscreteStates");
}
fmi3Status fmi3UpdateDiscreteStates(fmi3Instance instance, fmi3Boolean*, fmi3Boolean*, fmi3Boolean*, fmi3Boolean*,
                                    fmi3Boolean*, fmi3Float64*) {
  return unsupported(instance, "fmi3UpdateDiscreteStates");
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance) {
  return unsupported(instance, "fmi3EnterContinuousTimeMode");
}
fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance, fmi3Boolean, fmi3Boolean*, fmi3Boolean*) {
  return unsupported(instance, "fmi3CompletedIntegratorStep");
}
fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64) { return unsupported(instance, "fmi3SetTime"); }
fmi3Status fmi3SetContinuousStates(fmi3Instance instance, const fmi3Float64[], size_t) {
  return unsupported(instance, "fmi3SetContinuousStates");
}
fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance, fmi3Float64[], size_t) {
  return unsupported(instance, "fmi3GetContinuousStateDerivatives");
}
fmi3Status fmi3GetEventIndicators(fmi3Instance instance, fmi3Float64[], size_t) {
  return unsupported(instance, "fmi3GetEventIndicators");
}
fmi3Status fmi3GetContinuousStates(fmi3Instance instance, fmi3Float64[], size_t) {
  return unsupported(instance, "fmi3GetContinuousStates");
}
fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance, fmi3Float64[], size_t) {
  return unsupported(instance, "fmi3GetNominalsOfContinuousStates");
}
fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance, size_t*) {
  return unsupported(instance, "fmi3GetNumberOfEventIndicators");
}
fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance, size_t*) {
  return unsupported(instance, "fmi3GetNumberOfContinuousStates");
}

fmi3Status fmi3EnterStepMode(fmi3Instance instance) { return unsupported(instance, "fmi3EnterStepMode"); }
fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance, const fmi3ValueReference[], size_t, const fmi3Int32[],
                                    fmi3Float64[], size_t) {
  return unsupported(instance, "fmi3GetOutputDerivatives");
}

fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 currentCommunicationPoint, fmi3Float64 communicationStepSize,
                      fmi3Boolean, fmi3Boolean* eventHandlingNeeded, fmi3Boolean* terminateSimulation,
                      fmi3Boolean* earlyReturn, fmi3Float64* lastSuccessfulTime) {
  if (instance == nullptr) return fmi3Error;
  Instance& stepped = *as_instance(instance);
  const Status result = stepped.do_step("fmi3DoStep", currentCommunicationPoint, communicationStepSize);
  if (eventHandlingNeeded != nullptr) *eventHandlingNeeded = false;
  if (terminateSimulation != nullptr) *terminateSimulation = false;
  if (earlyReturn != nullptr) *earlyReturn = false;
  if (lastSuccessfulTime != nullptr) *lastSuccessfulTime = stepped.time();
  return status(result);
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance instance, fmi3ValueReference, fmi3Float64) {
  return unsupported(instance, "fmi3ActivateModelPartition");
}

}  // extern "C"
