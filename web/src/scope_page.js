import { element, replaceChildren } from './dom.js';
import { colourFor } from './palette.js';
import { ScopeView } from './scope_view.js';
import { signalsCsv } from './csv.js';
import { downloadText, timestampForFile } from './download.js';

const default_signal_count = 8;

// The Scope page: signal choice, window length, pause, CSV and MDF4 export around a ScopeView.
export function createScopePage({ hub, stats, mdf4 }) {
  const checkboxes = document.getElementById('scope-signals');
  const summary = document.getElementById('scope-signals-summary');
  const windowSelect = document.getElementById('scope-window');
  const pauseButton = document.getElementById('scope-pause');
  const exportButton = document.getElementById('scope-export');
  const mdf4Button = document.getElementById('scope-mdf4');
  const message = document.getElementById('scope-message');
  const view = new ScopeView(document.getElementById('scope-plot'), stats);
  let chosen = null; // names, kept across descriptions of the same signals

  const showPaused = () => {
    pauseButton.textContent = view.paused ? 'Resume' : 'Pause';
    pauseButton.classList.toggle('active', view.paused);
  };
  view.onPausedByZoom = showPaused;

  const choose = () => {
    if (!view.store) return;
    chosen = [...checkboxes.querySelectorAll('input[data-signal]')].filter((box) => box.checked).map((box) => box.dataset.signal);
    summary.textContent = `Signals (${chosen.length} of ${view.store.signals.length})`;
    view.setSignals(view.store.signals.filter((signal) => chosen.includes(signal.name)));
  };

  hub.on('store', (store) => {
    const names = store.signals.map((signal) => signal.name);
    if (!chosen || !chosen.some((name) => names.includes(name))) chosen = names.slice(0, default_signal_count);
    view.setStore(store);
    replaceChildren(
      checkboxes,
      store.signals.map((signal) =>
        element(
          'label',
          { class: 'chip', style: `--signal-colour: ${colourFor(signal.index)}` },
          element('input', { type: 'checkbox', 'data-signal': signal.name, checked: chosen.includes(signal.name), onchange: choose }),
          element('span', { class: 'swatch' }),
          signal.unit ? `${signal.name} [${signal.unit}]` : signal.name,
        ),
      ),
    );
    choose();
  });
  hub.on('data', () => view.dataArrived());

  windowSelect.addEventListener('change', () => view.setWindow(Number(windowSelect.value)));
  view.windowS = Number(windowSelect.value);
  pauseButton.addEventListener('click', () => {
    view.setPaused(!view.paused);
    showPaused();
  });
  // What the exports hold: every sample the scope has of the signals shown.
  const shownColumns = () => {
    const source = view.source();
    if (!source || view.signals.length === 0) return null;
    return { time: source.time, columns: view.signals.map((signal) => ({ name: signal.name, unit: signal.unit, values: source.values[signal.index] })) };
  };
  exportButton.addEventListener('click', () => {
    const shown = shownColumns();
    if (shown) downloadText(`scope-${timestampForFile()}.csv`, signalsCsv(shown.time, shown.columns), 'text/csv');
  });
  hub.on('description', () => {
    mdf4Button.hidden = !mdf4.available;
  });
  mdf4Button.addEventListener('click', async () => {
    const shown = shownColumns();
    if (!shown || shown.time.length === 0) {
      message.textContent = 'nothing to save yet';
      message.className = 'message bad';
      return;
    }
    mdf4Button.disabled = true;
    message.textContent = 'writing the MDF4 file…';
    message.className = 'message muted';
    // The request is built from copies taken now: the rings go on filling while it is on its way.
    const { ok, message: result } = await mdf4.scope(shown.time, shown.columns);
    mdf4Button.disabled = false;
    message.textContent = result;
    message.className = `message ${ok ? 'muted' : 'bad'}`;
  });

  return {
    show: () => view.setVisible(true),
    hide: () => view.setVisible(false),
  };
}
