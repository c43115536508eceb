import { svgElement } from './svg.js';

// Drawing a connection: press on a port, drag (a rubber band follows), release on a port of
// another block. Output to input, or input to output (reported the same way round).
export function createConnectDrag(svg, layer, toDrawing, onConnect) {
  let drag = null;
  const portUnder = (target) => {
    const port = target?.closest?.('.block .port');
    if (!port) return null;
    const [direction, ...name] = port.dataset.port.split(':');
    return { block: port.closest('.block').dataset.id, port: name.join(':'), direction };
  };
  svg.addEventListener('pointerdown', (event) => {
    if (event.button !== 0) return;
    const from = portUnder(event.target);
    if (!from) return;
    event.preventDefault();
    const start = toDrawing(event.clientX, event.clientY);
    const band = svgElement('line', { class: 'rubber-band', x1: start.x, y1: start.y, x2: start.x, y2: start.y });
    layer.append(band);
    drag = { from, band };
    svg.setPointerCapture(event.pointerId);
  });
  svg.addEventListener('pointermove', (event) => {
    if (!drag) return;
    const at = toDrawing(event.clientX, event.clientY);
    drag.band.setAttribute('x2', at.x);
    drag.band.setAttribute('y2', at.y);
  });
  const finish = (event, cancelled) => {
    if (!drag) return;
    const { from, band } = drag;
    drag = null;
    band.remove();
    svg.releasePointerCapture?.(event.pointerId);
    if (cancelled) return;
    // With the pointer captured, the event's target is the SVG: ask what lies under the pointer.
    const to = portUnder(document.elementFromPoint(event.clientX, event.clientY));
    if (!to || to.block === from.block || to.direction === from.direction) return;
    const [output, input] = from.direction === 'out' ? [from, to] : [to, from];
    onConnect({ from: { block: output.block, port: output.port }, to: { block: input.block, port: input.port } });
  };
  svg.addEventListener('pointerup', (event) => finish(event, false));
  svg.addEventListener('pointercancel', (event) => finish(event, true));
  return { active: () => drag !== null };
}
