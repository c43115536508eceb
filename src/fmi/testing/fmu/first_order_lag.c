/* y' = (k*u - y) / T, stepped exactly for a constant u. Value references: 1 u, 2 y, 3 T, 4 k. */
#include <math.h>

#include "model.h"

const unsigned model_value_count = 5;

void model_start(double values[]) {
  values[1] = 0.0;
  values[2] = 0.0;
  values[3] = 0.5;
  values[4] = 2.0;
}

ModelStepResult model_step(double values[], double step) {
  if (!(values[3] > 0.0)) return MODEL_FAILED; /* a time constant must be positive */
  values[2] += (values[4] * values[1] - values[2]) * (1.0 - exp(-step / values[3]));
  return MODEL_STEPPED;
}
