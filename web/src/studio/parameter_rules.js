// What a block parameter may be, from its library entry: the form validates before it writes,
// so the text only ever gets values of the right shape (the server still checks the meaning).
import { isIdentifier } from './yaml_edit.js';

const numberPattern = /^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/;

// The numbers in a literal: a scalar or a (nested) list of them; null when it is not one.
function numbersIn(text) {
  if (numberPattern.test(text)) return [Number(text)];
  if (!/^\[.*\]$/s.test(text)) return null;
  const items = text.replace(/[[\]]/g, ' ').split(/[\s,]+/).filter(Boolean);
  if (items.length === 0 || !items.every((item) => numberPattern.test(item) || item === 'true' || item === 'false')) return null;
  return items.filter((item) => numberPattern.test(item)).map(Number);
}

// Returns an error message, or '' when `typed` may be written. A number parameter may also name
// a model parameter or constant; whether the name exists is the server's check (it knows the
// constants, the page does not).
export function parameterProblem(spec, typed) {
  const text = typed.trim();
  if (text === '') return spec.required ? `${spec.name} is required` : '';
  if (spec.choices?.length) return spec.choices.includes(text) ? '' : `one of ${spec.choices.join(', ')}`;
  if (spec.kind === 'word' || spec.kind === 'data_type') return '';
  if (isIdentifier(text)) return '';
  const numbers = numbersIn(text);
  if (!numbers) return 'a number, a list like [1, 2], or a parameter name';
  return limitsProblem(spec, numbers);
}

export function limitsProblem({ min, max, integer }, numbers) {
  for (const value of numbers) {
    if (integer && !Number.isInteger(value)) return 'a whole number';
    if (min !== undefined && min !== null && value < min) return `at least ${min}`;
    if (max !== undefined && max !== null && value > max) return `at most ${max}`;
  }
  return '';
}

// A model parameter's value (Parameter: type, min, max).
export function modelValueProblem(parameter, typed) {
  const text = typed.trim();
  if (text === '') return 'a value is required';
  if (parameter.type === 'boolean') return ['true', 'false', '0', '1'].includes(text) ? '' : 'true or false';
  const numbers = numbersIn(text);
  if (!numbers) return 'a number or a list like [1, 2]';
  const integer = /^u?int/.test(parameter.type ?? '');
  return limitsProblem({ min: parameter.min, max: parameter.max, integer }, numbers);
}

// What a new block's required parameter starts as (as typed; yamlValue writes it): within
// the limits, the first choice when there are choices.
export function defaultValue(spec) {
  if (spec.choices?.length) return spec.kind === 'data_type' && spec.choices.includes('single') ? 'single' : spec.choices[0];
  if (spec.kind === 'data_type') return 'single';
  if (spec.kind === 'word') return ''; // a pin, a timer: nothing sensible to guess; the check asks for it
  const low = spec.min ?? -Infinity;
  const high = spec.max ?? Infinity;
  for (const candidate of [1, 0, low, high]) if (Number.isFinite(candidate) && candidate >= low && candidate <= high) return String(candidate);
  return '1';
}
