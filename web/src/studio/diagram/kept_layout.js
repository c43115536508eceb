import { danglingRoute, orthogonalRoute } from './routes.js';
import { portPoint } from './scene.js';

// Layout after an edit: every node that was drawn before stays where it was, a new one goes next
// to what it connects to, and only wires whose ends moved are routed anew (plainly, by
// routes.js); the rest keep ELK's routes. A full ELK layout is the caller's, on request.
const gap = 50;

// Where each wire's ends are, as a string: equal strings mean the old route still fits.
export function wireEndpoints(scene, positions) {
  const ends = new Map();
  const point = (end) => {
    const node = scene.nodes.get(end.node);
    const position = positions.get(end.node);
    return position ? portPoint(node, position, end.key) : null;
  };
  for (const edge of scene.edges) {
    const from = point(edge.from);
    const to = point(edge.to);
    if (!from || !to) continue;
    const entry = ends.get(edge.wireId) ?? { start: from, ends: [], label: edge.label ?? ends.get(edge.wireId)?.label };
    entry.ends.push(to);
    ends.set(edge.wireId, entry);
  }
  const signatures = new Map([...ends].map(([wireId, entry]) => [wireId, JSON.stringify([entry.start, ...entry.ends].map(({ x, y }) => [Math.round(x), Math.round(y)]))]));
  return { ends, signatures };
}

function overlaps(a, b) {
  return a.x < b.x + b.width + 20 && b.x < a.x + a.width + 20 && a.y < b.y + b.height + 20 && b.y < a.y + a.height + 20;
}

function neighbourPlace(node, scene, positions) {
  const sized = (id) => ({ ...positions.get(id), width: scene.nodes.get(id).geometry.width, height: scene.nodes.get(id).geometry.height });
  const feeding = scene.edges.filter((edge) => edge.to.node === node.id && positions.has(edge.from.node)).map((edge) => sized(edge.from.node));
  if (feeding.length > 0) return { x: Math.max(...feeding.map((box) => box.x + box.width)) + gap, y: feeding[0].y };
  const fed = scene.edges.filter((edge) => edge.from.node === node.id && positions.has(edge.to.node)).map((edge) => sized(edge.to.node));
  if (fed.length > 0) return { x: Math.min(...fed.map((box) => box.x)) - gap - node.geometry.width, y: fed[0].y };
  const boxes = [...positions.keys()].map(sized);
  return { x: Math.min(20, ...boxes.map((box) => box.x)), y: Math.max(0, ...boxes.map((box) => box.y + box.height)) + gap };
}

export function placeNodes(scene, previousPositions) {
  const positions = new Map();
  for (const id of scene.nodes.keys()) if (previousPositions.has(id)) positions.set(id, previousPositions.get(id));
  for (const node of scene.nodes.values()) {
    if (positions.has(node.id)) continue;
    const place = neighbourPlace(node, scene, positions);
    const box = { ...place, width: node.geometry.width, height: node.geometry.height };
    // Step down past whatever is already there.
    for (let attempt = 0; attempt < 200; attempt += 1) {
      const blocking = [...positions].find(([id, at]) => overlaps(box, { ...at, width: scene.nodes.get(id).geometry.width, height: scene.nodes.get(id).geometry.height }));
      if (!blocking) break;
      box.y = blocking[1].y + scene.nodes.get(blocking[0]).geometry.height + 24;
    }
    positions.set(node.id, { x: box.x, y: box.y });
  }
  return positions;
}

export function keptLayout(scene, previous) {
  const positions = placeNodes(scene, previous.positions);
  const { ends, signatures } = wireEndpoints(scene, positions);
  const floor = Math.max(0, ...[...positions].map(([id, at]) => at.y + scene.nodes.get(id).geometry.height)) + 16;
  const routes = new Map();
  for (const [wireId, entry] of ends) {
    const unchanged = previous.signatures?.get(wireId) === signatures.get(wireId) && previous.routes.has(wireId);
    routes.set(wireId, unchanged ? previous.routes.get(wireId) : orthogonalRoute(entry.start, entry.ends, floor, entry.label));
  }
  for (const dangling of scene.dangling) {
    const node = scene.nodes.get(dangling.from.node);
    routes.set(dangling.wireId, danglingRoute(portPoint(node, positions.get(node.id), dangling.from.key), dangling.label));
  }
  return { positions, routes, signatures, ...extent(scene, positions, routes) };
}

// The drawing's box: every node and every route point.
export function extent(scene, positions, routes) {
  let left = Infinity; let top = Infinity; let right = -Infinity; let bottom = -Infinity;
  const cover = (x, y) => { left = Math.min(left, x); top = Math.min(top, y); right = Math.max(right, x); bottom = Math.max(bottom, y); };
  for (const [id, at] of positions) {
    const { width, height } = scene.nodes.get(id).geometry;
    cover(at.x, at.y);
    cover(at.x + width, at.y + height);
  }
  for (const route of routes.values()) {
    for (const branch of route.branches) for (const point of branch) cover(point.x, point.y);
    if (route.label) cover(route.label.x + route.label.width, route.label.y + route.label.height + 14);
  }
  if (left === Infinity) return { box: { x: 0, y: 0, width: 0, height: 0 } };
  return { box: { x: left, y: top, width: right - left, height: bottom - top } };
}
