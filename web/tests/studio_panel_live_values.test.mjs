import { test } from 'node:test';
import assert from 'node:assert/strict';
import { SignalStore } from '../src/signal_store.js';
import { EventHub } from '../src/event_hub.js';
import { connectSignalFeed } from '../src/signal_feed.js';
import { baseName, groupItems, itemsNamed, splitItemName } from '../src/studio/panels/vector_items.js';
import { LiveValues } from '../src/studio/panels/live_values.js';

test('an item name splits into the measurement and its indices', () => {
  assert.deepEqual(splitItemName('theta'), { base: 'theta', indices: [] });
  assert.deepEqual(splitItemName('linux_gains[1]'), { base: 'linux_gains', indices: [1] });
  assert.deepEqual(splitItemName('m[2][10]'), { base: 'm', indices: [2, 10] });
  assert.equal(baseName('a.b[3]'), 'a.b');
  // Not an index: stays part of the name.
  assert.equal(baseName('odd[x]'), 'odd[x]');
  assert.equal(baseName('[3]'), '[3]');
});

test('items group by measurement in first-seen order, elements by their index', () => {
  const groups = groupItems(['theta', 'gains[1]', 'gains[0]', 'y', 'm[1][0]', 'm[0][1]', 'm[0][0]', 'gains[2]']);
  assert.deepEqual(groups, [
    { name: 'theta', vector: false, positions: [0] },
    { name: 'gains', vector: true, positions: [2, 1, 7] },
    { name: 'y', vector: false, positions: [3] },
    { name: 'm', vector: true, positions: [6, 5, 4] },
  ]);
});

test('a name finds the scalar itself or every element of the vector', () => {
  const items = ['theta', 'gains[0]', 'gains[1]', 'gains_limit'].map((name) => ({ name }));
  assert.deepEqual(itemsNamed(items, 'gains').map((item) => item.name), ['gains[0]', 'gains[1]']);
  assert.deepEqual(itemsNamed(items, 'theta').map((item) => item.name), ['theta']);
  assert.deepEqual(itemsNamed(items, 'gains[1]').map((item) => item.name), ['gains[1]']);
  assert.deepEqual(itemsNamed(items, 'nothing'), []);
});

const description = {
  telemetry_period_us: 1000,
  telemetry: [{ name: 'theta', unit: 'deg' }, { name: 'gains[0]' }, { name: 'gains[1]' }, { name: 'y' }],
};

test('the live values are the newest sample of each measurement, vectors as arrays', () => {
  const store = new SignalStore(description);
  const live = new LiveValues(store);
  assert.deepEqual(live.read(), new Map());
  store.addSamples({ time_s: [0.001, 0.002], values: [[1, 2], [10, 11], [20, 21], [5, 6]] });
  assert.deepEqual(live.read(), new Map([['theta', 2], ['gains', [11, 21]], ['y', 6]]));
});

test('a sample missing from a block reads as NaN, not as the value before', () => {
  const store = new SignalStore(description);
  const live = new LiveValues(store);
  store.addSamples({ time_s: [0.001], values: [[1], [10], [20], [5]] });
  store.addSamples({ time_s: [0.002], values: [[null], [10], [20], [5]] });
  assert.ok(Number.isNaN(live.read().get('theta')));
});

test('through the dashboard feed: a description, then samples blocks, counted', () => {
  const hub = new EventHub();
  const stats = { samples: 0 };
  let live = null;
  connectSignalFeed(hub, stats);
  hub.on('store', (store) => (live = new LiveValues(store)));
  hub.emit('description', description);
  hub.emit('samples', { time_s: [0.001, 0.002, 0.003], values: [[1, 2, 3], [0, 0, 7], [0, 0, 8], [0, 0, 9]] });
  assert.equal(stats.samples, 3);
  assert.deepEqual(live.read(), new Map([['theta', 3], ['gains', [7, 8]], ['y', 9]]));
});
