import { test } from 'node:test';
import assert from 'node:assert/strict';
import { actionLabel, argumentLabel, buildRequest, describePlantEvent, plantActions } from '../src/plant_actions.js';

const described = {
  type: 'description',
  plant: {
    name: 'balbot',
    actions: [
      { name: 'push', summary: 'a shove', arguments: [{ name: 'force_n', unit: 'N', min: -50, max: 50, default: 5 }, { name: 'duration_s', unit: 's', min: 0.001, max: 1, default: 0.05 }] },
      { name: 'duty_pulse', summary: '', arguments: [{ name: 'duty', unit: '', min: -1, max: 1, default: 1 }] },
      { name: 'restart', summary: 'again', arguments: [] },
    ],
  },
};

test('the actions come from the description; without a plant there are none', () => {
  const actions = plantActions(described);
  assert.deepEqual(actions.map((action) => action.name), ['push', 'duty_pulse', 'restart']);
  assert.deepEqual(actions[0].arguments[1], { name: 'duration_s', unit: 's', min: 0.001, max: 1, default: 0.05 });
  assert.deepEqual(plantActions({ type: 'description', parameters: [] }), []);
  assert.deepEqual(plantActions({ plant: { actions: 'push' } }), []);
  assert.deepEqual(plantActions({ plant: { actions: [{ summary: 'no name' }] } }), []);
});

test('labels read as words; a unit in the name is left to the unit', () => {
  assert.equal(actionLabel('push'), 'Push');
  assert.equal(actionLabel('duty_pulse'), 'Duty pulse');
  assert.equal(argumentLabel({ name: 'force_n', unit: 'N' }), 'force');
  assert.equal(argumentLabel({ name: 'duration_s', unit: 's' }), 'duration');
  assert.equal(argumentLabel({ name: 'duty', unit: '' }), 'duty');
});

test('a request carries every argument by name, or nothing is sent and the problem is said', () => {
  const [push, , restart] = plantActions(described);
  assert.deepEqual(buildRequest(push, { force_n: '7.5', duration_s: ' 0.1 ' }), { request: { type: 'plant', action: 'push', force_n: 7.5, duration_s: 0.1 } });
  assert.deepEqual(buildRequest(restart, {}), { request: { type: 'plant', action: 'restart' } });
  assert.equal(buildRequest(push, { force_n: '80', duration_s: '0.1' }).problem, 'push: force_n 80 N is outside -50 to 50 N');
  assert.equal(buildRequest(push, { force_n: 'hard', duration_s: '0.1' }).problem, 'push: force_n must be a number');
  assert.equal(buildRequest(push, { force_n: '5', duration_s: '' }).problem, 'push: duration_s must be a number');
});

test('an event reads with its arguments, units and model time; a refusal with its problem', () => {
  const actions = plantActions(described);
  assert.equal(
    describePlantEvent({ type: 'plant', action: 'push', arguments: { force_n: 5, duration_s: 0.05 }, time_s: 12.3456 }, actions),
    'push force_n=5 N duration_s=0.05 s at 12.346 s',
  );
  assert.equal(describePlantEvent({ type: 'plant', action: 'restart', arguments: {}, time_s: 3 }, actions), 'restart at 3.000 s');
  assert.equal(describePlantEvent({ type: 'plant', action: 'push', error: 'too hard' }, actions), 'push: too hard');
  assert.equal(describePlantEvent({ type: 'plant', error: 'not reachable' }), 'plant: not reachable');
});
