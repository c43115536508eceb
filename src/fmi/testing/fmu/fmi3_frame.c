/* The FMI 3.0 functions of the test FMUs, over a model of model.h: all 75 exported as 3.0 requires; those outside
 * co-simulation of Float64 values return fmi3Error. MODEL_TOKEN (the instantiationToken) comes from the build. */
#include <stdlib.h>
#include <string.h>

#include "duet/fmi/fmi3_api.h"
#include "model.h"

#define EXPORT __attribute__((visibility("default")))

EXPORT fmi3GetVersionTYPE fmi3GetVersion;
EXPORT fmi3SetDebugLoggingTYPE fmi3SetDebugLogging;
EXPORT fmi3InstantiateModelExchangeTYPE fmi3InstantiateModelExchange;
EXPORT fmi3InstantiateCoSimulationTYPE fmi3InstantiateCoSimulation;
EXPORT fmi3InstantiateScheduledExecutionTYPE fmi3InstantiateScheduledExecution;
EXPORT fmi3FreeInstanceTYPE fmi3FreeInstance;
EXPORT fmi3EnterInitializationModeTYPE fmi3EnterInitializationMode;
EXPORT fmi3ExitInitializationModeTYPE fmi3ExitInitializationMode;
EXPORT fmi3EnterEventModeTYPE fmi3EnterEventMode;
EXPORT fmi3TerminateTYPE fmi3Terminate;
EXPORT fmi3ResetTYPE fmi3Reset;
EXPORT fmi3GetFloat32TYPE fmi3GetFloat32;
EXPORT fmi3GetFloat64TYPE fmi3GetFloat64;
EXPORT fmi3GetInt8TYPE fmi3GetInt8;
EXPORT fmi3GetUInt8TYPE fmi3GetUInt8;
EXPORT fmi3GetInt16TYPE fmi3GetInt16;
EXPORT fmi3GetUInt16TYPE fmi3GetUInt16;
EXPORT fmi3GetInt32TYPE fmi3GetInt32;
EXPORT fmi3GetUInt32TYPE fmi3GetUInt32;
EXPORT fmi3GetInt64TYPE fmi3GetInt64;
EXPORT fmi3GetUInt64TYPE fmi3GetUInt64;
EXPORT fmi3GetBooleanTYPE fmi3GetBoolean;
EXPORT fmi3GetStringTYPE fmi3GetString;
EXPORT fmi3GetBinaryTYPE fmi3GetBinary;
EXPORT fmi3GetClockTYPE fmi3GetClock;
EXPORT fmi3SetFloat32TYPE fmi3SetFloat32;
EXPORT fmi3SetFloat64TYPE fmi3SetFloat64;
EXPORT fmi3SetInt8TYPE fmi3SetInt8;
EXPORT fmi3SetUInt8TYPE fmi3SetUInt8;
EXPORT fmi3SetInt16TYPE fmi3SetInt16;
EXPORT fmi3SetUInt16TYPE fmi3SetUInt16;
EXPORT fmi3SetInt32TYPE fmi3SetInt32;
EXPORT fmi3SetUInt32TYPE fmi3SetUInt32;
EXPORT fmi3SetInt64TYPE fmi3SetInt64;
EXPORT fmi3SetUInt64TYPE fmi3SetUInt64;
EXPORT fmi3SetBooleanTYPE fmi3SetBoolean;
EXPORT fmi3SetStringTYPE fmi3SetString;
EXPORT fmi3SetBinaryTYPE fmi3SetBinary;
EXPORT fmi3SetClockTYPE fmi3SetClock;
EXPORT fmi3GetNumberOfVariableDependenciesTYPE fmi3GetNumberOfVariableDependencies;
EXPORT fmi3GetVariableDependenciesTYPE fmi3GetVariableDependencies;
EXPORT fmi3GetFMUStateTYPE fmi3GetFMUState;
EXPORT fmi3SetFMUStateTYPE fmi3SetFMUState;
EXPORT fmi3FreeFMUStateTYPE fmi3FreeFMUState;
EXPORT fmi3SerializedFMUStateSizeTYPE fmi3SerializedFMUStateSize;
EXPORT fmi3SerializeFMUStateTYPE fmi3SerializeFMUState;
EXPORT fmi3DeserializeFMUStateTYPE fmi3DeserializeFMUState;
EXPORT fmi3GetDirectionalDerivativeTYPE fmi3GetDirectionalDerivative;
EXPORT fmi3GetAdjointDerivativeTYPE fmi3GetAdjointDerivative;
EXPORT fmi3EnterConfigurationModeTYPE fmi3EnterConfigurationMode;
EXPORT fmi3ExitConfigurationModeTYPE fmi3ExitConfigurationMode;
EXPORT fmi3GetIntervalDecimalTYPE fmi3GetIntervalDecimal;
EXPORT fmi3GetIntervalFractionTYPE fmi3GetIntervalFraction;
EXPORT fmi3GetShiftDecimalTYPE fmi3GetShiftDecimal;
EXPORT fmi3GetShiftFractionTYPE fmi3GetShiftFraction;
EXPORT fmi3SetIntervalDecimalTYPE fmi3SetIntervalDecimal;
EXPORT fmi3SetIntervalFractionTYPE fmi3SetIntervalFraction;
EXPORT fmi3SetShiftDecimalTYPE fmi3SetShiftDecimal;
EXPORT fmi3SetShiftFractionTYPE fmi3SetShiftFraction;
EXPORT fmi3EvaluateDiscreteStatesTYPE fmi3EvaluateDiscreteStates;
EXPORT fmi3UpdateDiscreteStatesTYPE fmi3UpdateDiscreteStates;
EXPORT fmi3EnterContinuousTimeModeTYPE fmi3EnterContinuousTimeMode;
EXPORT fmi3CompletedIntegratorStepTYPE fmi3CompletedIntegratorStep;
EXPORT fmi3SetTimeTYPE fmi3SetTime;
EXPORT fmi3SetContinuousStatesTYPE fmi3SetContinuousStates;
EXPORT fmi3GetContinuousStateDerivativesTYPE fmi3GetContinuousStateDerivatives;
EXPORT fmi3GetEventIndicatorsTYPE fmi3GetEventIndicators;
EXPORT fmi3GetContinuousStatesTYPE fmi3GetContinuousStates;
EXPORT fmi3GetNominalsOfContinuousStatesTYPE fmi3GetNominalsOfContinuousStates;
EXPORT fmi3GetNumberOfEventIndicatorsTYPE fmi3GetNumberOfEventIndicators;
EXPORT fmi3GetNumberOfContinuousStatesTYPE fmi3GetNumberOfContinuousStates;
EXPORT fmi3EnterStepModeTYPE fmi3EnterStepMode;
EXPORT fmi3GetOutputDerivativesTYPE fmi3GetOutputDerivatives;
EXPORT fmi3DoStepTYPE fmi3DoStep;
EXPORT fmi3ActivateModelPartitionTYPE fmi3ActivateModelPartition;

typedef enum { INSTANTIATED, INITIALIZATION, STEP_MODE, TERMINATED } State;

typedef struct {
  State state;
  double values[MODEL_MAX_VALUES];
  fmi3InstanceEnvironment environment;
  fmi3LogMessageCallback log;
  int logging;
} Instance;

static fmi3Status refuse(fmi3Instance handle, const char* why) {
  Instance* instance = (Instance*)handle;
  if (instance != NULL && instance->logging && instance->log != NULL)
    instance->log(instance->environment, fmi3Error, "logStatusError", why);
  return fmi3Error;
}

static int known(const fmi3ValueReference vr[], size_t nvr) {
  for (size_t i = 0; i < nvr; ++i)
    if (vr[i] >= model_value_count) return 0;
  return 1;
}

const char* fmi3GetVersion(void) { return "3.0"; }

fmi3Status fmi3SetDebugLogging(fmi3Instance handle, fmi3Boolean on, size_t n, const fmi3String categories[]) {
  Instance* instance = (Instance*)handle;
  if (instance == NULL) return fmi3Error;
  instance->logging = on;
  return fmi3OK;
}

fmi3Instance fmi3InstantiateCoSimulation(fmi3String name, fmi3String token, fmi3String resources, fmi3Boolean visible,
                                         fmi3Boolean logging, fmi3Boolean event_mode, fmi3Boolean early_return,
                                         const fmi3ValueReference required[], size_t n_required,
                                         fmi3InstanceEnvironment environment, fmi3LogMessageCallback log,
                                         fmi3IntermediateUpdateCallback update) {
  if (token == NULL || strcmp(token, MODEL_TOKEN) != 0) {
    if (logging && log != NULL) log(environment, fmi3Error, "logStatusError", "Wrong instantiationToken");
    return NULL;
  }
  if (event_mode || name == NULL) return NULL; /* no event mode: events are handled inside fmi3DoStep */
  Instance* instance = calloc(1, sizeof(Instance));
  if (instance == NULL) return NULL;
  instance->environment = environment;
  instance->log = log;
  instance->logging = logging;
  model_start(instance->values);
  return instance;
}

void fmi3FreeInstance(fmi3Instance handle) { free(handle); }

fmi3Status fmi3EnterInitializationMode(fmi3Instance handle, fmi3Boolean tolerance_defined, fmi3Float64 tolerance,
                                       fmi3Float64 start_time, fmi3Boolean stop_defined, fmi3Float64 stop_time) {
  Instance* instance = (Instance*)handle;
  if (instance == NULL || instance->state != INSTANTIATED) return refuse(handle, "Illegal call sequence");
  instance->values[0] = start_time;
  instance->state = INITIALIZATION;
  return fmi3OK;
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance handle) {
  Instance* instance = (Instance*)handle;
  if (instance == NULL || instance->state != INITIALIZATION) return refuse(handle, "Illegal call sequence");
  instance->state = STEP_MODE;
  return fmi3OK;
}

fmi3Status fmi3Terminate(fmi3Instance handle) {
  Instance* instance = (Instance*)handle;
  if (instance == NULL || instance->state != STEP_MODE) return refuse(handle, "Illegal call sequence");
  instance->state = TERMINATED;
  return fmi3OK;
}

fmi3Status fmi3Reset(fmi3Instance handle) {
  Instance* instance = (Instance*)handle;
  if (instance == NULL) return fmi3Error;
  instance->state = INSTANTIATED;
  instance->values[0] = 0.0;
  model_start(instance->values);
  return fmi3OK;
}

fmi3Status fmi3GetFloat64(fmi3Instance handle, const fmi3ValueReference vr[], size_t nvr, fmi3Float64 values[],
                          size_t n_values) {
  Instance* instance = (Instance*)handle;
  if (instance == NULL || n_values != nvr || !known(vr, nvr)) return refuse(handle, "Unknown value reference");
  for (size_t i = 0; i < nvr; ++i) values[i] = instance->values[vr[i]];
  return fmi3OK;
}

fmi3Status fmi3SetFloat64(fmi3Instance handle, const fmi3ValueReference vr[], size_t nvr, const fmi3Float64 values[],
                          size_t n_values) {
  Instance* instance = (Instance*)handle;
  if (instance == NULL || n_values != nvr || !known(vr, nvr)) return refuse(handle, "Unknown value reference");
  for (size_t i = 0; i < nvr; ++i) {
    if (vr[i] == 0) return refuse(handle, "time cannot be set");
    instance->values[vr[i]] = values[i];
  }
  return fmi3OK;
}

fmi3Status fmi3DoStep(fmi3Instance handle, fmi3Float64 point, fmi3Float64 step, fmi3Boolean no_rollback,
                      fmi3Boolean* event_handling_needed, fmi3Boolean* terminate, fmi3Boolean* early_return,
                      fmi3Float64* last_successful_time) {
  Instance* instance = (Instance*)handle;
  if (instance == NULL || instance->state != STEP_MODE) return refuse(handle, "Illegal call sequence");
  if (step <= 0.0) return refuse(handle, "The step size must be positive");
  const double tolerance = 1e-9 * (1.0 + (point < 0 ? -point : point));
  if (point - instance->values[0] > tolerance || instance->values[0] - point > tolerance)
    return refuse(handle, "The communication point is not where the last step ended");
  *event_handling_needed = false;
  *early_return = false;
  *terminate = false;
  switch (model_step(instance->values, step)) {
    case MODEL_TERMINATED:
      *terminate = true; /* the step is done all the same */
    /* fall through */
    case MODEL_STEPPED:
      instance->values[0] = point + step;
      *last_successful_time = instance->values[0];
      return fmi3OK;
    case MODEL_FAILED:
      *last_successful_time = instance->values[0];
      instance->state = TERMINATED;
      return refuse(handle, "The model failed in this step");
  }
  return fmi3Error;
}

/* Everything else: not this FMU's interface, or no variables of the type. */
fmi3Instance fmi3InstantiateModelExchange(fmi3String instanceName, fmi3String instantiationToken,
                                          fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn,
                                          fmi3InstanceEnvironment instanceEnvironment,
                                          fmi3LogMessageCallback logMessage) {
  return NULL; /* only co-simulation */
}

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String instanceName, fmi3String instantiationToken,
                                               fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn,
                                               fmi3InstanceEnvironment instanceEnvironment,
                                               fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
                                               fmi3LockPreemptionCallback lockPreemption,
                                               fmi3UnlockPreemptionCallback unlockPreemption) {
  return NULL; /* only co-simulation */
}

fmi3Status fmi3EnterEventMode(fmi3Instance instance) { return refuse(instance, "fmi3EnterEventMode is not supported"); }

fmi3Status fmi3GetFloat32(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                          fmi3Float32 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Float32 variables");
}

fmi3Status fmi3GetInt8(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                       fmi3Int8 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Int8 variables");
}

fmi3Status fmi3GetUInt8(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        fmi3UInt8 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No UInt8 variables");
}

fmi3Status fmi3GetInt16(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        fmi3Int16 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Int16 variables");
}

fmi3Status fmi3GetUInt16(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                         fmi3UInt16 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No UInt16 variables");
}

fmi3Status fmi3GetInt32(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        fmi3Int32 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Int32 variables");
}

fmi3Status fmi3GetUInt32(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                         fmi3UInt32 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No UInt32 variables");
}

fmi3Status fmi3GetInt64(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        fmi3Int64 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Int64 variables");
}

fmi3Status fmi3GetUInt64(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                         fmi3UInt64 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No UInt64 variables");
}

fmi3Status fmi3GetBoolean(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                          fmi3Boolean values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Boolean variables");
}

fmi3Status fmi3GetString(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                         fmi3String values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No String variables");
}

fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                         size_t valueSizes[], fmi3Binary values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Binary variables");
}

fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        fmi3Clock values[]) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Clock variables");
}

fmi3Status fmi3SetFloat32(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                          const fmi3Float32 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Float32 variables");
}

fmi3Status fmi3SetInt8(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                       const fmi3Int8 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Int8 variables");
}

fmi3Status fmi3SetUInt8(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        const fmi3UInt8 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No UInt8 variables");
}

fmi3Status fmi3SetInt16(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        const fmi3Int16 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Int16 variables");
}

fmi3Status fmi3SetUInt16(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                         const fmi3UInt16 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No UInt16 variables");
}

fmi3Status fmi3SetInt32(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        const fmi3Int32 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Int32 variables");
}

fmi3Status fmi3SetUInt32(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                         const fmi3UInt32 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No UInt32 variables");
}

fmi3Status fmi3SetInt64(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        const fmi3Int64 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Int64 variables");
}

fmi3Status fmi3SetUInt64(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                         const fmi3UInt64 values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No UInt64 variables");
}

fmi3Status fmi3SetBoolean(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                          const fmi3Boolean values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Boolean variables");
}

fmi3Status fmi3SetString(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                         const fmi3String values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No String variables");
}

fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                         const size_t valueSizes[], const fmi3Binary values[], size_t nValues) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Binary variables");
}

fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        const fmi3Clock values[]) {
  return nValueReferences == 0 ? fmi3OK : refuse(instance, "No Clock variables");
}

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance, fmi3ValueReference valueReference,
                                               size_t* nDependencies) {
  return refuse(instance, "fmi3GetNumberOfVariableDependencies is not supported");
}

fmi3Status fmi3GetVariableDependencies(fmi3Instance instance, fmi3ValueReference dependent,
                                       size_t elementIndicesOfDependent[], fmi3ValueReference independents[],
                                       size_t elementIndicesOfIndependents[], fmi3DependencyKind dependencyKinds[],
                                       size_t nDependencies) {
  return refuse(instance, "fmi3GetVariableDependencies is not supported");
}

fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState* FMUState) {
  return refuse(instance, "fmi3GetFMUState is not supported");
}

fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState) {
  return refuse(instance, "fmi3SetFMUState is not supported");
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState* FMUState) {
  return refuse(instance, "fmi3FreeFMUState is not supported");
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance, fmi3FMUState FMUState, size_t* size) {
  return refuse(instance, "fmi3SerializedFMUStateSize is not supported");
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState, fmi3Byte serializedState[],
                                 size_t size) {
  return refuse(instance, "fmi3SerializeFMUState is not supported");
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance instance, const fmi3Byte serializedState[], size_t size,
                                   fmi3FMUState* FMUState) {
  return refuse(instance, "fmi3DeserializeFMUState is not supported");
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
                                        const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[],
                                        size_t nSeed, fmi3Float64 sensitivity[], size_t nSensitivity) {
  return refuse(instance, "fmi3GetDirectionalDerivative is not supported");
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
                                    const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[],
                                    size_t nSeed, fmi3Float64 sensitivity[], size_t nSensitivity) {
  return refuse(instance, "fmi3GetAdjointDerivative is not supported");
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance) {
  return refuse(instance, "fmi3EnterConfigurationMode is not supported");
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance) {
  return refuse(instance, "fmi3ExitConfigurationMode is not supported");
}

fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                  size_t nValueReferences, fmi3Float64 intervals[],
                                  fmi3IntervalQualifier qualifiers[]) {
  return refuse(instance, "fmi3GetIntervalDecimal is not supported");
}

fmi3Status fmi3GetIntervalFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                   size_t nValueReferences, fmi3UInt64 counters[], fmi3UInt64 resolutions[],
                                   fmi3IntervalQualifier qualifiers[]) {
  return refuse(instance, "fmi3GetIntervalFraction is not supported");
}

fmi3Status fmi3GetShiftDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                               size_t nValueReferences, fmi3Float64 shifts[]) {
  return refuse(instance, "fmi3GetShiftDecimal is not supported");
}

fmi3Status fmi3GetShiftFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                size_t nValueReferences, fmi3UInt64 counters[], fmi3UInt64 resolutions[]) {
  return refuse(instance, "fmi3GetShiftFraction is not supported");
}

fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                  size_t nValueReferences, const fmi3Float64 intervals[]) {
  return refuse(instance, "fmi3SetIntervalDecimal is not supported");
}

fmi3Status fmi3SetIntervalFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                   size_t nValueReferences, const fmi3UInt64 counters[],
                                   const fmi3UInt64 resolutions[]) {
  return refuse(instance, "fmi3SetIntervalFraction is not supported");
}

fmi3Status fmi3SetShiftDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                               size_t nValueReferences, const fmi3Float64 shifts[]) {
  return refuse(instance, "fmi3SetShiftDecimal is not supported");
}

fmi3Status fmi3SetShiftFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                size_t nValueReferences, const fmi3UInt64 counters[], const fmi3UInt64 resolutions[]) {
  return refuse(instance, "fmi3SetShiftFraction is not supported");
}

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance) {
  return refuse(instance, "fmi3EvaluateDiscreteStates is not supported");
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance instance, fmi3Boolean* discreteStatesNeedUpdate,
                                    fmi3Boolean* terminateSimulation, fmi3Boolean* nominalsOfContinuousStatesChanged,
                                    fmi3Boolean* valuesOfContinuousStatesChanged, fmi3Boolean* nextEventTimeDefined,
                                    fmi3Float64* nextEventTime) {
  return refuse(instance, "fmi3UpdateDiscreteStates is not supported");
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance) {
  return refuse(instance, "fmi3EnterContinuousTimeMode is not supported");
}

fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi3Boolean* enterEventMode, fmi3Boolean* terminateSimulation) {
  return refuse(instance, "fmi3CompletedIntegratorStep is not supported");
}

fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time) {
  return refuse(instance, "fmi3SetTime is not supported");
}

fmi3Status fmi3SetContinuousStates(fmi3Instance instance, const fmi3Float64 continuousStates[],
                                   size_t nContinuousStates) {
  return refuse(instance, "fmi3SetContinuousStates is not supported");
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance, fmi3Float64 derivatives[],
                                             size_t nContinuousStates) {
  return refuse(instance, "fmi3GetContinuousStateDerivatives is not supported");
}

fmi3Status fmi3GetEventIndicators(fmi3Instance instance, fmi3Float64 eventIndicators[], size_t nEventIndicators) {
  return refuse(instance, "fmi3GetEventIndicators is not supported");
}

fmi3Status fmi3GetContinuousStates(fmi3Instance instance, fmi3Float64 continuousStates[], size_t nContinuousStates) {
  return refuse(instance, "fmi3GetContinuousStates is not supported");
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance, fmi3Float64 nominals[], size_t nContinuousStates) {
  return refuse(instance, "fmi3GetNominalsOfContinuousStates is not supported");
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance, size_t* nEventIndicators) {
  return refuse(instance, "fmi3GetNumberOfEventIndicators is not supported");
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance, size_t* nContinuousStates) {
  return refuse(instance, "fmi3GetNumberOfContinuousStates is not supported");
}

fmi3Status fmi3EnterStepMode(fmi3Instance instance) { return refuse(instance, "fmi3EnterStepMode is not supported"); }

fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                    size_t nValueReferences, const fmi3Int32 orders[], fmi3Float64 values[],
                                    size_t nValues) {
  return refuse(instance, "fmi3GetOutputDerivatives is not supported");
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance instance, fmi3ValueReference clockReference,
                                      fmi3Float64 activationTime) {
  return refuse(instance, "fmi3ActivateModelPartition is not supported");
}
