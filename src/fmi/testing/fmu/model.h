/* What a test model gives the FMI frames (fmi2_frame.c, fmi3_frame.c): Float64 values numbered by their value
 * reference, 0 being time, and a step from one communication point to the next. */
#ifndef DUET_FMI_TEST_MODEL_H
#define DUET_FMI_TEST_MODEL_H

#define MODEL_MAX_VALUES 8

typedef enum { MODEL_STEPPED, MODEL_TERMINATED, MODEL_FAILED } ModelStepResult;

extern const unsigned model_value_count; /* value references 0 .. count-1 */
void model_start(double values[]);       /* the start values of modelDescription.xml */
/* Advances from values[0] by `step`; the frame sets values[0] afterwards. */
ModelStepResult model_step(double values[], double step);

#endif
