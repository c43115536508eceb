import { drawBlock, drawSystemPort, drawUndrivenStub } from './draw_block.js';
import { drawWire } from './draw_wire.js';
import { svgElement } from './svg.js';

// The whole shown system: wires under blocks (a wire never hides a block's name), each element
// findable by its id afterwards. Returns {root, blocks: Map id -> g, wires: Map id -> g}.
export function drawScene(scene, layout, colourOf) {
  const blocks = new Map();
  const wires = new Map();
  const wireLayer = svgElement('g', { class: 'wires' });
  const blockLayer = svgElement('g', { class: 'blocks' });
  for (const [wireId, route] of layout.routes) {
    const group = drawWire(scene.wires.get(wireId), route);
    wires.set(wireId, group);
    wireLayer.append(group);
  }
  for (const node of scene.nodes.values()) {
    const position = layout.positions.get(node.id);
    if (!position) continue;
    if (node.kind === 'block') {
      const group = drawBlock(node.block, node.geometry, position, colourOf(node.block.task));
      blocks.set(node.id, group);
      blockLayer.append(group);
    } else if (node.kind === 'undriven') blockLayer.append(drawUndrivenStub(node, position));
    else blockLayer.append(drawSystemPort(node, position));
  }
  return { root: svgElement('g', { class: 'scene' }, wireLayer, blockLayer), blocks, wires };
}
