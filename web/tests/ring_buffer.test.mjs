import { test } from 'node:test';
import assert from 'node:assert/strict';
import { RingBuffer } from '../src/ring_buffer.js';

test('holds values oldest first until full', () => {
  const ring = new RingBuffer(4);
  assert.deepEqual([...ring.view()], []);
  assert.equal(ring.last(), undefined);
  for (const value of [1, 2, 3]) ring.push(value);
  assert.deepEqual([...ring.view()], [1, 2, 3]);
  assert.equal(ring.last(), 3);
});

test('overwrites the oldest and still reads as one contiguous view', () => {
  const ring = new RingBuffer(4);
  for (let value = 1; value <= 10; value += 1) {
    ring.push(value);
    const expected = Array.from({ length: Math.min(value, 4) }, (_, i) => value - Math.min(value, 4) + 1 + i);
    assert.deepEqual([...ring.view()], expected, `after pushing ${value}`);
    assert.equal(ring.last(), value);
  }
  assert.equal(ring.length, 4);
  assert.equal(ring.data.length, 8, 'never grows');
});

test('clear empties it', () => {
  const ring = new RingBuffer(3);
  ring.push(1);
  ring.clear();
  assert.equal(ring.view().length, 0);
  ring.push(5);
  assert.deepEqual([...ring.view()], [5]);
});

test('rejects a capacity that is not positive', () => {
  assert.throws(() => new RingBuffer(0), RangeError);
});
