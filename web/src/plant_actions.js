// What a simulated plant offers to disturb it (the description's `plant` member, docs/DASHBOARD.md), as the Disturb
// box shows and sends it: no plant's names are known here, every action and argument comes from the description.

// The actions of `description.plant`, each {name, summary, arguments: [{name, unit, min, max, default}]}; none
// without a plant (the board's bridge), or when what it says is not that shape.
export function plantActions(description) {
  const actions = description?.plant?.actions;
  if (!Array.isArray(actions)) return [];
  return actions
    .filter((action) => action && typeof action.name === 'string')
    .map((action) => ({
      name: action.name,
      summary: typeof action.summary === 'string' ? action.summary : '',
      arguments: (Array.isArray(action.arguments) ? action.arguments : [])
        .filter((argument) => argument && typeof argument.name === 'string')
        .map((argument) => ({
          name: argument.name,
          unit: typeof argument.unit === 'string' ? argument.unit : '',
          min: Number(argument.min),
          max: Number(argument.max),
          default: Number(argument.default),
        })),
    }));
}

// "duty_pulse" -> "Duty pulse"; "force_n" with unit N -> "force" (the unit says the rest).
export function actionLabel(name) {
  const words = name.replace(/_/g, ' ');
  return words.charAt(0).toUpperCase() + words.slice(1);
}
export function argumentLabel(argument) {
  const suffix = argument.unit ? `_${argument.unit.toLowerCase().replace(/[^a-z0-9]/g, '')}` : '';
  const bare = suffix && argument.name.endsWith(suffix) ? argument.name.slice(0, -suffix.length) : argument.name;
  return bare.replace(/_/g, ' ');
}

// The request for `action` with the fields' texts by argument name: {request} or, when a field is no number or out
// of its limits, {problem} naming it (nothing is sent then).
export function buildRequest(action, texts) {
  const request = { type: 'plant', action: action.name };
  for (const argument of action.arguments) {
    const text = String(texts[argument.name] ?? '').trim();
    const value = Number(text);
    const unit = argument.unit ? ` ${argument.unit}` : '';
    if (text === '' || !Number.isFinite(value)) return { problem: `${action.name}: ${argument.name} must be a number` };
    if (value < argument.min || value > argument.max) {
      return { problem: `${action.name}: ${argument.name} ${value}${unit} is outside ${argument.min} to ${argument.max}${unit}` };
    }
    request[argument.name] = value;
  }
  return { request };
}

// A `plant` message as a line: "push force_n=5 N duration_s=0.05 s at 12.345 s", or the problem.
export function describePlantEvent(message, actions = []) {
  const name = typeof message.action === 'string' ? message.action : 'plant';
  if (typeof message.error === 'string') return `${name}: ${message.error}`;
  const units = new Map((actions.find((action) => action.name === name)?.arguments ?? []).map((argument) => [argument.name, argument.unit]));
  const parts = Object.entries(message.arguments ?? {}).map(([argument, value]) => {
    const unit = units.get(argument);
    return `${argument}=${value}${unit ? ` ${unit}` : ''}`;
  });
  const time = typeof message.time_s === 'number' ? ` at ${message.time_s.toFixed(3)} s` : '';
  return [name, ...parts].join(' ') + time;
}
