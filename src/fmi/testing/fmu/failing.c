/* y = time; the step that reaches fail_at fails. Value references: 1 y, 2 fail_at. */
#include "model.h"

const unsigned model_value_count = 3;

void model_start(double values[]) {
  values[1] = values[0];
  values[2] = 0.5;
}

ModelStepResult model_step(double values[], double step) {
  if (values[0] + step >= values[2] - 1e-9) return MODEL_FAILED;
  values[1] = values[0] + step;
  return MODEL_STEPPED;
}
