// Calls onChange(visible) when `element` starts or stops taking up room. The shell hides a
// panel's tab with display: none, which gives the element no size: plotting then would waste
// frames on charts nobody sees and measure them at width 0.
export function watchVisibility(element, onChange) {
  let visible = null;
  const observer = new ResizeObserver(() => {
    const now = element.offsetWidth > 0 && element.offsetHeight > 0;
    if (now === visible) return;
    visible = now;
    onChange(now);
  });
  observer.observe(element);
  return observer;
}
