import { blockGeometry, portKey, systemPortGeometry, undrivenStubGeometry } from './block_geometry.js';

// One system as things to place (blocks, the system's port markers, "?" stubs) and the
// connections between their ports: one branch per target of each Wire. Independent of ELK, so
// both the automatic layout and the kept positions work from it.
export const inport_prefix = '@in:';
export const outport_prefix = '@out:';
export const undriven_prefix = '@undriven:';

export function buildScene(system, tasks) {
  const nodes = new Map();
  for (const block of system.blocks ?? []) nodes.set(block.id, { id: block.id, kind: 'block', block, geometry: blockGeometry(block, tasks) });
  for (const { port } of system.inputs ?? []) nodes.set(inport_prefix + port, { id: inport_prefix + port, kind: 'inport', port, geometry: systemPortGeometry('input', port) });
  for (const { port } of system.outputs ?? []) nodes.set(outport_prefix + port, { id: outport_prefix + port, kind: 'outport', port, geometry: systemPortGeometry('output', port) });

  // An end only counts when its node and port exist: a wire naming a port the block lacks is
  // the checker's to report, the drawing just leaves that branch out.
  const end = (nodeId, key) => {
    const node = nodes.get(nodeId);
    return node && node.geometry.ports.some((port) => port.key === key) ? { node: nodeId, key } : null;
  };
  const sourceEnd = (wire) => {
    if (wire.source?.block !== undefined) return end(wire.source.block, portKey('out', wire.source.port));
    if (wire.source?.system_input !== undefined) return end(inport_prefix + wire.source.system_input, portKey('out', wire.source.system_input));
    const stub = { id: undriven_prefix + wire.id, kind: 'undriven', wireId: wire.id, geometry: undrivenStubGeometry() };
    nodes.set(stub.id, stub);
    return { node: stub.id, key: 'out:?' };
  };
  const targetEnd = (target) => {
    if (target.block !== undefined) return end(target.block, portKey('in', target.port));
    if (target.system_output !== undefined) return end(outport_prefix + target.system_output, portKey('in', target.system_output));
    return null;
  };

  const edges = [];
  const dangling = [];
  for (const wire of system.wires ?? []) {
    const from = sourceEnd(wire);
    if (!from) continue;
    const ends = (wire.targets ?? []).map(targetEnd).filter(Boolean);
    if (ends.length === 0) dangling.push({ wireId: wire.id, from, label: wire.signal });
    ends.forEach((to, branch) => edges.push({ id: `${wire.id}#${branch}`, wireId: wire.id, branch, from, to, label: branch === 0 ? wire.signal : null }));
  }
  return { nodes, edges, dangling, wires: new Map((system.wires ?? []).map((wire) => [wire.id, wire])) };
}

// Where a port is in the drawing, given its node's top-left corner.
export function portPoint(node, position, key) {
  const port = node.geometry.ports.find((candidate) => candidate.key === key);
  return { x: position.x + port.x, y: position.y + port.y, side: port.side };
}
