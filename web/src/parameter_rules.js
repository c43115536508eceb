// What a parameter's type means for editing it: integers move in steps of 1, float32 values
// compare equal when they round to the same float32 (the target can hold nothing finer).

const integer_types = new Set(['uint8', 'int8', 'uint16', 'int16', 'uint32', 'int32', 'uint64', 'int64']);

export function isIntegerType(type) {
  return integer_types.has(type);
}

export function hasUsableLimits(parameter) {
  return Number.isFinite(parameter.min) && Number.isFinite(parameter.max) && parameter.max > parameter.min;
}

// The slider's step: whole numbers for integers, a thousandth of the range for floats.
export function stepFor(parameter) {
  if (isIntegerType(parameter.type)) return 1;
  if (!hasUsableLimits(parameter)) return 'any';
  return (parameter.max - parameter.min) / 1000;
}

// The value the target would hold after a write of `value`.
export function asStored(parameter, value) {
  if (isIntegerType(parameter.type)) return Math.round(value);
  if (parameter.type === 'float32') return Math.fround(value);
  return value;
}

export function sameValue(parameter, a, b) {
  if (typeof a !== 'number' || typeof b !== 'number') return false;
  return asStored(parameter, a) === asStored(parameter, b);
}

// Significant digits worth showing in an edit field.
export function digitsFor(parameter) {
  return parameter.type === 'float64' ? 12 : 7;
}

// Why `value` cannot be written, or '' when it can; mirrors the back ends' own checks so the
// page can say so before the round trip.
export function problemWith(parameter, value) {
  if (typeof value !== 'number' || Number.isNaN(value)) return 'not a number';
  if (Number.isFinite(parameter.min) && value < parameter.min) return `below the minimum ${parameter.min}`;
  if (Number.isFinite(parameter.max) && value > parameter.max) return `above the maximum ${parameter.max}`;
  if (isIntegerType(parameter.type) && !Number.isInteger(value)) return `${parameter.type} takes whole numbers`;
  return '';
}
