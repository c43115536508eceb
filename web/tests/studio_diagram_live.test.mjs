import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createLiveLabels } from '../src/studio/diagram/live_labels.js';

// Stand-ins for the drawing's <text class="live-value"> elements, counting text writes.
function fakeDrawing(names) {
  const labels = names.map((name) => {
    const label = { dataset: { measurement: name }, writes: 0, text: '' };
    Object.defineProperty(label, 'textContent', { get: () => label.text, set: (value) => { label.text = value; label.writes += 1; } });
    return label;
  });
  return { labels, root: { querySelectorAll: () => labels } };
}

function manualFrames() {
  const queue = [];
  return { request: (callback) => queue.push(callback), run: () => queue.splice(0).forEach((callback) => callback()), pending: () => queue.length };
}

test('live values: many updates between frames cost one write of the newest', () => {
  const frames = manualFrames();
  const live = createLiveLabels(frames.request);
  const { labels, root } = fakeDrawing(['theta', 'theta', 'speed']);
  live.attach(root);
  live.setEnabled(true);
  for (let i = 0; i < 50; i += 1) live.setValues(new Map([['theta', i], ['speed', [1, 2, 3, 4]]]));
  assert.equal(frames.pending(), 1, 'one frame requested, not fifty');
  frames.run();
  assert.deepEqual(labels.map((label) => label.text), ['49', '49', '[1, 2, 3, …] (4)']);
  assert.deepEqual(labels.map((label) => label.writes), [1, 1, 1]);
  // The same text again is not written again.
  live.setValues(new Map([['theta', 49], ['speed', [1, 2, 3, 4]]]));
  frames.run();
  assert.deepEqual(labels.map((label) => label.writes), [1, 1, 1]);
});

test('live values: nothing is written while live mode is off; turning it on shows the newest', () => {
  const frames = manualFrames();
  const live = createLiveLabels(frames.request);
  const { labels, root } = fakeDrawing(['y']);
  live.attach(root);
  live.setValues(new Map([['y', 0.5]]));
  assert.equal(frames.pending(), 0);
  live.setEnabled(true);
  frames.run();
  assert.equal(labels[0].text, '0.5');
});

test('live values: a new drawing gets the current values at once', () => {
  const frames = manualFrames();
  const live = createLiveLabels(frames.request);
  live.setEnabled(true);
  live.setValues(new Map([['y', 2]]));
  frames.run();
  const { labels, root } = fakeDrawing(['y']);
  live.attach(root);
  frames.run();
  assert.equal(labels[0].text, '2');
});
