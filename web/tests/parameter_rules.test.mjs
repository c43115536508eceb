import { test } from 'node:test';
import assert from 'node:assert/strict';
import { asStored, problemWith, sameValue, stepFor } from '../src/parameter_rules.js';

const gain = { name: 'P', type: 'float32', min: 0, max: 1 };
const mode = { name: 'mode', type: 'uint8', min: 0, max: 3 };

test('steps: whole numbers for integers, a thousandth of the range for floats', () => {
  assert.equal(stepFor(mode), 1);
  assert.equal(stepFor(gain), 0.001);
  assert.equal(stepFor({ type: 'float64', min: -Infinity, max: 1 }), 'any');
});

test('float32 values compare at float32 precision', () => {
  assert.ok(sameValue(gain, 0.05, 0.05000000074505806));
  assert.ok(!sameValue(gain, 0.05, 0.051));
  assert.ok(!sameValue(gain, 0.05, undefined));
  assert.ok(sameValue({ type: 'float64' }, 0.1, 0.1));
  assert.ok(!sameValue({ type: 'float64' }, 0.1, 0.1 + 1e-15));
});

test('stored values: float32 rounding, integers rounded', () => {
  assert.equal(asStored(gain, 0.1), Math.fround(0.1));
  assert.equal(asStored(mode, 2.4), 2);
});

test('problems mirror the back ends checks', () => {
  assert.equal(problemWith(gain, 0.5), '');
  assert.match(problemWith(gain, 1.5), /maximum/);
  assert.match(problemWith(gain, -1), /minimum/);
  assert.match(problemWith(mode, 1.5), /whole/);
  assert.match(problemWith(gain, NaN), /not a number/);
});
