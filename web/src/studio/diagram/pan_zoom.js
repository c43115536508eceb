// Pan (drag the background) and zoom (wheel, buttons) of one SVG group, as a transform
// scale-then-translate; the drawing itself never changes for either.
const minimum_scale = 0.05;
const maximum_scale = 4;

export function createPanZoom(svg, viewport, { isBackground }) {
  let scale = 1;
  let x = 0;
  let y = 0;
  const apply = () => viewport.setAttribute('transform', `translate(${x},${y}) scale(${scale})`);
  const clampScale = (value) => Math.min(maximum_scale, Math.max(minimum_scale, value));

  // Zoom about a point of the SVG, so what is under the pointer stays under it.
  const zoomAt = (factor, pointX, pointY) => {
    const next = clampScale(scale * factor);
    x = pointX - ((pointX - x) * next) / scale;
    y = pointY - ((pointY - y) * next) / scale;
    scale = next;
    apply();
  };
  const size = () => ({ width: svg.clientWidth || 800, height: svg.clientHeight || 600 });

  svg.addEventListener('wheel', (event) => {
    event.preventDefault();
    const box = svg.getBoundingClientRect();
    zoomAt(Math.exp(-event.deltaY * 0.0015), event.clientX - box.left, event.clientY - box.top);
  }, { passive: false });

  let drag = null;
  svg.addEventListener('pointerdown', (event) => {
    if (event.button !== 0 || !isBackground(event.target)) return;
    drag = { startX: event.clientX, startY: event.clientY, fromX: x, fromY: y, moved: false };
    svg.setPointerCapture(event.pointerId);
  });
  svg.addEventListener('pointermove', (event) => {
    if (!drag) return;
    x = drag.fromX + event.clientX - drag.startX;
    y = drag.fromY + event.clientY - drag.startY;
    drag.moved ||= Math.abs(event.clientX - drag.startX) + Math.abs(event.clientY - drag.startY) > 3;
    apply();
  });
  const endDrag = (event) => {
    if (!drag) return;
    svg.releasePointerCapture?.(event.pointerId);
    // A drag that moved is a pan, not a click on the background (which clears the selection).
    if (drag.moved) svg.addEventListener('click', (click) => click.stopPropagation(), { capture: true, once: true });
    drag = null;
  };
  svg.addEventListener('pointerup', endDrag);
  svg.addEventListener('pointercancel', endDrag);

  return {
    zoomBy(factor) {
      const { width, height } = size();
      zoomAt(factor, width / 2, height / 2);
    },
    // The whole box in view with a margin, never magnified beyond 1.2 (a small system stays readable, not huge).
    fit(box) {
      const { width, height } = size();
      const margin = 24;
      scale = clampScale(Math.min((width - 2 * margin) / Math.max(box.width, 1), (height - 2 * margin) / Math.max(box.height, 1), 1.2));
      x = (width - box.width * scale) / 2 - box.x * scale;
      y = (height - box.height * scale) / 2 - box.y * scale;
      apply();
    },
    // Moves the view so a box (drawing coordinates) is visible, changing nothing when it already is.
    reveal(box) {
      const { width, height } = size();
      const left = box.x * scale + x;
      const top = box.y * scale + y;
      const right = left + box.width * scale;
      const bottom = top + box.height * scale;
      if (left >= 0 && top >= 0 && right <= width && bottom <= height) return;
      x += width / 2 - (left + right) / 2;
      y += height / 2 - (top + bottom) / 2;
      apply();
    },
    // From client (pointer) coordinates to drawing coordinates.
    toDrawing(clientX, clientY) {
      const box = svg.getBoundingClientRect();
      return { x: (clientX - box.left - x) / scale, y: (clientY - box.top - y) / scale };
    },
    // The view of one system, to come back to it as it was left.
    view: () => ({ scale, x, y }),
    restore(view) {
      ({ scale, x, y } = view);
      apply();
    },
  };
}
