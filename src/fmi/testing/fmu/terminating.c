/* y = time; the step that reaches stop_at asks the importer to stop. Value references: 1 y, 2 stop_at. */
#include "model.h"

const unsigned model_value_count = 3;

void model_start(double values[]) {
  values[1] = values[0];
  values[2] = 1.0;
}

ModelStepResult model_step(double values[], double step) {
  values[1] = values[0] + step;
  return values[1] >= values[2] - 1e-9 ? MODEL_TERMINATED : MODEL_STEPPED;
}
