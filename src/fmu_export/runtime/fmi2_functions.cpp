// The FMI 2.0 functions of an exported co-simulation FMU (docs/FMI.md, "Export"): the 34 of the common and the
// co-simulation interfaces, with default visibility; the ones this FMU does not offer log and return Error.

#include <cstring>
#include <new>

#include "duet/fmi/fmi2_api.h"
#include "instance.hpp"

#define DUET_FMI_EXPORT __attribute__((visibility("default")))

namespace {

using duet::fmu::Instance;
using duet::fmu::Status;
using duet::fmu::ValueType;

void log_to_importer(const duet::fmu::Logger& logger, const char* instance, Status status, const char* category,
                     const char* message) {
  // 2.0's logger formats like printf: the message goes in as an argument, never as the format.
  reinterpret_cast<fmi2CallbackLogger>(logger.callback)(logger.environment, instance, static_cast<fmi2Status>(status),
                                                        category, "%s", message);
}

const duet::fmu::Rules rules{.get_when_instantiated = false,
                             .phase_names = {"instantiated", "initializationMode", "stepComplete", "terminated"}};

Instance* as_instance(fmi2Component component) { return static_cast<Instance*>(component); }

fmi2Status status(Status value) { return static_cast<fmi2Status>(value); }

fmi2Status unsupported(fmi2Component component, const char* function) {
  if (component == nullptr) return fmi2Error;
  return status(as_instance(component)->refuse(function, "not offered by this FMU"));
}

// 2.0's three types hold every type of a model: Real the floats and uint32 (exactly, in a double), Integer the
// smaller integers.
constexpr duet::fmu::TypeSet real_types = duet::fmu::types({ValueType::float64, ValueType::float32, ValueType::uint32});
constexpr duet::fmu::TypeSet integer_types =
    duet::fmu::types({ValueType::int8, ValueType::int16, ValueType::int32, ValueType::uint8, ValueType::uint16});
constexpr duet::fmu::TypeSet boolean_types = duet::fmu::types({ValueType::boolean});

template <typename T>
fmi2Status get(fmi2Component component, const char* function, const fmi2ValueReference references[], size_t count,
               T values[], duet::fmu::TypeSet accepted) {
  if (component == nullptr) return fmi2Error;
  return status(as_instance(component)->get(function, {references, count}, values, accepted));
}

template <typename T>
fmi2Status set(fmi2Component component, const char* function, const fmi2ValueReference references[], size_t count,
               const T values[], duet::fmu::TypeSet accepted) {
  if (component == nullptr) return fmi2Error;
  return status(as_instance(component)->set(function, {references, count}, values, accepted));
}

}  // namespace

extern "C" {

DUET_FMI_EXPORT fmi2GetTypesPlatformTYPE fmi2GetTypesPlatform;
DUET_FMI_EXPORT fmi2GetVersionTYPE fmi2GetVersion;
DUET_FMI_EXPORT fmi2SetDebugLoggingTYPE fmi2SetDebugLogging;
DUET_FMI_EXPORT fmi2InstantiateTYPE fmi2Instantiate;
DUET_FMI_EXPORT fmi2FreeInstanceTYPE fmi2FreeInstance;
DUET_FMI_EXPORT fmi2SetupExperimentTYPE fmi2SetupExperiment;
DUET_FMI_EXPORT fmi2EnterInitializationModeTYPE fmi2EnterInitializationMode;
DUET_FMI_EXPORT fmi2ExitInitializationModeTYPE fmi2ExitInitializationMode;
DUET_FMI_EXPORT fmi2TerminateTYPE fmi2Terminate;
DUET_FMI_EXPORT fmi2ResetTYPE fmi2Reset;
DUET_FMI_EXPORT fmi2GetRealTYPE fmi2GetReal;
DUET_FMI_EXPORT fmi2GetIntegerTYPE fmi2GetInteger;
DUET_FMI_EXPORT fmi2GetBooleanTYPE fmi2GetBoolean;
DUET_FMI_EXPORT fmi2GetStringTYPE fmi2GetString;
DUET_FMI_EXPORT fmi2SetRealTYPE fmi2SetReal;
DUET_FMI_EXPORT fmi2SetIntegerTYPE fmi2SetInteger;
DUET_FMI_EXPORT fmi2SetBooleanTYPE fmi2SetBoolean;
DUET_FMI_EXPORT fmi2SetStringTYPE fmi2SetString;
DUET_FMI_EXPORT fmi2GetFMUstateTYPE fmi2GetFMUstate;
DUET_FMI_EXPORT fmi2SetFMUstateTYPE fmi2SetFMUstate;
DUET_FMI_EXPORT fmi2FreeFMUstateTYPE fmi2FreeFMUstate;
DUET_FMI_EXPORT fmi2SerializedFMUstateSizeTYPE fmi2SerializedFMUstateSize;
DUET_FMI_EXPORT fmi2SerializeFMUstateTYPE fmi2SerializeFMUstate;
DUET_FMI_EXPORT fmi2DeSerializeFMUstateTYPE fmi2DeSerializeFMUstate;
DUET_FMI_EXPORT fmi2GetDirectionalDerivativeTYPE fmi2GetDirectionalDerivative;
DUET_FMI_EXPORT fmi2SetRealInputDerivativesTYPE fmi2SetRealInputDerivatives;
DUET_FMI_EXPORT fmi2GetRealOutputDerivativesTYPE fmi2GetRealOutputDerivatives;
DUET_FMI_EXPORT fmi2DoStepTYPE fmi2DoStep;
DUET_FMI_EXPORT fmi2CancelStepTYPE fmi2CancelStep;
DUET_FMI_EXPORT fmi2GetStatusTYPE fmi2GetStatus;
DUET_FMI_EXPORT fmi2GetRealStatusTYPE fmi2GetRealStatus;
DUET_FMI_EXPORT fmi2GetIntegerStatusTYPE fmi2GetIntegerStatus;
DUET_FMI_EXPORT fmi2GetBooleanStatusTYPE fmi2GetBooleanStatus;
DUET_FMI_EXPORT fmi2GetStringStatusTYPE fmi2GetStringStatus;

const char* fmi2GetTypesPlatform(void) { return "default"; }
const char* fmi2GetVersion(void) { return "2.0"; }

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t, const fmi2String[]) {
  if (c == nullptr) return fmi2Error;
  as_instance(c)->set_logging(loggingOn != fmi2False);
  return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID, fmi2String,
                              const fmi2CallbackFunctions* functions, fmi2Boolean, fmi2Boolean loggingOn) {
  const fmi2CallbackLogger logger = functions == nullptr ? nullptr : functions->logger;
  void* const environment = functions == nullptr ? nullptr : functions->componentEnvironment;
  const auto refuse = [&](const char* reason) -> fmi2Component {
    if (loggingOn != fmi2False && logger != nullptr) {
      logger(environment, instanceName, fmi2Error, "logStatusError", "%s", reason);
    }
    return nullptr;
  };
  if (instanceName == nullptr) return refuse("fmi2Instantiate: no instanceName");
  if (fmuType != fmi2CoSimulation) return refuse("fmi2Instantiate: this FMU offers co-simulation only");
  if (fmuGUID == nullptr || std::strcmp(fmuGUID, duet::fmu::model.token) != 0) {
    return refuse("fmi2Instantiate: the GUID is not this FMU's");
  }
  const duet::fmu::Logger to_importer{.log = logger == nullptr ? nullptr : log_to_importer,
                                      .callback = reinterpret_cast<void*>(logger),
                                      .environment = environment};
  return new (std::nothrow) Instance{instanceName, to_importer, loggingOn != fmi2False, rules};
}

void fmi2FreeInstance(fmi2Component c) { delete as_instance(c); }

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean, fmi2Real, fmi2Real startTime, fmi2Boolean, fmi2Real) {
  if (c == nullptr) return fmi2Error;
  return status(as_instance(c)->set_start_time("fmi2SetupExperiment", startTime));
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
  if (c == nullptr) return fmi2Error;
  return status(as_instance(c)->enter_initialization("fmi2EnterInitializationMode"));
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
  if (c == nullptr) return fmi2Error;
  return status(as_instance(c)->exit_initialization("fmi2ExitInitializationMode"));
}

fmi2Status fmi2Terminate(fmi2Component c) {
  if (c == nullptr) return fmi2Error;
  return status(as_instance(c)->terminate("fmi2Terminate"));
}

fmi2Status fmi2Reset(fmi2Component c) {
  if (c == nullptr) return fmi2Error;
  as_instance(c)->reset();
  return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
  return get(c, "fmi2GetReal", vr, nvr, value, real_types);
}
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
  return get(c, "fmi2GetInteger", vr, nvr, value, integer_types);
}
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[]) {
  return get(c, "fmi2GetBoolean", vr, nvr, value, boolean_types);
}
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference[], size_t, fmi2String[]) {
  return unsupported(c, "fmi2GetString");
}
fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
  return set(c, "fmi2SetReal", vr, nvr, value, real_types);
}
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[]) {
  return set(c, "fmi2SetInteger", vr, nvr, value, integer_types);
}
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[]) {
  return set(c, "fmi2SetBoolean", vr, nvr, value, boolean_types);
}
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference[], size_t, const fmi2String[]) {
  return unsupported(c, "fmi2SetString");
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate*) { return unsupported(c, "fmi2GetFMUstate"); }
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate) { return unsupported(c, "fmi2SetFMUstate"); }
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate*) { return unsupported(c, "fmi2FreeFMUstate"); }
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate, size_t*) {
  return unsupported(c, "fmi2SerializedFMUstateSize");
}
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate, fmi2Byte[], size_t) {
  return unsupported(c, "fmi2SerializeFMUstate");
}
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte[], size_t, fmi2FMUstate*) {
  return unsupported(c, "fmi2DeSerializeFMUstate");
}
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference[], size_t, const fmi2ValueReference[],
                                        size_t, const fmi2Real[], fmi2Real[]) {
  return unsupported(c, "fmi2GetDirectionalDerivative");
}
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t, const fmi2Integer[],
                                       const fmi2Real[]) {
  return unsupported(c, "fmi2SetRealInputDerivatives");
}
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t, const fmi2Integer[],
                                        fmi2Real[]) {
  return unsupported(c, "fmi2GetRealOutputDerivatives");
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                      fmi2Boolean) {
  if (c == nullptr) return fmi2Error;
  return status(as_instance(c)->do_step("fmi2DoStep", currentCommunicationPoint, communicationStepSize));
}

// Steps finish before fmi2DoStep returns: there is never one to cancel or to ask about.
fmi2Status fmi2CancelStep(fmi2Component c) { return unsupported(c, "fmi2CancelStep"); }
fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind, fmi2Status*) { return unsupported(c, "fmi2GetStatus"); }
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Real* value) {
  if (c == nullptr || value == nullptr) return fmi2Error;
  if (kind != fmi2LastSuccessfulTime) return unsupported(c, "fmi2GetRealStatus");
  *value = as_instance(c)->time();
  return fmi2OK;
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind, fmi2Integer*) {
  return unsupported(c, "fmi2GetIntegerStatus");
}
// The FMU never asks to stop.
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Boolean* value) {
  if (c == nullptr || value == nullptr) return fmi2Error;
  if (kind != fmi2Terminated) return unsupported(c, "fmi2GetBooleanStatus");
  *value = fmi2False;
  return fmi2OK;
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind, fmi2String*) {
  return unsupported(c, "fmi2GetStringStatus");
}

}  // extern "C"
