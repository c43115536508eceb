import { element, replaceChildren } from './dom.js';
import { describeValue, namedFirst } from './value_names.js';

// "Now" on the Tuning page: every telemetry signal's newest value, named values (a state, the
// controller in use, whose settings) first and by name, so that one sees what is in effect while
// tuning. Redrawn at most once per animation frame.
export function createValuesPanel({ hub, node }) {
  let store = null;
  let cells = [];
  let pending = false;

  const draw = () => {
    pending = false;
    if (!store) return;
    for (const { signal, cell } of cells) {
      const value = store.values[signal.index].last();
      const text = describeValue(signal, value);
      if (cell.textContent !== text) cell.textContent = text;
      cell.dataset.value = typeof value === 'number' ? String(value) : '';
    }
  };

  hub.on('store', (next) => {
    store = next;
    cells = namedFirst(next.signals).map((signal) => ({
      signal,
      cell: element('span', { class: signal.labels?.length ? 'now-value named' : 'now-value', 'data-now': signal.name }, '—'),
    }));
    replaceChildren(
      node,
      cells.map(({ signal, cell }) => element('div', { class: 'now-item' }, element('span', { class: 'now-name' }, signal.name), cell)),
    );
    draw();
  });
  hub.on('data', () => {
    if (pending) return;
    pending = true;
    requestAnimationFrame(draw);
  });
}
