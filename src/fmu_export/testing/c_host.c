/* A minimal FMI host in plain C, independent of duet's importer: it drives the thermostat and its heater, both
 * exported by `duet fmu export`, in a closed loop, and checks what docs/FMI.md ("Export") promises (fmu_export_test.cpp
 * runs it). Usage:
 *   c_host VERSION CONTROLLER.so TOKEN PLANT.so TOKEN SIM.csv STEPS VR...
 * VERSION is 2 or 3; the value references, in this order: the controller's adc input, LED output, setpoint, heating,
 * sample; the plant's LED input, adc output. SIM.csv is `duet sim thermostat.yaml --plant heater.yaml`'s recording.
 * Exit status 0 when every check holds; each failed check prints a line. */
#include <dlfcn.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "duet/fmi/fmi2_api.h"
#include "duet/fmi/fmi3_api.h"

enum { adc_in, led_out, setpoint, heating, sample, plant_led_in, plant_adc_out, reference_count };

static int failures = 0;
static int errors_logged = 0;

static void check(int holds, const char* what) {
  if (!holds) {
    printf("FAILED: %s\n", what);
    ++failures;
  }
}

/* dlsym's object pointer as a function pointer: ISO C has no cast between the two, POSIX guarantees the copy. */
typedef void (*AnyFunction)(void);
static AnyFunction symbol(void* library, const char* name) {
  void* found = dlsym(library, name);
  if (found == NULL) {
    printf("FAILED: %s is not exported\n", name);
    exit(1);
  }
  AnyFunction function;
  memcpy(&function, &found, sizeof function);
  return function;
}

static void log_fmi3(fmi3InstanceEnvironment environment, fmi3Status status, fmi3String category, fmi3String message) {
  (void)environment;
  if (status == fmi3Error) ++errors_logged;
  printf("  log %s: %s\n", category, message);
}

static void log_fmi2(fmi2ComponentEnvironment environment, fmi2String instance, fmi2Status status, fmi2String category,
                     fmi2String message, ...) {
  (void)environment;
  va_list arguments;
  va_start(arguments, message);
  if (status == fmi2Error) ++errors_logged;
  printf("  log %s %s: ", instance, category);
  vprintf(message, arguments);
  printf("\n");
  va_end(arguments);
}

/* One FMU of either version behind the few operations the checks need; values travel as doubles. */
typedef struct {
  int version;
  void* library;
  const char* token;
  fmi2CallbackFunctions callbacks;
} Fmu;

static Fmu load(int version, const char* path, const char* token) {
  Fmu fmu = {version, dlopen(path, RTLD_NOW | RTLD_LOCAL), token, {log_fmi2, calloc, free, NULL, NULL}};
  if (fmu.library == NULL) {
    printf("FAILED: cannot load %s: %s\n", path, dlerror());
    exit(1);
  }
  return fmu;
}

static void* instantiate(Fmu* fmu, const char* name, const char* token) {
  if (fmu->version == 3) {
    fmi3InstantiateCoSimulationTYPE* instantiate3 =
        (fmi3InstantiateCoSimulationTYPE*)symbol(fmu->library, "fmi3InstantiateCoSimulation");
    return instantiate3(name, token, NULL, false, true, false, false, NULL, 0, NULL, log_fmi3, NULL);
  }
  fmi2InstantiateTYPE* instantiate2 = (fmi2InstantiateTYPE*)symbol(fmu->library, "fmi2Instantiate");
  return instantiate2(name, fmi2CoSimulation, token, NULL, &fmu->callbacks, fmi2False, fmi2True);
}

/* Instantiated → initialisation → step mode (2.0: SetupExperiment first). */
static int start(Fmu* fmu, void* instance) {
  if (fmu->version == 3) {
    int ok = ((fmi3EnterInitializationModeTYPE*)symbol(fmu->library, "fmi3EnterInitializationMode"))(
                 instance, false, 0, 0, false, 0) == fmi3OK;
    return ok &&
           ((fmi3ExitInitializationModeTYPE*)symbol(fmu->library, "fmi3ExitInitializationMode"))(instance) == fmi3OK;
  }
  int ok = ((fmi2SetupExperimentTYPE*)symbol(fmu->library, "fmi2SetupExperiment"))(instance, fmi2False, 0, 0, fmi2False,
                                                                                   0) == fmi2OK;
  ok =
      ok && ((fmi2EnterInitializationModeTYPE*)symbol(fmu->library, "fmi2EnterInitializationMode"))(instance) == fmi2OK;
  return ok &&
         ((fmi2ExitInitializationModeTYPE*)symbol(fmu->library, "fmi2ExitInitializationMode"))(instance) == fmi2OK;
}

static int step(Fmu* fmu, void* instance, double time, double size) {
  if (fmu->version == 3) {
    fmi3Boolean event = false, terminate = false, early = false;
    fmi3Float64 last = 0;
    return ((fmi3DoStepTYPE*)symbol(fmu->library, "fmi3DoStep"))(instance, time, size, true, &event, &terminate, &early,
                                                                 &last) == fmi3OK;
  }
  return ((fmi2DoStepTYPE*)symbol(fmu->library, "fmi2DoStep"))(instance, time, size, fmi2True) == fmi2OK;
}

static int terminate(Fmu* fmu, void* instance) {
  if (fmu->version == 3) return ((fmi3TerminateTYPE*)symbol(fmu->library, "fmi3Terminate"))(instance) == fmi3OK;
  return ((fmi2TerminateTYPE*)symbol(fmu->library, "fmi2Terminate"))(instance) == fmi2OK;
}

static void free_instance(Fmu* fmu, void* instance) {
  if (fmu->version == 3) {
    ((fmi3FreeInstanceTYPE*)symbol(fmu->library, "fmi3FreeInstance"))(instance);
  } else {
    ((fmi2FreeInstanceTYPE*)symbol(fmu->library, "fmi2FreeInstance"))(instance);
  }
}

/* The kinds of the thermostat's variables: the resources are Float64 (Real), the setpoint and the sample UInt16
 * (Integer), heating Boolean. */
typedef enum { as_float, as_uint16, as_boolean } Kind;

static int get(Fmu* fmu, void* instance, unsigned reference, Kind kind, double* value) {
  const fmi3ValueReference vr = reference;
  int ok;
  if (fmu->version == 3) {
    if (kind == as_float) {
      ok = ((fmi3GetFloat64TYPE*)symbol(fmu->library, "fmi3GetFloat64"))(instance, &vr, 1, value, 1) == fmi3OK;
    } else if (kind == as_uint16) {
      fmi3UInt16 got = 0;
      ok = ((fmi3GetUInt16TYPE*)symbol(fmu->library, "fmi3GetUInt16"))(instance, &vr, 1, &got, 1) == fmi3OK;
      *value = got;
    } else {
      fmi3Boolean got = false;
      ok = ((fmi3GetBooleanTYPE*)symbol(fmu->library, "fmi3GetBoolean"))(instance, &vr, 1, &got, 1) == fmi3OK;
      *value = got ? 1 : 0;
    }
    return ok;
  }
  if (kind == as_float)
    return ((fmi2GetRealTYPE*)symbol(fmu->library, "fmi2GetReal"))(instance, &vr, 1, value) == fmi2OK;
  fmi2Integer got = 0;
  if (kind == as_uint16) {
    ok = ((fmi2GetIntegerTYPE*)symbol(fmu->library, "fmi2GetInteger"))(instance, &vr, 1, &got) == fmi2OK;
  } else {
    ok = ((fmi2GetBooleanTYPE*)symbol(fmu->library, "fmi2GetBoolean"))(instance, &vr, 1, &got) == fmi2OK;
  }
  *value = got;
  return ok;
}

static int set(Fmu* fmu, void* instance, unsigned reference, Kind kind, double value) {
  const fmi3ValueReference vr = reference;
  if (fmu->version == 3) {
    if (kind == as_float) {
      return ((fmi3SetFloat64TYPE*)symbol(fmu->library, "fmi3SetFloat64"))(instance, &vr, 1, &value, 1) == fmi3OK;
    }
    const fmi3UInt16 number = (fmi3UInt16)value;
    return ((fmi3SetUInt16TYPE*)symbol(fmu->library, "fmi3SetUInt16"))(instance, &vr, 1, &number, 1) == fmi3OK;
  }
  if (kind == as_float)
    return ((fmi2SetRealTYPE*)symbol(fmu->library, "fmi2SetReal"))(instance, &vr, 1, &value) == fmi2OK;
  const fmi2Integer number = (fmi2Integer)value;
  return ((fmi2SetIntegerTYPE*)symbol(fmu->library, "fmi2SetInteger"))(instance, &vr, 1, &number) == fmi2OK;
}

/* The recording's columns heating and sample, row by row. */
typedef struct {
  int rows;
  double heating[4096];
  double sample[4096];
} Recording;

static int column_of(char* header, const char* name) {
  int column = 0;
  for (char* field = strtok(header, ",\n"); field != NULL; field = strtok(NULL, ",\n"), ++column) {
    if (strcmp(field, name) == 0) return column;
  }
  return -1;
}

static void read_recording(const char* path, Recording* recording) {
  FILE* file = fopen(path, "r");
  char line[4096];
  if (file == NULL || fgets(line, sizeof line, file) == NULL) {
    printf("FAILED: cannot read %s\n", path);
    exit(1);
  }
  char copy[4096];
  strcpy(copy, line);
  const int heating_column = column_of(copy, "heating");
  strcpy(copy, line);
  const int sample_column = column_of(copy, "sample");
  recording->rows = 0;
  while (recording->rows < 4096 && fgets(line, sizeof line, file) != NULL) {
    int column = 0;
    for (char* field = strtok(line, ",\n"); field != NULL; field = strtok(NULL, ",\n"), ++column) {
      if (column == heating_column) recording->heating[recording->rows] = strtod(field, NULL);
      if (column == sample_column) recording->sample[recording->rows] = strtod(field, NULL);
    }
    ++recording->rows;
  }
  fclose(file);
}

int main(int argc, char** argv) {
  if (argc != 8 + reference_count) {
    printf("usage: c_host VERSION CONTROLLER.so TOKEN PLANT.so TOKEN SIM.csv STEPS VR...\n");
    return 2;
  }
  setvbuf(stdout, NULL, _IOLBF, 0); /* every line out even if the process dies */
  const int version = atoi(argv[1]);
  Fmu controller = load(version, argv[2], argv[3]);
  Fmu plant = load(version, argv[4], argv[5]);
  static Recording recording;
  read_recording(argv[6], &recording);
  const int steps = atoi(argv[7]);
  unsigned vr[reference_count];
  for (int k = 0; k < reference_count; ++k) vr[k] = (unsigned)atoi(argv[8 + k]);
  const double controller_period = 0.01, plant_period = 0.001;
  char what[256];

  /* The token is checked. */
  check(instantiate(&controller, "wrong", "{not-this-fmu}") == NULL, "a wrong token is refused");

  /* Illegal calls are refused: a step before initialisation. */
  void* loop = instantiate(&controller, "loop", controller.token);
  void* room = instantiate(&plant, "room", plant.token);
  check(loop != NULL && room != NULL, "instantiation with the right token");
  errors_logged = 0;
  check(!step(&controller, loop, 0, controller_period), "a step before initialisation is refused");
  check(errors_logged == 1, "the refusal is logged");

  /* Another instance of the same FMU, stepped between the loop's steps with other inputs and parameters. */
  void* other = instantiate(&controller, "other", controller.token);
  check(start(&controller, other), "the second instance initialises");

  /* The closed loop, in the order `duet sim` runs it: the plant up to the controller's tick, then the controller. */
  double led = 0, adc = 0;
  check(start(&plant, room), "the plant initialises");
  check(get(&plant, room, vr[plant_adc_out], as_float, &adc), "the plant's adc output after initialisation");
  check(set(&controller, loop, vr[adc_in], as_float, adc), "the controller's adc input in initialisation mode");
  check(start(&controller, loop), "the controller initialises");
  for (int row = 0; row < steps && row < recording.rows; ++row) {
    const double time = row * controller_period;
    if (row > 0) {
      check(set(&plant, room, vr[plant_led_in], as_float, led), "set the plant's LED input");
      for (int k = 0; k < 10; ++k) {
        check(step(&plant, room, (row - 1) * controller_period + k * plant_period, plant_period), "a plant step");
      }
      check(get(&plant, room, vr[plant_adc_out], as_float, &adc), "get the plant's adc output");
      check(set(&controller, loop, vr[adc_in], as_float, adc), "set the controller's adc input");
      check(step(&controller, loop, time - controller_period, controller_period), "a controller step");
    }
    double heats = -1, sampled = -1;
    check(get(&controller, loop, vr[heating], as_boolean, &heats), "get heating");
    check(get(&controller, loop, vr[sample], as_uint16, &sampled), "get sample");
    check(get(&controller, loop, vr[led_out], as_float, &led), "get the LED output");
    snprintf(what, sizeof what, "row %d (t = %.2f s): heating %g and sample %g as duet sim's %g and %g", row, time,
             heats, sampled, recording.heating[row], recording.sample[row]);
    check(heats == recording.heating[row] && sampled == recording.sample[row], what);
    check(led == heats, "the LED output is heating");

    /* The other instance: a cold room (adc 0) and its setpoint moved between steps; the loop must not notice. */
    check(set(&controller, other, vr[adc_in], as_float, row < steps / 2 ? 0 : 1500), "set the other's input");
    if (row == steps / 2) check(set(&controller, other, vr[setpoint], as_uint16, 1000), "tune the other's setpoint");
    check(step(&controller, other, time, controller_period), "the other's step");
    double other_heats = -1;
    check(get(&controller, other, vr[heating], as_boolean, &other_heats), "get the other's heating");
    /* 0 < 2000 heats; after the change 1500 < 1000 does not. */
    snprintf(what, sizeof what, "row %d: the other instance heats %g", row, other_heats);
    check(other_heats == (row < steps / 2 ? 1 : 0), what);
  }
  check(recording.rows >= steps, "the recording has a row per step");

  /* Refusals in step mode. */
  errors_logged = 0;
  double now = (steps - 1) * controller_period;
  check(!step(&controller, loop, now + 0.5, controller_period), "a wrong currentCommunicationPoint is refused");
  check(!step(&controller, loop, now, controller_period * 0.5), "a step of half a base period is refused");
  check(set(&controller, loop, vr[adc_in], as_float, 0), "set an input");
  double ignored = 0;
  check(!get(&controller, loop, vr[heating], as_boolean, &ignored), "a Get after a Set without a step is refused");
  check(!set(&controller, loop, vr[heating], as_boolean, 1), "a local cannot be set");
  check(errors_logged == 4, "each refusal is logged");
  check(step(&controller, loop, now, 3 * controller_period), "a step of three base periods");

  check(terminate(&controller, loop) && terminate(&plant, room) && terminate(&controller, other), "terminate");
  check(!step(&controller, loop, now + 3 * controller_period, controller_period), "no step after terminating");
  free_instance(&controller, loop);
  free_instance(&controller, other);
  free_instance(&plant, room);
  /* The libraries stay loaded: the static C++ library in each allocates its exception pool once and never frees it,
   * which a sanitizer would take for a leak after dlclose. */
  printf("%s: %d failed checks\n", failures == 0 ? "passed" : "FAILED", failures);
  return failures == 0 ? 0 : 1;
}
