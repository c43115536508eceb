import { textWidth } from './text_width.js';
import { label_font } from './elk_graph.js';

// Wire routes ELK does not draw: a wire that goes nowhere, and (for positions kept across edits)
// plain orthogonal routes between ports.
const stub_length = 24;
const clearance = 12;

// A short line out of the source with the name above it: the signal exists, nothing reads it.
export function danglingRoute(start, label) {
  return {
    branches: [[{ x: start.x, y: start.y }, { x: start.x + stub_length, y: start.y }]],
    junctions: [],
    label: { x: start.x + 4, y: start.y - 15, width: textWidth(label, label_font) + 4, height: 13 },
  };
}

// A wire from `start` (an east-facing output) to each of `ends` (west- or north-facing inputs):
// one vertical trunk just right of the source, a branch off it to each end, going around below
// `floor` when the end lies behind the source.
export function orthogonalRoute(start, ends, floor, label) {
  const trunkX = start.x + clearance;
  const branches = ends.map((end) => {
    if (end.side === 'NORTH') {
      const above = end.y - clearance;
      return [start, { x: trunkX, y: start.y }, { x: trunkX, y: above }, { x: end.x, y: above }, end];
    }
    if (end.x - clearance > trunkX) return [start, { x: trunkX, y: start.y }, { x: trunkX, y: end.y }, end];
    const behind = end.x - clearance;
    return [start, { x: trunkX, y: start.y }, { x: trunkX, y: floor }, { x: behind, y: floor }, { x: behind, y: end.y }, end];
  });
  const junctions = ends.length > 1 ? [{ x: trunkX, y: start.y }] : [];
  const labelBox = label ? { x: start.x + 2, y: start.y - 15, width: textWidth(label, label_font) + 4, height: 13 } : null;
  return { branches, junctions, label: labelBox };
}
