import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Decimator, lowerBound } from '../src/decimate.js';

const ramp = (n, step = 0.001) => Float64Array.from({ length: n }, (_, i) => i * step);

test('lowerBound finds the first value at or above', () => {
  const sorted = Float64Array.of(1, 2, 2, 3);
  assert.equal(lowerBound(sorted, 0), 0);
  assert.equal(lowerBound(sorted, 2), 1);
  assert.equal(lowerBound(sorted, 2.5), 3);
  assert.equal(lowerBound(sorted, 9), 4);
});

test('few samples pass through unchanged, with one sample either side of the window', () => {
  const time = ramp(10, 1);
  const values = Float64Array.from(time, (t) => t * 10);
  const [x, y] = new Decimator().decimate(time, [values], 3, 6, 100);
  assert.deepEqual([...x], [2, 3, 4, 5, 6, 7]);
  assert.deepEqual([...y], [20, 30, 40, 50, 60, 70]);
});

test('many samples shrink to about two points per column and keep a one-sample spike', () => {
  const time = ramp(100000); // 100 s at 1 kHz
  const values = new Float64Array(time.length);
  values[54321] = 1000; // a single-sample spike
  values[54322] = -5;
  const [x, y] = new Decimator().decimate(time, [values], 0, 100, 500);
  assert.ok(x.length <= 2 * 502 + 1, `${x.length} points`);
  assert.equal(x.length, y.length);
  assert.equal(Math.max(...y), 1000);
  assert.equal(Math.min(...y), -5);
  for (let i = 1; i < x.length; i += 1) assert.ok(x[i] >= x[i - 1], 'x stays sorted');
});

test('min and max are emitted in the order they occurred', () => {
  const time = ramp(1000);
  const falling = Float64Array.from(time, (t) => -t);
  const [, y] = new Decimator().decimate(time, [falling], 0, 1, 10);
  for (let i = 1; i < y.length; i += 1) assert.ok(y[i] <= y[i - 1], 'a falling line stays falling');
});

test('the newest sample ends the line with its own value', () => {
  const time = ramp(10000);
  const values = Float64Array.from(time, (_, i) => (i % 2 === 0 ? 1 : -1));
  const [x, y] = new Decimator().decimate(time, [values], 0, time[time.length - 1], 100);
  assert.equal(x[x.length - 1], time[time.length - 1]);
  assert.equal(y[y.length - 1], values[values.length - 1]);
});

test('signals share the x array', () => {
  const time = ramp(5000);
  const a = Float64Array.from(time, Math.sin);
  const b = Float64Array.from(time, Math.cos);
  const data = new Decimator().decimate(time, [a, b], 1, 4, 50);
  assert.equal(data.length, 3);
  assert.equal(data[1].length, data[0].length);
  assert.equal(data[2].length, data[0].length);
});

test('an empty window or no data gives no points', () => {
  const decimator = new Decimator();
  const [x] = decimator.decimate(new Float64Array(0), [new Float64Array(0)], 0, 1, 100);
  assert.equal(x.length, 0);
});
