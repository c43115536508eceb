import { test } from 'node:test';
import assert from 'node:assert/strict';
import { presetText, readPreset } from '../src/preset.js';

const parameters = [
  { name: 'P', type: 'float32', min: 0, max: 1 },
  { name: 'D', type: 'float32', min: 0, max: 1 },
];

test('a saved preset reads back', () => {
  const text = presetText('balbot', { P: 0.02, D: 0.5 });
  assert.deepEqual(JSON.parse(text), { application: 'balbot', parameters: { P: 0.02, D: 0.5 } });
  assert.deepEqual(readPreset(text, parameters, 'balbot'), { values: { P: 0.02, D: 0.5 }, warnings: [] });
});

test('names not in the description and non-numbers are warned about, the rest used', () => {
  const { values, warnings } = readPreset('{"application":"other","parameters":{"P":0.1,"Q":1,"D":"x"}}', parameters, 'balbot');
  assert.deepEqual(values, { P: 0.1 });
  assert.equal(warnings.length, 3);
  assert.ok(warnings.some((warning) => warning.includes('Q')));
  assert.ok(warnings.some((warning) => warning.includes('other')));
});

test('files that are not presets are refused with a reason', () => {
  assert.match(readPreset('nope', parameters).warnings[0], /not JSON/);
  assert.match(readPreset('{"P":1}', parameters).warnings[0], /parameters/);
});
