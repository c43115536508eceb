/* x'' = a, stepped exactly for a constant a. Value references: 1 a, 2 x, 3 v. */
#include "model.h"

const unsigned model_value_count = 4;

void model_start(double values[]) {
  values[1] = 0.0;
  values[2] = 0.0;
  values[3] = 0.0;
}

ModelStepResult model_step(double values[], double step) {
  values[2] += values[3] * step + 0.5 * values[1] * step * step;
  values[3] += values[1] * step;
  return MODEL_STEPPED;
}
