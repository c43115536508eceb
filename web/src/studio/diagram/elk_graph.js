import { textWidth } from './text_width.js';
import { inport_prefix, outport_prefix, undriven_prefix } from './scene.js';

// A scene as ELK's JSON graph: layered left to right, orthogonal wires, the ports exactly where
// the drawing has them (FIXED_POS, which keeps their order too), wire names as edge labels.
export const label_font = 10;
const label_height = 13;

export const layout_options = {
  'elk.algorithm': 'layered',
  'elk.direction': 'RIGHT',
  'elk.edgeRouting': 'ORTHOGONAL',
  'elk.spacing.nodeNode': '28',
  'elk.layered.spacing.nodeNodeBetweenLayers': '40',
  'elk.spacing.edgeNode': '14',
  'elk.spacing.edgeEdge': '8',
  'elk.layered.spacing.edgeNodeBetweenLayers': '14',
  'elk.spacing.edgeLabel': '2',
  'elk.edgeLabels.placement': 'CENTER',
  'elk.layered.edgeLabels.sideSelection': 'ALWAYS_UP',
  'elk.layered.nodePlacement.strategy': 'BRANDES_KOEPF',
  // Fewer crossing-minimisation sweeps than the default 7: a quarter less time on the robot's
  // top level (100 blocks) for a drawing that looks the same.
  'elk.layered.thoroughness': '3',
  'elk.layered.crossingMinimization.strategy': 'LAYER_SWEEP',
  'elk.layered.considerModelOrder.strategy': 'NODES_AND_EDGES',
  'elk.padding': '[top=20,left=20,bottom=20,right=20]',
};

export function elkPortId(nodeId, key) {
  return `${nodeId}|${key}`;
}

function layerConstraint(node) {
  if (node.id.startsWith(inport_prefix)) return 'FIRST';
  if (node.id.startsWith(outport_prefix)) return 'LAST';
  if (node.id.startsWith(undriven_prefix)) return 'FIRST';
  return undefined;
}

export function elkGraph(scene) {
  const children = [...scene.nodes.values()].map((node) => {
    const layoutOptions = { 'elk.portConstraints': 'FIXED_POS' };
    const constraint = layerConstraint(node);
    if (constraint) layoutOptions['elk.layered.layering.layerConstraint'] = constraint;
    return {
      id: node.id,
      width: node.geometry.width,
      height: node.geometry.height,
      layoutOptions,
      ports: node.geometry.ports.map((port) => ({
        id: elkPortId(node.id, port.key), x: port.x, y: port.y, width: 0, height: 0,
        layoutOptions: { 'elk.port.side': port.side },
      })),
    };
  });
  const edges = scene.edges.map((edge) => ({
    id: edge.id,
    sources: [elkPortId(edge.from.node, edge.from.key)],
    targets: [elkPortId(edge.to.node, edge.to.key)],
    labels: edge.label ? [{ text: edge.label, width: textWidth(edge.label, label_font) + 4, height: label_height }] : [],
  }));
  return { id: 'system', layoutOptions: { ...layout_options }, children, edges };
}
