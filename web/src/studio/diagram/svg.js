// SVG element builder, the SVG twin of ../../dom.js's element(): attributes set as given,
// text always as text (names come from the model file, never parsed as markup).
const svg_namespace = 'http://www.w3.org/2000/svg';

export function svgElement(tag, attributes = {}, ...children) {
  const node = document.createElementNS(svg_namespace, tag);
  for (const [name, value] of Object.entries(attributes)) {
    if (value === undefined || value === null || value === false) continue;
    node.setAttribute(name, value === true ? '' : String(value));
  }
  for (const child of children.flat()) {
    if (child === undefined || child === null || child === false) continue;
    node.append(typeof child === 'object' ? child : String(child));
  }
  return node;
}

// Round coordinates for path data: sub-pixel digits only make the DOM bigger.
export function pathData(points) {
  return points.map((point, index) => `${index === 0 ? 'M' : 'L'}${Math.round(point.x * 10) / 10},${Math.round(point.y * 10) / 10}`).join('');
}
