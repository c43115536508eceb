import ELK from 'elkjs/lib/elk.bundled.js';
import { elkGraph } from './elk_graph.js';
import { danglingRoute } from './routes.js';
import { portPoint } from './scene.js';
import { extent, wireEndpoints } from './kept_layout.js';

// Runs ELK on a scene and returns the layout the drawing uses:
// {positions: Map nodeId -> {x, y}, routes: Map wireId -> {branches, junctions, label}, signatures
// (where each wire's ends are, for kept_layout.js), box (the drawing's extent)}.
let elk = null;

export async function elkLayout(scene) {
  elk ??= new ELK();
  const result = await elk.layout(elkGraph(scene));
  const positions = new Map(result.children.map((child) => [child.id, { x: child.x, y: child.y }]));
  const routes = new Map();
  const edgesById = new Map(scene.edges.map((edge) => [edge.id, edge]));
  for (const elkEdge of result.edges) {
    const edge = edgesById.get(elkEdge.id);
    const route = routes.get(edge.wireId) ?? { branches: [], junctions: [], label: null };
    routes.set(edge.wireId, route);
    for (const section of elkEdge.sections ?? []) route.branches.push([section.startPoint, ...(section.bendPoints ?? []), section.endPoint]);
    for (const point of elkEdge.junctionPoints ?? []) {
      if (!route.junctions.some((known) => known.x === point.x && known.y === point.y)) route.junctions.push(point);
    }
    const label = elkEdge.labels?.[0];
    if (label) route.label = { x: label.x, y: label.y, width: label.width, height: label.height };
  }
  for (const dangling of scene.dangling) {
    const node = scene.nodes.get(dangling.from.node);
    routes.set(dangling.wireId, danglingRoute(portPoint(node, positions.get(node.id), dangling.from.key), dangling.label));
  }
  return { positions, routes, signatures: wireEndpoints(scene, positions).signatures, ...extent(scene, positions, routes) };
}
