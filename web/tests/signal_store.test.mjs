import { test } from 'node:test';
import assert from 'node:assert/strict';
import { SignalStore, capacityFor } from '../src/signal_store.js';

const description = {
  telemetry_period_us: 10000,
  telemetry: [
    { name: 'theta', unit: 'deg' },
    { name: 'battery', unit: 'V' },
  ],
};

test('capacity is 20 s at the signal rate, at least 20000 points, bounded', () => {
  assert.equal(capacityFor(10000), 20000);
  assert.equal(capacityFor(1000), 20000);
  assert.equal(capacityFor(100), 200000);
  assert.equal(capacityFor(1), 400000);
  assert.equal(capacityFor(0), 20000);
});

test('a telemetry message is one sample at sample number times the period', () => {
  const store = new SignalStore(description);
  assert.equal(store.addTelemetry({ sample: 812, values: [-0.3, 7.4] }), 1);
  assert.ok(Math.abs(store.time.last() - 8.12) < 1e-12);
  assert.deepEqual([...store.values[0].view()], [-0.3]);
  assert.deepEqual([...store.values[1].view()], [7.4]);
});

test('a samples block adds every sample of every signal', () => {
  const store = new SignalStore(description);
  const added = store.addSamples({ time_s: [1, 1.001, 1.002], values: [[1, 2, 3], [7, 7.1, 7.2]] });
  assert.equal(added, 3);
  assert.deepEqual([...store.time.view()], [1, 1.001, 1.002]);
  assert.deepEqual([...store.values[1].view()], [7, 7.1, 7.2]);
});

test('missing values become NaN gaps, not zeros', () => {
  const store = new SignalStore(description);
  store.addSamples({ time_s: [1], values: [[null]] });
  assert.ok(Number.isNaN(store.values[0].last()));
  assert.ok(Number.isNaN(store.values[1].last()));
});

test('time going back (a restarted target) starts the history afresh', () => {
  const store = new SignalStore(description);
  store.addSamples({ time_s: [5, 6], values: [[1, 2], [3, 4]] });
  store.addSamples({ time_s: [0.5], values: [[9], [9]] });
  assert.deepEqual([...store.time.view()], [0.5]);
  assert.deepEqual([...store.values[0].view()], [9]);
});

test('malformed blocks are ignored', () => {
  const store = new SignalStore(description);
  assert.equal(store.addSamples({ time_s: 'x' }), 0);
  assert.equal(store.addTelemetry({ sample: 1 }), 0);
  assert.equal(store.time.length, 0);
});
