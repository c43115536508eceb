// Drag handles between the diagram and the text (widths) and above the bottom area (height).
// Sizes are CSS custom properties on the body, so the grid reflows and nothing is measured twice.
export function makeSplitter(handle, { property, axis, min, max, invert = false, onDone }) {
  handle.addEventListener('pointerdown', (down) => {
    down.preventDefault();
    handle.setPointerCapture(down.pointerId);
    const start = axis === 'x' ? down.clientX : down.clientY;
    const initial = parseFloat(getComputedStyle(document.body).getPropertyValue(property)) || 0;
    const move = (event) => {
      const delta = (axis === 'x' ? event.clientX : event.clientY) - start;
      const size = Math.min(Math.max(initial + (invert ? -delta : delta), min), max());
      document.body.style.setProperty(property, `${size}px`);
    };
    const up = () => {
      handle.removeEventListener('pointermove', move);
      handle.removeEventListener('pointerup', up);
      onDone?.();
    };
    handle.addEventListener('pointermove', move);
    handle.addEventListener('pointerup', up);
  });
}
