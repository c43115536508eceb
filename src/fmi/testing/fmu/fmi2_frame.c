/* The FMI 2.0 co-simulation functions of the test FMUs, over a model of model.h: all 34 exported, those the test
 * models have no use for returning fmi2Error. MODEL_TOKEN (the guid) comes from the build. */
#include <stdlib.h>
#include <string.h>

#include "duet/fmi/fmi2_api.h"
#include "model.h"

#define EXPORT __attribute__((visibility("default")))

EXPORT fmi2GetTypesPlatformTYPE fmi2GetTypesPlatform;
EXPORT fmi2GetVersionTYPE fmi2GetVersion;
EXPORT fmi2SetDebugLoggingTYPE fmi2SetDebugLogging;
EXPORT fmi2InstantiateTYPE fmi2Instantiate;
EXPORT fmi2FreeInstanceTYPE fmi2FreeInstance;
EXPORT fmi2SetupExperimentTYPE fmi2SetupExperiment;
EXPORT fmi2EnterInitializationModeTYPE fmi2EnterInitializationMode;
EXPORT fmi2ExitInitializationModeTYPE fmi2ExitInitializationMode;
EXPORT fmi2TerminateTYPE fmi2Terminate;
EXPORT fmi2ResetTYPE fmi2Reset;
EXPORT fmi2GetRealTYPE fmi2GetReal;
EXPORT fmi2GetIntegerTYPE fmi2GetInteger;
EXPORT fmi2GetBooleanTYPE fmi2GetBoolean;
EXPORT fmi2GetStringTYPE fmi2GetString;
EXPORT fmi2SetRealTYPE fmi2SetReal;
EXPORT fmi2SetIntegerTYPE fmi2SetInteger;
EXPORT fmi2SetBooleanTYPE fmi2SetBoolean;
EXPORT fmi2SetStringTYPE fmi2SetString;
EXPORT fmi2GetFMUstateTYPE fmi2GetFMUstate;
EXPORT fmi2SetFMUstateTYPE fmi2SetFMUstate;
EXPORT fmi2FreeFMUstateTYPE fmi2FreeFMUstate;
EXPORT fmi2SerializedFMUstateSizeTYPE fmi2SerializedFMUstateSize;
EXPORT fmi2SerializeFMUstateTYPE fmi2SerializeFMUstate;
EXPORT fmi2DeSerializeFMUstateTYPE fmi2DeSerializeFMUstate;
EXPORT fmi2GetDirectionalDerivativeTYPE fmi2GetDirectionalDerivative;
EXPORT fmi2SetRealInputDerivativesTYPE fmi2SetRealInputDerivatives;
EXPORT fmi2GetRealOutputDerivativesTYPE fmi2GetRealOutputDerivatives;
EXPORT fmi2DoStepTYPE fmi2DoStep;
EXPORT fmi2CancelStepTYPE fmi2CancelStep;
EXPORT fmi2GetStatusTYPE fmi2GetStatus;
EXPORT fmi2GetRealStatusTYPE fmi2GetRealStatus;
EXPORT fmi2GetIntegerStatusTYPE fmi2GetIntegerStatus;
EXPORT fmi2GetBooleanStatusTYPE fmi2GetBooleanStatus;
EXPORT fmi2GetStringStatusTYPE fmi2GetStringStatus;

typedef enum { INSTANTIATED, INITIALIZATION, STEP_COMPLETE, STEP_FAILED, TERMINATED } State;

typedef struct {
  State state;
  double values[MODEL_MAX_VALUES];
  double start_time;
  int terminate_requested;
  fmi2CallbackFunctions callbacks; /* a copy: the importer's may not outlive fmi2Instantiate */
  char name[64];
} Instance;

static fmi2Status refuse(fmi2Component c, const char* why) {
  Instance* instance = (Instance*)c;
  if (instance != NULL && instance->callbacks.logger != NULL)
    instance->callbacks.logger(instance->callbacks.componentEnvironment, instance->name, fmi2Error, "logStatusError",
                               "%s", why);
  return fmi2Error;
}

static int known(const fmi2ValueReference vr[], size_t nvr) {
  for (size_t i = 0; i < nvr; ++i)
    if (vr[i] >= model_value_count) return 0;
  return 1;
}

const char* fmi2GetTypesPlatform(void) { return "default"; }
const char* fmi2GetVersion(void) { return "2.0"; }
fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String categories[]) {
  return c != NULL ? fmi2OK : fmi2Error;
}

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid, fmi2String resources,
                              const fmi2CallbackFunctions* functions, fmi2Boolean visible, fmi2Boolean logging) {
  if (functions == NULL || functions->logger == NULL || type != fmi2CoSimulation || name == NULL) return NULL;
  if (guid == NULL || strcmp(guid, MODEL_TOKEN) != 0) {
    functions->logger(functions->componentEnvironment, name, fmi2Error, "logStatusError", "Wrong guid %s", guid);
    return NULL;
  }
  Instance* instance = calloc(1, sizeof(Instance));
  if (instance == NULL) return NULL;
  instance->callbacks = *functions;
  strncpy(instance->name, name, sizeof instance->name - 1);
  model_start(instance->values);
  return instance;
}

void fmi2FreeInstance(fmi2Component c) { free(c); }

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean tolerance_defined, fmi2Real tolerance, fmi2Real start_time,
                               fmi2Boolean stop_defined, fmi2Real stop_time) {
  Instance* instance = (Instance*)c;
  if (instance == NULL || instance->state != INSTANTIATED) return refuse(c, "Illegal call sequence");
  instance->start_time = start_time;
  instance->values[0] = start_time;
  return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
  Instance* instance = (Instance*)c;
  if (instance == NULL || instance->state != INSTANTIATED) return refuse(c, "Illegal call sequence");
  instance->state = INITIALIZATION;
  return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
  Instance* instance = (Instance*)c;
  if (instance == NULL || instance->state != INITIALIZATION) return refuse(c, "Illegal call sequence");
  instance->state = STEP_COMPLETE;
  return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c) {
  Instance* instance = (Instance*)c;
  if (instance == NULL || (instance->state != STEP_COMPLETE && instance->state != STEP_FAILED))
    return refuse(c, "Illegal call sequence");
  instance->state = TERMINATED;
  return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c) {
  Instance* instance = (Instance*)c;
  if (instance == NULL) return fmi2Error;
  instance->state = INSTANTIATED;
  instance->terminate_requested = 0;
  instance->values[0] = 0.0;
  model_start(instance->values);
  return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
  Instance* instance = (Instance*)c;
  if (instance == NULL || !known(vr, nvr)) return refuse(c, "Unknown value reference");
  for (size_t i = 0; i < nvr; ++i) value[i] = instance->values[vr[i]];
  return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
  Instance* instance = (Instance*)c;
  if (instance == NULL || !known(vr, nvr)) return refuse(c, "Unknown value reference");
  for (size_t i = 0; i < nvr; ++i) {
    if (vr[i] == 0) return refuse(c, "time cannot be set");
    instance->values[vr[i]] = value[i];
  }
  return fmi2OK;
}

/* The test models have only Real variables. */
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
  return nvr == 0 ? fmi2OK : refuse(c, "No Integer variables");
}
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[]) {
  return nvr == 0 ? fmi2OK : refuse(c, "No Boolean variables");
}
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2String value[]) {
  return nvr == 0 ? fmi2OK : refuse(c, "No String variables");
}
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[]) {
  return nvr == 0 ? fmi2OK : refuse(c, "No Integer variables");
}
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[]) {
  return nvr == 0 ? fmi2OK : refuse(c, "No Boolean variables");
}
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2String value[]) {
  return nvr == 0 ? fmi2OK : refuse(c, "No String variables");
}

/* Not offered (modelDescription.xml says so): FMU states, derivatives, asynchronous steps. */
fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* state) { return refuse(c, "Not supported"); }
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate state) { return refuse(c, "Not supported"); }
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* state) { return refuse(c, "Not supported"); }
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate state, size_t* size) {
  return refuse(c, "Not supported");
}
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate state, fmi2Byte bytes[], size_t size) {
  return refuse(c, "Not supported");
}
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte bytes[], size_t size, fmi2FMUstate* state) {
  return refuse(c, "Not supported");
}
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference unknowns[], size_t n_unknowns,
                                        const fmi2ValueReference knowns[], size_t n_knowns, const fmi2Real seed[],
                                        fmi2Real sensitivity[]) {
  return refuse(c, "Not supported");
}
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
  return refuse(c, "Not supported");
}
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[]) {
  return refuse(c, "Not supported");
}
fmi2Status fmi2CancelStep(fmi2Component c) { return refuse(c, "Not supported"); }

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real point, fmi2Real step, fmi2Boolean no_rollback) {
  Instance* instance = (Instance*)c;
  if (instance == NULL || instance->state != STEP_COMPLETE) return refuse(c, "Illegal call sequence");
  if (step <= 0.0) return refuse(c, "The step size must be positive");
  const double tolerance = 1e-9 * (1.0 + (point < 0 ? -point : point));
  if (point - instance->values[0] > tolerance || instance->values[0] - point > tolerance)
    return refuse(c, "The communication point is not where the last step ended");
  switch (model_step(instance->values, step)) {
    case MODEL_STEPPED: instance->values[0] = point + step; return fmi2OK;
    case MODEL_TERMINATED:
      /* 2.0 asks to stop with Discard; fmi2GetBooleanStatus(fmi2Terminated) then says why. */
      instance->values[0] = point + step;
      instance->terminate_requested = 1;
      instance->state = STEP_FAILED;
      return fmi2Discard;
    case MODEL_FAILED: instance->state = STEP_FAILED; return refuse(c, "The model failed in this step");
  }
  return fmi2Error;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status* value) {
  return refuse(c, "Not supported");
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real* value) {
  Instance* instance = (Instance*)c;
  if (instance == NULL || s != fmi2LastSuccessfulTime) return refuse(c, "Not supported");
  *value = instance->values[0];
  return fmi2OK;
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer* value) {
  return refuse(c, "Not supported");
}
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean* value) {
  Instance* instance = (Instance*)c;
  if (instance == NULL || s != fmi2Terminated) return refuse(c, "Not supported");
  *value = instance->terminate_requested ? fmi2True : fmi2False;
  return fmi2OK;
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String* value) {
  return refuse(c, "Not supported");
}
