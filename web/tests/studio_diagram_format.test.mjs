import { test } from 'node:test';
import assert from 'node:assert/strict';
import { formatLiveValue, formatScalar } from '../src/studio/diagram/value_format.js';
import { constant_colour, legendEntries, taskColours, taskRateText, unknown_colour } from '../src/studio/diagram/task_colours.js';
import { subsystemMarking } from '../src/studio/diagram/subsystem_marking.js';

const tasks = [
  { index: 0, name: 'base', kind: 'periodic', period_us: 1000 },
  { index: 1, name: 'slow', kind: 'periodic', period_us: 10000 },
  { index: 2, name: 'EXTI8', kind: 'interrupt', interrupt: 'EXTI8', priority: 5 },
  { index: 3, name: 'TIM1', kind: 'interrupt', interrupt: 'TIM1', priority: 2 },
];

test('live values: about 4 significant digits, integers whole, tiny and huge in exponent form', () => {
  assert.equal(formatScalar(3.14159265), '3.142');
  assert.equal(formatScalar(0.019487), '0.01949');
  assert.equal(formatScalar(42), '42');
  assert.equal(formatScalar(4294967295), '4.295e9');
  assert.equal(formatScalar(1.2e-5), '1.2e-5');
  assert.equal(formatScalar(-123.456), '-123.5');
  assert.equal(formatScalar(0), '0');
  assert.equal(formatScalar(true), '1');
  assert.equal(formatScalar(NaN), 'NaN');
  assert.equal(formatScalar(undefined), '—');
});

test('live vectors: all of up to 3 elements, else the first 3 and the length', () => {
  assert.equal(formatLiveValue([0.02, 0, 0.019]), '[0.02, 0, 0.019]');
  assert.equal(formatLiveValue([1.2, 3.4, 5.6, 7, 8, 9, 10, 11]), '[1.2, 3.4, 5.6, …] (8)');
  assert.equal(formatLiveValue(new Float32Array([1, 2])), '[1, 2]');
  assert.equal(formatLiveValue(2.5), '2.5');
});

test('task colours: periodic red, green, blue fastest first; interrupts apart; constant magenta; unknown grey', () => {
  const colourOf = taskColours(tasks);
  assert.equal(colourOf(0), '#d62728');
  assert.equal(colourOf(1), '#2ca02c');
  assert.notEqual(colourOf(2), colourOf(3));
  assert.ok(![colourOf(0), colourOf(1)].includes(colourOf(2)));
  assert.equal(colourOf('constant'), constant_colour);
  assert.equal(colourOf(null), unknown_colour);
  assert.equal(colourOf(17), unknown_colour);
});

test('the legend lists every task with its rate, then constant and not known when used', () => {
  assert.equal(taskRateText(tasks[1]), '10 ms');
  assert.equal(taskRateText({ kind: 'periodic', period_us: 500 }), '0.5 ms');
  assert.equal(taskRateText({ kind: 'interrupt', name: 'receive', interrupt: 'IPCC_RX1', priority: 9 }), 'IPCC_RX1 · priority 9');
  const rows = legendEntries(tasks, [0, 'constant', null]);
  assert.deepEqual(rows.map((row) => [row.name, row.rate]), [
    ['base', '1 ms'], ['slow', '10 ms'], ['EXTI8', 'priority 5'], ['TIM1', 'priority 2'],
    ['constant', 'at initialisation'], ['not known', ''],
  ]);
  assert.equal(legendEntries(tasks, [0, 1]).length, 4);
});

test('subsystem marking: edge and signal, interrupt and priority (own or the task table), enable', () => {
  const subsystem = { type: 'Subsystem' };
  assert.equal(subsystemMarking({ ...subsystem, trigger: { kind: 'edge', edge: 'rising', signal: 'write_wake' } }, tasks), '↑ rising: write_wake');
  assert.equal(subsystemMarking({ ...subsystem, trigger: { kind: 'edge', edge: 'falling', signal: 'x' } }, tasks), '↓ falling: x');
  assert.equal(subsystemMarking({ ...subsystem, trigger: { kind: 'interrupt', interrupt: 'EXTI8', priority: 2 } }, tasks), 'EXTI8 · priority 2');
  assert.equal(subsystemMarking({ ...subsystem, task: 3 }, tasks), 'TIM1 · priority 2');
  assert.equal(subsystemMarking({ ...subsystem, enable: 'stop_off', task: 0 }, tasks), 'enable: stop_off');
  assert.equal(subsystemMarking({ ...subsystem, task: 0 }, tasks), '');
  assert.equal(subsystemMarking({ type: 'Gain', task: 2 }, tasks), '');
});
