import { svgElement } from './svg.js';

// One block as SVG, in its own coordinates (the caller places it): the box in its task's colour,
// name, type, what starts a subsystem, and the named ports.
const port_mark = 5;

function portShape(port) {
  if (port.side === 'WEST') return `M${port.x},${port.y - port_mark}L${port.x + port_mark},${port.y}L${port.x},${port.y + port_mark}Z`;
  if (port.side === 'EAST') return `M${port.x - port_mark},${port.y - port_mark}L${port.x},${port.y}L${port.x - port_mark},${port.y + port_mark}Z`;
  return `M${port.x - port_mark},${port.y}L${port.x},${port.y + port_mark}L${port.x + port_mark},${port.y}Z`;
}

function portLabel(port) {
  if (port.side === 'NORTH') return null; // the marking line names a trigger or enable port
  const west = port.side === 'WEST';
  return svgElement('text', { class: 'port-label', x: west ? port.x + 7 : port.x - 7, y: port.y + 3.5, 'text-anchor': west ? 'start' : 'end' }, port.port);
}

function portGroup(port) {
  return svgElement('g', { class: `port port-${port.kind}`, 'data-port': port.key },
    svgElement('path', { class: 'port-mark', d: portShape(port) }),
    // A generous invisible target, so starting a connection does not need pixel precision.
    svgElement('circle', { class: 'port-hit', cx: port.x, cy: port.y, r: 8 }),
    portLabel(port));
}

export function drawBlock(block, geometry, position, colour) {
  const { width, height, marking } = geometry;
  const textX = geometry.isSubsystem ? (width - 18) / 2 : width / 2;
  const group = svgElement('g', {
    class: `block${geometry.isSubsystem ? ' subsystem' : ''}`,
    'data-id': block.id,
    transform: `translate(${position.x},${position.y})`,
    style: `--task-colour:${colour}`,
  },
  svgElement('rect', { class: 'block-box', width, height, rx: 4 }),
  svgElement('text', { class: 'block-name', x: textX, y: 19, 'text-anchor': 'middle' }, block.name),
  svgElement('text', { class: 'block-type', x: textX, y: 33, 'text-anchor': 'middle' }, block.type),
  marking ? svgElement('text', { class: 'block-marking', x: width / 2, y: 47, 'text-anchor': 'middle' }, marking) : null,
  geometry.isSubsystem ? svgElement('g', { class: 'open-button', transform: `translate(${width - 20},4)` },
    svgElement('title', {}, 'open'),
    svgElement('rect', { width: 16, height: 16, rx: 3 }),
    svgElement('path', { d: 'M4,8L12,8M8.5,4.5L12,8L8.5,11.5' })) : null,
  geometry.ports.map(portGroup));
  return group;
}

// A system's own input or output, at the left or right edge of the drawing.
export function drawSystemPort(node, position) {
  const { width, height } = node.geometry;
  const direction = node.kind === 'inport' ? 'inport' : 'outport';
  const tip = node.kind === 'inport' ? `M0,0L${width - 8},0L${width},${height / 2}L${width - 8},${height}L0,${height}Z`
    : `M8,0L${width},0L${width},${height}L8,${height}L0,${height / 2}Z`;
  return svgElement('g', { class: `system-port ${direction}`, 'data-port': node.port, transform: `translate(${position.x},${position.y})` },
    svgElement('path', { d: tip }),
    svgElement('text', { x: width / 2, y: height / 2 + 3.5, 'text-anchor': 'middle' }, node.port));
}

export function drawUndrivenStub(node, position) {
  const { width, height } = node.geometry;
  return svgElement('g', { class: 'undriven-stub', transform: `translate(${position.x},${position.y})` },
    svgElement('title', {}, 'nothing drives this signal'),
    svgElement('circle', { cx: width / 2, cy: height / 2, r: width / 2 - 1 }),
    svgElement('text', { x: width / 2, y: height / 2 + 4, 'text-anchor': 'middle' }, '?'));
}
