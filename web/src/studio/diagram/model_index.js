// Lookups over a diagram (docs/STUDIO.md "diagram"): systems by path, blocks and wires by id,
// each with the path of the system that draws it.

export function parentPath(path) {
  const slash = path.lastIndexOf('/');
  return slash < 0 ? '' : path.slice(0, slash);
}

// A block's id is its path, so the system holding it is the id's parent.
export function systemOfBlock(blockId) {
  return parentPath(blockId);
}

export function indexDiagram(diagram) {
  const systems = new Map();
  const blocks = new Map();
  const wires = new Map();
  const visit = (system) => {
    systems.set(system.path, system);
    for (const block of system.blocks ?? []) {
      blocks.set(block.id, { block, system: system.path });
      if (block.system) visit(block.system);
    }
    for (const wire of system.wires ?? []) wires.set(wire.id, { wire, system: system.path });
  };
  if (diagram?.root) visit(diagram.root);
  const parameters = new Map((diagram?.parameters ?? []).map((parameter) => [parameter.name, parameter]));
  return { systems, blocks, wires, parameters };
}

// The system to show when `path` may have gone: itself, else its closest surviving ancestor.
export function nearestExistingSystem(index, path) {
  let candidate = path;
  while (candidate !== '' && !index.systems.has(candidate)) candidate = parentPath(candidate);
  return candidate;
}

// The levels from the top down to `path`, for the breadcrumb: [{path, name}].
export function systemTrail(diagram, path) {
  const trail = [{ path: '', name: diagram?.name || 'top' }];
  if (path === '') return trail;
  const names = path.split('/');
  names.forEach((name, depth) => trail.push({ path: names.slice(0, depth + 1).join('/'), name }));
  return trail;
}

// The selection object the view hands out for a wire: the wire's names travel with it.
export function wireSelection(entry) {
  const { wire, system } = entry;
  return { kind: 'wire', id: wire.id, system, signal: wire.signal, resolved: wire.resolved, measurement: wire.measurement };
}
