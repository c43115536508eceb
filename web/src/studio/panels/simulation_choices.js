// What the Simulation panel offers to simulate against, from the `studio` message.

// Plants: the built-in ones by name, then the model files beside the model (a model with
// PlantInput and PlantOutput blocks can be a plant). The model itself and the default scenario
// cannot be its own plant, so they are left out; the server still checks whatever is chosen.
// The command line's plant is always offered, even when it is neither.
export function plantChoices(studio) {
  const choices = (studio?.plants ?? []).map((plant) => ({ value: plant.name, label: plant.name, title: plant.description ?? '', group: 'plants' }));
  const notPlants = new Set([studio?.file, studio?.defaults?.scenario]);
  for (const file of studio?.files ?? []) {
    if (!notPlants.has(file) && !choices.some((choice) => choice.value === file)) choices.push({ value: file, label: file, title: '', group: 'model files' });
  }
  const wanted = studio?.defaults?.plant;
  if (wanted && !choices.some((choice) => choice.value === wanted)) choices.push({ value: wanted, label: wanted, title: '', group: 'model files' });
  return choices;
}

// Scenarios: none, or one of the files beside the model (only the robot, `balbot`, takes one).
export function scenarioChoices(studio) {
  const files = (studio?.files ?? []).filter((file) => file !== studio?.file);
  const wanted = studio?.defaults?.scenario;
  if (wanted && !files.includes(wanted)) files.push(wanted);
  return [{ value: '', label: 'none' }, ...files.map((file) => ({ value: file, label: file }))];
}

export const plant_taking_scenarios = 'balbot';

// The `simulate` request, or a reason it cannot be sent.
export function simulateRequest({ text, id, durationS, plant, scenario }) {
  if (!(Number.isFinite(durationS) && durationS > 0)) return { problem: 'the duration must be a positive number of seconds' };
  if (!plant) return { problem: 'choose a plant' };
  return { request: { type: 'simulate', text, id, duration_s: durationS, plant, scenario: plant === plant_taking_scenarios ? scenario : '' } };
}
