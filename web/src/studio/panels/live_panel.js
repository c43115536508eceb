import { EventHub } from '../../event_hub.js';
import { connectSignalFeed } from '../../signal_feed.js';
import { ScopeView } from '../../scope_view.js';
import { element } from '../../dom.js';
import { formatCounter, formatNumber } from '../../number_format.js';
import { executiveSummary } from '../../status_tables.js';
import { LiveValues } from './live_values.js';
import { SignalChooser } from './signal_chooser.js';
import { itemsNamed } from './vector_items.js';
import { watchVisibility } from './visibility.js';

// 20 Hz: a value on a wire changing faster cannot be read anyway, and the diagram's redraw then
// costs the same whether DAQ runs at 100 Hz or 1 kHz.
const live_update_interval_ms = 50;
const figures_interval_ms = 1000;
const scope_window_s = 10;
const default_address = 'tcp://127.0.0.1:5555';
// Of the executive's account, what fits the toolbar.
const executive_figures = new Set(['core load', 'overruns']);
// The server's answers to these requests are this panel's to show.
const own_requests = new Set(['connect', 'disconnect', 'set', 'describe', 'status']);

// External mode: connects the studio server to a running target over XCP, puts the newest value
// of every measurement on the diagram's wires, plots the scoped ones and writes parameters.
export function createLivePanel({ element: root, hub, connection, studio, view }) {
  const stats = { samples: 0, liveUpdates: 0, lastLiveUpdateMs: 0, frames: 0 };
  let external = { state: 'off' };
  let store = null;
  let liveValues = null;
  let freshSamples = false; // samples came since the diagram was last given values
  let describedParameters = [];
  const parameters = new Map(); // name -> {value, status, message}, as last read back
  const wanted = new Set(); // scoped before the target described them
  let liveTimer = 0;
  let figuresTimer = 0;
  let counted = { samples: 0, liveUpdates: 0, atMs: 0 };

  root.classList.add('studio-panel', 'live-panel');
  const address = element('input', { type: 'text', class: 'address', value: studio?.defaults?.xcp || default_address, spellcheck: false, 'aria-label': 'target address' });
  const connectButton = element('button', { type: 'submit', class: 'primary' }, 'Connect');
  const disconnectButton = element('button', { type: 'button', onclick: () => send({ type: 'disconnect' }) }, 'Disconnect');
  const stateBadge = element('span', { class: 'external-state', role: 'status' });
  const problem = element('span', { class: 'bad external-problem' });
  const figures = element('span', { class: 'figures muted' });
  const executive = element('span', { class: 'muted' });
  const message = element('p', { class: 'panel-message', role: 'status' });
  const chooserNode = element('div');
  const plotNode = element('div', { class: 'panel-plot' });
  const form = element(
    'form',
    {
      class: 'panel-toolbar',
      onsubmit: (event) => {
        event.preventDefault();
        send({ type: 'connect', address: address.value.trim() });
      },
    },
    element('label', { class: 'inline' }, 'Target', address),
    connectButton,
    disconnectButton,
    stateBadge,
    problem,
    executive,
    figures,
  );
  root.replaceChildren(form, message, element('div', { class: 'panel-scope-head' }, element('span', { class: 'muted' }, 'Scope (click a wire to add):'), chooserNode), plotNode);

  const scopeView = new ScopeView(plotNode, stats);
  scopeView.windowS = scope_window_s;
  const chooser = new SignalChooser(chooserNode, { onChange: (signals) => scopeView.setSignals(signals), placeholder: 'add a measurement…' });
  watchVisibility(root, (visible) => scopeView.setVisible(visible));

  function say(text, tone = 'muted') {
    message.textContent = text;
    message.className = `panel-message ${tone}`;
  }

  function send(request) {
    if (connection.send(request)) return true;
    say('not connected to duet studio', 'bad');
    return false;
  }

  // The dashboard's signal feed does the rings; it runs on a hub of its own so that its 'store'
  // and 'data' events stay out of the shell's hub.
  const feed = new EventHub();
  for (const type of ['description', 'samples', 'telemetry']) hub.on(type, (payload) => feed.emit(type, payload));
  connectSignalFeed(feed, stats);
  feed.on('store', (next) => {
    store = next;
    liveValues = new LiveValues(store);
    scopeView.setStore(store);
    const pending = [...wanted].flatMap((name) => itemsNamed(store.signals, name).map((signal) => signal.name));
    chooser.setSignals(store.signals, [...chooser.chosen, ...pending]);
    wanted.clear();
  });
  feed.on('data', () => {
    freshSamples = true;
    scopeView.dataArrived();
  });

  function pushLiveValues() {
    if (!freshSamples || !liveValues) return;
    freshSamples = false;
    view?.setLiveValues(liveValues.read());
    stats.liveUpdates += 1;
    stats.lastLiveUpdateMs = performance.timeOrigin + performance.now();
  }

  function showFigures() {
    const now = performance.now();
    const seconds = (now - counted.atMs) / 1000;
    const rate = (count) => (counted.atMs > 0 && seconds > 0 ? formatNumber(count / seconds, 3) : '—');
    figures.textContent = `${formatCounter(stats.samples)} samples (${rate(stats.samples - counted.samples)}/s), wire values ${rate(stats.liveUpdates - counted.liveUpdates)}/s`;
    counted = { samples: stats.samples, liveUpdates: stats.liveUpdates, atMs: now };
  }

  function showExternal() {
    const open = external.state === 'open';
    stateBadge.textContent = external.state + (external.address && external.state !== 'off' ? ` ${external.address}` : '');
    stateBadge.dataset.state = external.state;
    problem.textContent = external.problem ?? '';
    connectButton.disabled = open || external.state === 'connecting';
    disconnectButton.disabled = external.state === 'off';
    root.dataset.external = external.state;
  }

  hub.on('external', setExternal);
  // Without the page's own socket to duet studio nothing of the target arrives: the link shows
  // off until the server says otherwise.
  hub.on('link', (link) => {
    if (link.name !== 'connected' && external.state !== 'off') setExternal({ state: 'off', problem: 'the connection to duet studio was lost' });
  });

  function setExternal(next) {
    const wasOpen = external.state === 'open';
    external = next;
    const open = external.state === 'open';
    showExternal();
    if (open === wasOpen) return;
    view?.setLiveMode(open);
    clearInterval(liveTimer);
    clearInterval(figuresTimer);
    if (open) {
      say('');
      liveTimer = setInterval(pushLiveValues, live_update_interval_ms);
      figuresTimer = setInterval(showFigures, figures_interval_ms);
    }
    counted = { samples: stats.samples, liveUpdates: stats.liveUpdates, atMs: 0 };
    showFigures();
  }

  hub.on('description', (description) => {
    describedParameters = description.parameters ?? [];
  });

  hub.on('parameter', (answer) => {
    const name = answer.name ?? describedParameters[answer.index]?.name;
    if (name === undefined) return;
    // A refused write reads nothing back: the value last read stays the target's.
    const value = typeof answer.value === 'number' ? answer.value : parameters.get(name)?.value;
    const readBack = { value, status: answer.status, message: answer.message };
    parameters.set(name, readBack);
    if (answer.status !== 'reported' && answer.status !== 'applied') {
      say(`${name}: ${answer.status}${answer.message ? ` — ${answer.message}` : ''}`, answer.status === 'clamped' ? 'warn' : 'bad');
    }
    panel.onParameter?.(name, readBack);
  });

  hub.on('channel', (channel) => {
    if (channel.open === false) say('The target went away; the values shown are the last it sent.', 'warn');
    else say('');
  });

  // The target's executive in a few words (the dashboard's Status page has the whole account).
  hub.on('status', (status) => {
    executive.textContent = executiveSummary(status.executive)
      .filter(([label]) => executive_figures.has(label))
      .map(([label, value]) => `${label} ${formatCounter(value)}`)
      .join(', ');
  });

  hub.on('error', (error) => {
    if (own_requests.has(error.request)) say(`${error.request}: ${error.message}`, 'bad');
  });

  showExternal();
  showFigures();
  say("Connect to a target running this model's firmware (duet pil, or the board) to see its signals on the wires.");

  const panel = {
    stats,
    onParameter: null,

    get connected() {
      return external.state === 'open';
    },

    // A measurement of the diagram (a wire's `measurement`): all its elements when a vector.
    scope(measurementName) {
      if (!store) {
        wanted.add(measurementName);
        say(`${measurementName} will be plotted once the target describes its measurements`);
        return;
      }
      const items = itemsNamed(store.signals, measurementName);
      if (items.length === 0) return say(`${measurementName} is not among the measurements the target sends`, 'warn');
      chooser.add(items.map((signal) => signal.name));
    },

    parameter(name) {
      const readBack = parameters.get(name);
      return readBack && { value: readBack.value, status: readBack.status };
    },

    write(name, value) {
      if (!panel.connected) {
        say(`${name} not written: no target connected`, 'bad');
        return false;
      }
      return send({ type: 'set', name, value });
    },
  };
  return panel;
}
