import { test } from 'node:test';
import assert from 'node:assert/strict';
import { describeValue, nameOf, namedFirst } from '../src/value_names.js';

const state = { name: 'robot_state', unit: '', labels: [{ value: 0, text: 'initialising' }, { value: 1, text: 'balancing' }, { value: 2, text: 'stopped' }] };
const theta = { name: 'theta', unit: 'deg' };

test('a named value shows its name; a value without one, and an item without names, show the number', () => {
  assert.equal(nameOf(state, 1), 'balancing');
  assert.equal(nameOf(state, 7), undefined);
  assert.equal(nameOf(theta, 1), undefined);
  assert.equal(describeValue(state, 2), 'stopped');
  assert.equal(describeValue(state, 7), '7');
  assert.equal(describeValue(theta, 0.05000000074505806), '0.05 deg');
  assert.equal(describeValue(theta, NaN), '—');
  assert.equal(describeValue(theta, undefined), '—');
});

test('named items come first, the rest keep their order', () => {
  const battery = { name: 'battery', unit: 'V' };
  assert.deepEqual(namedFirst([theta, state, battery]).map((item) => item.name), ['robot_state', 'theta', 'battery']);
});
