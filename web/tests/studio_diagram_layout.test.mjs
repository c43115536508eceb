import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { buildScene, inport_prefix, outport_prefix, portPoint, undriven_prefix } from '../src/studio/diagram/scene.js';
import { elkGraph } from '../src/studio/diagram/elk_graph.js';
import { elkLayout } from '../src/studio/diagram/elk_layout.js';
import { keptLayout, placeNodes } from '../src/studio/diagram/kept_layout.js';
import { blockGeometry } from '../src/studio/diagram/block_geometry.js';
import { orthogonalRoute } from '../src/studio/diagram/routes.js';

const small = JSON.parse(readFileSync(new URL('./fixtures/studio/diagram_small.json', import.meta.url)));
const root = small.diagram.root;
const wake = root.blocks.find((block) => block.id === 'wake');

test('block geometry: inputs left and outputs right in order, trigger on top, room for every name', () => {
  const geometry = blockGeometry(wake, small.tasks);
  assert.deepEqual(geometry.ports.map((port) => [port.key, port.side]), [['in:count', 'WEST'], ['in:trigger', 'NORTH'], ['out:done', 'EAST']]);
  assert.equal(geometry.marking, '↑ rising: write_wake');
  const sum = blockGeometry(root.blocks.find((block) => block.id === 'sum'), small.tasks);
  const inputs = sum.ports.filter((port) => port.side === 'WEST');
  assert.deepEqual(inputs.map((port) => port.port), ['u1', 'u2', 'u3']);
  assert.ok(inputs[0].y < inputs[1].y && inputs[1].y < inputs[2].y);
  assert.ok(inputs[2].y < sum.height);
  const long = blockGeometry({ id: 'x', name: 'a_rather_long_block_name', type: 'Gain', inputs: [], outputs: [] }, []);
  assert.ok(long.width > 150);
});

test('the scene: one branch per target, system ports as markers, a "?" for an undriven wire, no edges for unused ones', () => {
  const scene = buildScene(root, small.tasks);
  const branches = scene.edges.filter((edge) => edge.wireId === ':init_count');
  assert.equal(branches.length, 3);
  assert.deepEqual(branches.map((edge) => edge.label), ['init_count', null, null]);
  assert.deepEqual(branches.map((edge) => edge.to.node), ['at_wake', 'wake', 'gain']);
  assert.equal(scene.edges.find((edge) => edge.wireId === ':write_wake').to.key, 'in:trigger');
  assert.ok(scene.nodes.has(`${undriven_prefix}:ghost`));
  assert.equal(scene.edges.find((edge) => edge.wireId === ':ghost').from.node, `${undriven_prefix}:ghost`);
  assert.deepEqual(scene.dangling.map((entry) => entry.wireId), [':requests_sent', ':total', ':filtered']);
  const inside = buildScene(wake.system, small.tasks);
  assert.equal(inside.edges.find((edge) => edge.wireId === 'wake:count').from.node, `${inport_prefix}count`);
  assert.equal(inside.edges.find((edge) => edge.wireId === 'wake:done').to.node, `${outport_prefix}done`);
});

test('a branch to a port the block does not have is left out', () => {
  const system = structuredClone(root);
  system.wires.find((wire) => wire.id === ':scaled').targets.push({ block: 'sum', port: 'no_such_port' });
  assert.equal(buildScene(system, small.tasks).edges.filter((edge) => edge.wireId === ':scaled').length, 2);
});

test('the ELK graph fixes port positions, keeps system ports at the edges, labels one branch per wire', () => {
  const graph = elkGraph(buildScene(wake.system, small.tasks));
  const inport = graph.children.find((child) => child.id === `${inport_prefix}count`);
  assert.equal(inport.layoutOptions['elk.layered.layering.layerConstraint'], 'FIRST');
  const flag = graph.children.find((child) => child.id === 'wake/flag');
  assert.equal(flag.layoutOptions['elk.portConstraints'], 'FIXED_POS');
  assert.deepEqual(flag.ports.map((port) => port.layoutOptions['elk.port.side']), ['WEST', 'EAST']);
  assert.equal(graph.layoutOptions['elk.algorithm'], 'layered');
  assert.equal(graph.layoutOptions['elk.edgeRouting'], 'ORTHOGONAL');
  const topGraph = elkGraph(buildScene(root, small.tasks));
  assert.equal(topGraph.edges.filter((edge) => edge.labels.length > 0).length, topGraph.edges.filter((edge) => edge.id.endsWith('#0')).length);
});

test('ELK lays out the top level: every node placed without overlap, wires from port to port, fan-out junction', async () => {
  const scene = buildScene(root, small.tasks);
  const layout = await elkLayout(scene);
  const boxes = [...scene.nodes.values()].map((node) => ({ id: node.id, ...layout.positions.get(node.id), width: node.geometry.width, height: node.geometry.height }));
  for (const box of boxes) assert.ok(Number.isFinite(box.x) && Number.isFinite(box.y), box.id);
  for (const a of boxes) for (const b of boxes) {
    if (a.id >= b.id) continue;
    const apart = a.x + a.width <= b.x || b.x + b.width <= a.x || a.y + a.height <= b.y || b.y + b.height <= a.y;
    assert.ok(apart, `${a.id} overlaps ${b.id}`);
  }
  const route = layout.routes.get(':init_count');
  assert.equal(route.branches.length, 3);
  const start = portPoint(scene.nodes.get('init_clock'), layout.positions.get('init_clock'), 'out:y');
  for (const branch of route.branches) assert.deepEqual([branch[0].x, branch[0].y], [start.x, start.y]);
  const end = portPoint(scene.nodes.get('gain'), layout.positions.get('gain'), 'in:u');
  assert.ok(route.branches.some((branch) => branch.at(-1).x === end.x && branch.at(-1).y === end.y));
  assert.ok(route.junctions.length >= 1);
  assert.ok(route.label.width > 0);
  assert.equal(layout.routes.get(':total').branches[0].length, 2);
  // Wire labels do not sit on blocks.
  for (const [wireId, { label }] of layout.routes) {
    if (!label) continue;
    for (const box of boxes) {
      const apart = label.x + label.width <= box.x || box.x + box.width <= label.x || label.y + label.height <= box.y || box.y + box.height <= label.y;
      assert.ok(apart, `label of ${wireId} lies on ${box.id}`);
    }
  }
});

test('after an edit, kept blocks stay put, a new one goes beside its neighbour, untouched wires keep their routes', async () => {
  const first = await elkLayout(buildScene(root, small.tasks));
  const edited = structuredClone(root);
  edited.blocks.push({ id: 'double', name: 'double', type: 'Gain', task: 0, inputs: [{ port: 'u', signal: 'total', kind: 'data' }], outputs: [{ port: 'y', signal: 'doubled', kind: 'data' }], parameters: [] });
  edited.wires.find((wire) => wire.id === ':total').targets.push({ block: 'double', port: 'u' });
  edited.wires.push({ id: ':doubled', signal: 'doubled', source: { block: 'double', port: 'y' }, targets: [] });
  const scene = buildScene(edited, small.tasks);
  const kept = keptLayout(scene, first);
  for (const [id, at] of first.positions) assert.deepEqual(kept.positions.get(id), at, id);
  const sum = first.positions.get('sum');
  const placed = kept.positions.get('double');
  assert.ok(placed.x > sum.x, 'the new block is right of what feeds it');
  assert.ok(Math.abs(placed.y - sum.y) < 400);
  assert.equal(kept.routes.get(':scaled'), first.routes.get(':scaled'), 'an untouched wire keeps its route');
  assert.notEqual(kept.routes.get(':total'), first.routes.get(':total'));
  const totalEnd = portPoint(scene.nodes.get('double'), placed, 'in:u');
  assert.deepEqual(kept.routes.get(':total').branches[0].at(-1), totalEnd);
});

test('a placed block never lands on another one', () => {
  const scene = buildScene(root, small.tasks);
  const positions = new Map([...scene.nodes.keys()].map((id, i) => [id, { x: 0, y: i * 200 }]));
  positions.delete('limit');
  const placed = placeNodes(scene, positions).get('limit');
  const limitHeight = scene.nodes.get('limit').geometry.height;
  for (const [id, at] of positions) {
    const other = scene.nodes.get(id).geometry;
    const apart = placed.x + 86 <= at.x || at.x + other.width <= placed.x || placed.y + limitHeight <= at.y || at.y + other.height <= placed.y;
    assert.ok(apart, `placed on ${id}`);
  }
});

test('plain routes: forward in three segments with a shared trunk, backward around below, trigger from above', () => {
  const route = orthogonalRoute({ x: 0, y: 0 }, [{ x: 100, y: 50, side: 'WEST' }, { x: -50, y: 10, side: 'WEST' }, { x: 200, y: 100, side: 'NORTH' }], 300, 'x');
  assert.equal(route.branches[0].length, 4);
  assert.ok(route.branches[1].some((point) => point.y === 300));
  assert.equal(route.branches[2].at(-2).y, 100 - 12);
  assert.deepEqual(route.junctions, [{ x: 12, y: 0 }]);
  // Every segment is horizontal or vertical.
  for (const branch of route.branches) for (let i = 1; i < branch.length; i += 1) {
    assert.ok(branch[i].x === branch[i - 1].x || branch[i].y === branch[i - 1].y);
  }
});
