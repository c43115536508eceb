import { pathData, svgElement } from './svg.js';

// One Wire with all its branches: a line per branch (each ends in an arrow), junction dots where
// branches part, the signal's name, and a place for its live value when it is measurable.
export function drawWire(wire, route) {
  const undriven = !wire.source;
  const group = svgElement('g', { class: `wire${undriven ? ' undriven' : ''}`, 'data-id': wire.id },
    svgElement('path', { class: 'wire-hit', d: route.branches.map(pathData).join('') }),
    route.branches.map((branch) => svgElement('path', { class: 'wire-line', d: pathData(branch), 'marker-end': wire.targets?.length ? 'url(#diagram-arrow)' : null })),
    route.junctions.map((point) => svgElement('circle', { class: 'junction', cx: point.x, cy: point.y, r: 3 })),
    route.label ? svgElement('text', { class: 'wire-label', x: route.label.x + 2, y: route.label.y + route.label.height - 3 }, wire.signal) : null);
  if (wire.measurement && route.label) {
    group.append(svgElement('text', {
      class: 'live-value', 'data-measurement': wire.measurement,
      x: route.label.x + 2, y: route.label.y + route.label.height + 12,
    }));
  }
  return group;
}
