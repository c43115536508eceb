import { test } from 'node:test';
import assert from 'node:assert/strict';
import { MockRecorder } from './mock/recorder.mjs';

test('the mock recorder triggers on the edge and captures pre and post samples', () => {
  const recorder = new MockRecorder(['x'], 1000);
  assert.equal(recorder.arm({ signal: 'x', level: 0.5, edge: 'rising', pre_s: 0.1, post_s: 0.2 }), '');
  const events = [];
  for (let i = 0; i < 100; i += 1) {
    const event = recorder.add(i / 100, [i >= 50 ? 1 : 0]);
    if (event) events.push(event);
  }
  assert.equal(events[0], 'triggered');
  const capture = events[1];
  assert.equal(capture.type, 'capture');
  assert.equal(capture.trigger_time_s, 0.5);
  assert.ok(Math.abs(capture.time_s[0] - 0.4) < 1e-9);
  assert.ok(capture.time_s[capture.time_s.length - 1] >= 0.7);
  assert.match(recorder.arm({ signal: 'y', level: 0, edge: 'rising', pre_s: 0, post_s: 0 }), /no signal/);
});
