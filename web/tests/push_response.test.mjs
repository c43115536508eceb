import { test } from 'node:test';
import assert from 'node:assert/strict';
import { responseToPush } from './push_response.mjs';

// A damped swing sampled at 100 Hz: rest at 0.2 degrees, pushed at 1 s, 3 degrees at most, 2 Hz, decaying in 0.4 s.
const swing = [];
for (let k = 0; k < 400; k += 1) {
  const time = k / 100;
  const since = time - 1;
  const value = 0.2 + (since >= 0 ? 3 * Math.exp(-since / 0.4) * Math.sin(2 * Math.PI * 2 * since) : 0);
  swing.push([time, value]);
}

test('the response to a push: how far, how long, how often it swings through its rest', () => {
  const response = responseToPush(swing, 1, 2);
  assert.equal(response.samples, 201);
  assert.ok(Math.abs(response.rest_deg - 0.2) < 1e-12);
  assert.ok(response.peak_deg > 2 && response.peak_deg < 3, `peak ${response.peak_deg}`);
  // exp(-t/0.4) 3 > 0.5 until t = 0.4 ln 6 = 0.72 s: the last excursion beyond 0.5 degrees ends before that.
  assert.ok(response.settling_s > 0.5 && response.settling_s < 0.72, `settling ${response.settling_s}`);
  assert.ok(response.crossings >= 3 && response.crossings <= 8, `crossings ${response.crossings}`);
});

test('no samples after the push: nothing moved', () => {
  assert.deepEqual(responseToPush(swing, 10, 1), { samples: 0, rest_deg: 0, peak_deg: 0, settling_s: 0, crossings: 0 });
});
