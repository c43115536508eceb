import { test } from 'node:test';
import assert from 'node:assert/strict';
import { plantChoices, scenarioChoices, simulateRequest } from '../src/studio/panels/simulation_choices.js';
import { resultStore, spanOf } from '../src/studio/panels/result_store.js';
import { Decimator } from '../src/decimate.js';

const studio = {
  file: 'balbot.yaml',
  plants: [{ name: 'none', description: 'no plant' }, { name: 'balbot', description: 'the robot' }],
  files: ['balbot.yaml', 'heater.yaml', 'disturbed.yaml'],
  defaults: { plant: 'balbot', scenario: 'disturbed.yaml', duration_s: 5, xcp: '' },
};

test('plants: the built-in ones, then the files beside the model but the model and the scenario', () => {
  assert.deepEqual(plantChoices(studio).map((choice) => [choice.value, choice.group]), [['none', 'plants'], ['balbot', 'plants'], ['heater.yaml', 'model files']]);
  assert.equal(plantChoices(studio)[1].title, 'the robot');
  // The command line's plant is offered even when the lists do not have it.
  assert.ok(plantChoices({ ...studio, defaults: { plant: 'plants/motor.yaml' } }).some((choice) => choice.value === 'plants/motor.yaml'));
  assert.deepEqual(plantChoices(undefined), []);
});

test('scenarios: none, then the files beside the model', () => {
  assert.deepEqual(scenarioChoices(studio).map((choice) => choice.value), ['', 'heater.yaml', 'disturbed.yaml']);
  assert.equal(scenarioChoices(studio)[0].label, 'none');
});

test('the simulate request carries the text, id, duration, plant and, for balbot only, the scenario', () => {
  const base = { text: 'name: m\n', id: 3, durationS: 2.5, scenario: 'disturbed.yaml' };
  assert.deepEqual(simulateRequest({ ...base, plant: 'balbot' }).request, { type: 'simulate', text: 'name: m\n', id: 3, duration_s: 2.5, plant: 'balbot', scenario: 'disturbed.yaml' });
  assert.equal(simulateRequest({ ...base, plant: 'heater.yaml' }).request.scenario, '');
  assert.match(simulateRequest({ ...base, plant: 'balbot', durationS: NaN }).problem, /duration/);
  assert.match(simulateRequest({ ...base, plant: 'balbot', durationS: 0 }).problem, /duration/);
  assert.match(simulateRequest({ ...base, plant: '' }).problem, /plant/);
});

const simulation = {
  type: 'simulation',
  id: 1,
  names: ['theta', 'u[0]', 'u[1]'],
  units: ['deg', 'V', 'V'],
  time_s: [0, 0.001, 0.002, 0.003],
  columns: [[0, 1, 2, 3], [5, null, 5, 5], [1, 1]],
  decimated_by: 1,
  cancelled: true,
};

test('a result reads like a signal store: signals by column, gaps as NaN, short columns padded', () => {
  const store = resultStore(simulation);
  assert.deepEqual(store.signals, [
    { name: 'theta', unit: 'deg', index: 0 },
    { name: 'u[0]', unit: 'V', index: 1 },
    { name: 'u[1]', unit: 'V', index: 2 },
  ]);
  assert.deepEqual([...store.time.view()], [0, 0.001, 0.002, 0.003]);
  assert.deepEqual([...store.values[1].view()], [5, NaN, 5, 5]);
  assert.deepEqual([...store.values[2].view()], [1, 1, NaN, NaN]);
  assert.equal(spanOf(store), 0.003);
  assert.equal(spanOf(resultStore({ names: [] })), 0);
});

test('the dashboard decimator takes a result as it takes the live rings', () => {
  const time = Array.from({ length: 10000 }, (_, i) => i * 0.001);
  const store = resultStore({ names: ['x'], units: [''], time_s: time, columns: [time.map((t) => (t === 5 ? 100 : 0))] });
  const [x, y] = new Decimator().decimate(store.time.view(), [store.values[0].view()], 0, 9.999, 200);
  assert.ok(x.length <= 2 * 202 + 1);
  assert.equal(Math.max(...y), 100); // a one-sample spike survives
});
