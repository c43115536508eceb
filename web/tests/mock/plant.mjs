// The mock's simulated plant behind the target, as duet pil's plant-control endpoint offers it: its description and
// its answers to `plant` requests (docs/DASHBOARD.md), checked as the real endpoint checks them.
export const plantDescription = {
  name: 'mock robot',
  actions: [
    {
      name: 'push',
      summary: "a horizontal force at the body's centre of mass, + forward",
      arguments: [
        { name: 'force_n', unit: 'N', min: -50, max: 50, default: 5 },
        { name: 'duration_s', unit: 's', min: 0.001, max: 1, default: 0.05 },
      ],
    },
    { name: 'restart', summary: 'picked up and put back as the scenario starts it', arguments: [] },
  ],
};

// The answer to `request` at model time `timeS`: the applied event, or {error} naming the problem.
export function answerPlant(request, timeS) {
  const names = plantDescription.actions.map((action) => action.name).join(', ');
  if (typeof request.action !== 'string') return { type: 'plant', error: `a plant request needs "action": ${names}` };
  const action = plantDescription.actions.find((candidate) => candidate.name === request.action);
  const refuse = (problem) => ({ type: 'plant', action: request.action, error: problem });
  if (!action) return refuse(`unknown action '${request.action}': ${names}`);
  const takes = action.arguments.map((argument) => argument.name);
  const stray = Object.keys(request).find((member) => !['type', 'action', 'id'].includes(member) && !takes.includes(member));
  if (stray) return refuse(`${action.name} takes no argument '${stray}'`);
  const values = {};
  for (const argument of action.arguments) {
    const value = request[argument.name] ?? argument.default;
    if (typeof value !== 'number') return refuse(`${action.name}: ${argument.name} is a number`);
    if (!(value >= argument.min && value <= argument.max)) {
      return refuse(`${action.name}: ${argument.name} = ${value} ${argument.unit} is outside ${argument.min} to ${argument.max} ${argument.unit}`);
    }
    values[argument.name] = value;
  }
  return { type: 'plant', action: action.name, arguments: values, time_s: timeS };
}
