import { formatLiveValue } from './value_format.js';

// Live values on the wires: the newest values are kept and written at most once per animation
// frame, text only (no layout), and only where the text changed, so a fast stream never queues
// work behind it.
export function createLiveLabels(requestFrame = (callback) => requestAnimationFrame(callback)) {
  let labels = new Map(); // measurement -> [text elements] of the drawn system
  let values = new Map();
  let shownText = new Map();
  let pending = false;
  let enabled = false;

  const write = () => {
    pending = false;
    if (!enabled) return;
    for (const [measurement, elements] of labels) {
      if (!values.has(measurement)) continue;
      const text = formatLiveValue(values.get(measurement));
      if (shownText.get(measurement) === text) continue;
      shownText.set(measurement, text);
      for (const label of elements) label.textContent = text;
    }
  };
  const schedule = () => {
    if (pending || !enabled) return;
    pending = true;
    requestFrame(write);
  };
  return {
    // A new drawing: its labels start empty.
    attach(root) {
      labels = new Map();
      shownText = new Map();
      for (const label of root.querySelectorAll('text.live-value')) {
        const name = label.dataset.measurement;
        labels.set(name, [...(labels.get(name) ?? []), label]);
      }
      schedule();
    },
    setValues(next) {
      values = next;
      schedule();
    },
    setEnabled(on) {
      enabled = on;
      schedule();
    },
  };
}
