// What hovering a block tells: its type and the library's summary, and per parameter the text
// as written, the model parameter it names (value, unit, limits) and the library's documentation.

function limitsText(low, high) {
  if (low === undefined && high === undefined) return '';
  return `${low ?? '−∞'} … ${high ?? '∞'}`;
}

function documentationText(documentation) {
  if (!documentation) return '';
  const facts = [documentation.kind === 'word' && documentation.choices ? 'one of' : documentation.kind];
  if (documentation.choices?.length) facts.push(documentation.choices.join(', '));
  const limits = limitsText(documentation.min, documentation.max);
  if (limits) facts.push(limits);
  if (documentation.integer) facts.push('integer');
  if (documentation.required) facts.push('required');
  return [documentation.description, `(${facts.filter(Boolean).join(' ')})`].filter(Boolean).join(' ');
}

function modelParameterText(parameter) {
  if (!parameter) return '';
  const value = [parameter.value, parameter.unit].filter(Boolean).join(' ');
  const limits = limitsText(parameter.min, parameter.max);
  return [`${parameter.name} = ${value}`, limits ? `in ${limits}` : '', parameter.description ? `— ${parameter.description}` : ''].filter(Boolean).join(' ');
}

export function describeBlock(block, libraryEntry, modelParameters) {
  const documented = new Map((libraryEntry?.parameters ?? []).map((parameter) => [parameter.name, parameter]));
  const written = new Set((block.parameters ?? []).map((argument) => argument.name));
  const parameters = (block.parameters ?? []).map((argument) => ({
    name: argument.name,
    text: argument.text,
    model: modelParameterText(argument.reference ? modelParameters.get(argument.reference) : null),
    documentation: documentationText(documented.get(argument.name)),
  }));
  // Parameters left at their defaults are worth knowing about too.
  const unset = [...documented.values()].filter((parameter) => !written.has(parameter.name))
    .map((parameter) => ({ name: parameter.name, text: '', model: '', documentation: documentationText(parameter) }));
  return {
    title: block.name,
    type: block.type,
    summary: libraryEntry?.summary ?? '',
    code: block.code ? `${block.code.function} in ${block.code.file}` : '',
    parameters,
    unset,
  };
}
