// Preset files: {"application": name, "parameters": {name: value, ...}}.

export function presetText(application, values) {
  return `${JSON.stringify({ application, parameters: values }, null, 2)}\n`;
}

// Reads a preset against the description's parameters. Returns the values to put in the edit
// fields and warnings for everything that could not be used; never throws on bad content.
export function readPreset(text, parameters, application) {
  let preset;
  try {
    preset = JSON.parse(text);
  } catch (error) {
    return { values: {}, warnings: [`not JSON: ${error.message}`] };
  }
  if (!preset || typeof preset !== 'object' || !preset.parameters || typeof preset.parameters !== 'object') {
    return { values: {}, warnings: ['no "parameters" object in the file'] };
  }
  const known = new Map(parameters.map((parameter) => [parameter.name, parameter]));
  const values = {};
  const warnings = [];
  if (preset.application !== undefined && application !== undefined && preset.application !== application) {
    warnings.push(`saved for "${preset.application}", not "${application}"`);
  }
  const unknown = [];
  for (const [name, value] of Object.entries(preset.parameters)) {
    if (!known.has(name)) unknown.push(name);
    else if (typeof value !== 'number' || !Number.isFinite(value)) warnings.push(`${name}: ${JSON.stringify(value)} is not a number`);
    else values[name] = value;
  }
  if (unknown.length > 0) warnings.push(`not in the description: ${unknown.join(', ')}`);
  return { values, warnings };
}
