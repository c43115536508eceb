import { wireSelection } from './model_index.js';

// The first block or signal whose name matches `text`, anywhere in the model: an exact name
// before a part of one, a block before a signal, shallower systems before deeper ones.
export function findInModel(index, text) {
  const wanted = text.trim().toLowerCase();
  if (!wanted) return null;
  const depth = (path) => (path === '' ? 0 : path.split('/').length);
  const candidates = [];
  for (const [id, entry] of index.blocks) {
    candidates.push({ name: entry.block.name, rank: 0, depth: depth(entry.system), selection: { kind: 'block', id } });
  }
  for (const entry of index.wires.values()) {
    const names = [entry.wire.signal, entry.wire.resolved].filter(Boolean);
    candidates.push({ names, rank: 1, depth: depth(entry.system), selection: wireSelection(entry) });
  }
  const matches = (candidate, exact) => (candidate.names ?? [candidate.name]).some((name) => {
    const lower = name.toLowerCase();
    return exact ? lower === wanted : lower.includes(wanted);
  });
  const order = (a, b) => a.rank - b.rank || a.depth - b.depth;
  for (const exact of [true, false]) {
    const found = candidates.filter((candidate) => matches(candidate, exact)).sort(order);
    if (found.length > 0) return found[0].selection;
  }
  return null;
}
