import { test } from 'node:test';
import assert from 'node:assert/strict';
import { formatPeriod, formatSize, taskRows } from '../src/studio/panels/generated_tables.js';

test('periods read in the fitting unit', () => {
  assert.equal(formatPeriod(250), '250 µs');
  assert.equal(formatPeriod(1000), '1 ms');
  assert.equal(formatPeriod(2500), '2.5 ms');
  assert.equal(formatPeriod(1500000), '1.5 s');
  assert.equal(formatPeriod(undefined), '—');
});

test('file sizes count UTF-8 bytes', () => {
  assert.equal(formatSize('abc'), '3 B');
  assert.equal(formatSize('µ'), '2 B');
  assert.equal(formatSize('x'.repeat(2048)), '2 KB');
  assert.equal(formatSize('x'.repeat(1500)), '1.46 KB');
  assert.equal(formatSize(undefined), '0 B');
});

test('a task row: name, kind, period or interrupt and priority, blocks', () => {
  const rows = taskRows([
    { index: 0, name: 'base', kind: 'periodic', period_us: 1000, blocks: 23 },
    { index: 1, name: 'encoder', kind: 'interrupt', interrupt: 'EXTI0', priority: 2, blocks: 3 },
    { index: 2, kind: 'periodic', period_us: 10000 },
  ]);
  assert.deepEqual(rows, [
    ['base', 'periodic', '1 ms', '23'],
    ['encoder', 'interrupt', 'EXTI0, priority 2', '3'],
    ['task 2', 'periodic', '10 ms', '—'],
  ]);
  assert.deepEqual(taskRows(undefined), []);
});
