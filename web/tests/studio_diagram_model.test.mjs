import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { indexDiagram, nearestExistingSystem, parentPath, systemTrail } from '../src/studio/diagram/model_index.js';
import { findInModel } from '../src/studio/diagram/find.js';
import { markersInSystem, worstSeverity } from '../src/studio/diagram/markers.js';
import { describeBlock } from '../src/studio/diagram/block_description.js';

const small = JSON.parse(readFileSync(new URL('./fixtures/studio/diagram_small.json', import.meta.url)));
const index = indexDiagram(small.diagram);

test('the index finds systems, blocks and wires with the system drawing them', () => {
  assert.deepEqual([...index.systems.keys()], ['', 'wake', 'data_ready', 'filter']);
  assert.equal(index.blocks.get('wake/flag').system, 'wake');
  assert.equal(index.wires.get('wake:count').system, 'wake');
  assert.equal(index.wires.get(':scaled').system, '');
  assert.equal(parentPath('a/b/c'), 'a/b');
  assert.equal(parentPath('a'), '');
});

test('a system that went is replaced by its nearest surviving parent', () => {
  assert.equal(nearestExistingSystem(index, 'wake'), 'wake');
  assert.equal(nearestExistingSystem(index, 'wake/gone/deeper'), 'wake');
  assert.equal(nearestExistingSystem(index, 'gone'), '');
});

test('the breadcrumb trail names each level from the top', () => {
  assert.deepEqual(systemTrail(small.diagram, 'a/b'), [{ path: '', name: 'small' }, { path: 'a', name: 'a' }, { path: 'a/b', name: 'b' }]);
});

test('find: exact names before parts, blocks before signals, shallow before deep', () => {
  assert.deepEqual(findInModel(index, 'sum'), { kind: 'block', id: 'sum' });
  assert.deepEqual(findInModel(index, 'FLAG'), { kind: 'block', id: 'wake/flag' });
  const wire = findInModel(index, 'scaled');
  assert.equal(wire.kind, 'wire');
  assert.equal(wire.id, ':scaled');
  assert.equal(wire.measurement, 'scaled');
  // "count" is exactly wake's signal; as a part it would first hit init_count at the top.
  assert.equal(findInModel(index, 'count').id, 'wake:count');
  assert.equal(findInModel(index, 'ready').id, 'data_ready');
  assert.equal(findInModel(index, 'nothing like it'), null);
  assert.equal(findInModel(index, '  '), null);
});

test('markers: on the block in its system, and on the closed subsystem box above it', () => {
  const markers = new Map([
    ['sum', [{ severity: 'warning', message: 'w' }]],
    ['wake/bytes', [{ severity: 'error', message: 'bad bytes' }]],
  ]);
  const top = markersInSystem(markers, '');
  assert.deepEqual([...top.keys()].sort(), ['sum', 'wake']);
  assert.equal(top.get('wake')[0].message, 'bytes: bad bytes');
  assert.equal(worstSeverity(top.get('wake')), 'error');
  assert.equal(worstSeverity(top.get('sum')), 'warning');
  const inside = markersInSystem(markers, 'wake');
  assert.deepEqual([...inside.keys()], ['wake/bytes']);
  assert.equal(inside.get('wake/bytes')[0].message, 'bad bytes');
  assert.equal(markersInSystem(markers, 'filter').size, 0);
});

test('a block description joins its arguments, the model parameter they name and the library', () => {
  const library = new Map(small.library.map((entry) => [entry.type, entry]));
  const gain = describeBlock(index.blocks.get('gain').block, library.get('Gain'), index.parameters);
  assert.equal(gain.summary, 'Multiplies its input by k.');
  assert.equal(gain.parameters[0].text, 'P');
  assert.match(gain.parameters[0].model, /^P = 0\.0196 1\/deg in -1 … 1 — proportional gain$/);
  assert.match(gain.parameters[0].documentation, /the gain \(number/);
  const compare = describeBlock(index.blocks.get('at_wake').block, library.get('Compare'), index.parameters);
  assert.match(compare.parameters[0].documentation, /one of ==, !=/);
  const constant = describeBlock(index.blocks.get('offset').block, library.get('Constant'), index.parameters);
  assert.deepEqual(constant.unset.map((parameter) => parameter.name), ['type']);
  assert.equal(describeBlock(index.blocks.get('sum').block, undefined, index.parameters).summary, '');
});
