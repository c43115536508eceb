import { ScopeView } from '../../scope_view.js';
import { element } from '../../dom.js';
import { formatCounter, formatNumber } from '../../number_format.js';
import { plantChoices, plant_taking_scenarios, scenarioChoices, simulateRequest } from './simulation_choices.js';
import { resultStore, spanOf } from './result_store.js';
import { SignalChooser } from './signal_chooser.js';
import { itemsNamed } from './vector_items.js';
import { watchVisibility } from './visibility.js';

// A first look that fits the panel: every column of a small result, else the first few.
const all_columns_up_to = 6;
const first_columns = 4;

// Simulation: runs the editor's text against a plant on the server and plots the result, one
// chart per unit with a shared cursor; clicking a wire adds its signal (plotSignal).
export function createSimulationPanel({ element: root, hub, connection, getText, studio }) {
  const defaults = studio?.defaults ?? {};
  let nextId = 1;
  let running = null; // the id of the run the server is working on
  let awaited = null; // the id whose result this panel will show
  let store = null;
  const wanted = new Set(); // signals asked for before a result had them

  root.classList.add('studio-panel', 'simulation-panel');
  const plantSelect = element('select', { 'aria-label': 'plant', onchange: () => showScenarioUse() }, optionsOf(plantChoices(studio)));
  plantSelect.value = defaults.plant ?? plantSelect.value;
  const scenarioSelect = element('select', { 'aria-label': 'scenario' }, scenarioChoices(studio).map(option));
  scenarioSelect.value = defaults.scenario ?? '';
  const durationField = element('input', { type: 'number', min: '0', step: 'any', value: String(defaults.duration_s ?? 10), class: 'duration', 'aria-label': 'duration in seconds' });
  const runButton = element('button', { type: 'submit', class: 'primary' }, 'Run');
  const cancelButton = element('button', { type: 'button', disabled: true, onclick: cancel }, 'Cancel');
  const progress = element('progress', { max: 1, value: 0, hidden: true });
  const info = element('span', { class: 'figures muted' });
  const message = element('p', { class: 'panel-message', role: 'status' });
  const chooserNode = element('div');
  const plotNode = element('div', { class: 'panel-plot' });
  root.replaceChildren(
    element(
      'form',
      {
        class: 'panel-toolbar',
        onsubmit: (event) => {
          event.preventDefault();
          run();
        },
      },
      element('label', { class: 'inline' }, 'Plant', plantSelect),
      element('label', { class: 'inline' }, 'Scenario', scenarioSelect),
      element('label', { class: 'inline' }, 'Duration', durationField, 's'),
      runButton,
      cancelButton,
      progress,
      info,
    ),
    message,
    element('div', { class: 'panel-scope-head' }, element('span', { class: 'muted' }, 'Plotted (click a wire to add):'), chooserNode),
    plotNode,
  );

  const scopeView = new ScopeView(plotNode, { frames: 0 });
  const chooser = new SignalChooser(chooserNode, { onChange: (signals) => scopeView.setSignals(signals), placeholder: 'add a signal…' });
  watchVisibility(root, (visible) => scopeView.setVisible(visible));
  showScenarioUse();
  say('Run simulates the text in the editor, saved or not.');

  function say(text, tone = 'muted') {
    message.textContent = text;
    message.className = `panel-message ${tone}`;
  }

  // The scenario is the robot's: with another plant it would be silently ignored, so say so.
  function showScenarioUse() {
    scenarioSelect.disabled = plantSelect.value !== plant_taking_scenarios;
    scenarioSelect.title = scenarioSelect.disabled ? `only the ${plant_taking_scenarios} plant takes a scenario` : '';
  }

  function showRunning(id) {
    running = id;
    runButton.disabled = id !== null;
    cancelButton.disabled = id === null;
    progress.hidden = id === null;
    if (id !== null) progress.value = 0;
  }

  function run() {
    const { request, problem } = simulateRequest({
      text: getText(),
      id: nextId,
      durationS: durationField.valueAsNumber,
      plant: plantSelect.value,
      scenario: scenarioSelect.value,
    });
    if (problem) return say(problem, 'bad');
    if (!connection.send(request)) return say('not connected to duet studio', 'bad');
    awaited = nextId;
    nextId += 1;
    showRunning(request.id);
    say(`simulating ${formatNumber(request.duration_s)} s against ${request.plant}${request.scenario ? ` (${request.scenario})` : ''}…`);
  }

  function cancel() {
    if (running === null) return;
    if (!connection.send({ type: 'cancel_simulation', id: running })) say('not connected to duet studio', 'bad');
    else say('cancelling…');
  }

  hub.on('simulation_progress', (update) => {
    if (update.id === running && typeof update.fraction === 'number') progress.value = update.fraction;
  });

  hub.on('simulation', (result) => {
    if (result.id !== awaited) return; // an older run's late answer
    showRunning(null);
    show(result);
  });

  hub.on('error', (error) => {
    if (error.request !== 'simulate' && error.request !== 'cancel_simulation') return;
    if (error.request === 'simulate') showRunning(null);
    say(`simulation failed: ${error.message}`, 'bad');
  });

  // The page's socket dropped: the run's answer cannot come any more.
  hub.on('link', (link) => {
    if (link.name === 'connected' || running === null) return;
    showRunning(null);
    say('the connection to duet studio was lost during the simulation; run it again', 'bad');
  });

  function show(result) {
    store = resultStore(result);
    const span = spanOf(store);
    const points = store.time.view().length;
    info.textContent = `${store.signals.length} signals, ${formatCounter(points)} points over ${formatNumber(span, 4)} s` + (result.decimated_by > 1 ? `, 1 tick in ${result.decimated_by}` : '');
    if (result.cancelled) say(`cancelled: showing the ${formatNumber(span, 4)} s simulated before`, 'warn');
    else say('');
    // A new result is seen whole, whatever the previous one was zoomed to.
    scopeView.setPaused(false);
    scopeView.setStore(store);
    scopeView.setWindow(span);
    const kept = chooser.chosen.filter((name) => store.signals.some((signal) => signal.name === name));
    const asked = [...wanted].flatMap((name) => itemsNamed(store.signals, name).map((signal) => signal.name));
    wanted.clear();
    chooser.setSignals(store.signals, [...(kept.length > 0 ? kept : firstColumns(store.signals)), ...asked]);
    plotNode.dataset.points = String(points);
  }

  return {
    // A wire's resolved signal name: its column, or all its elements' columns for a vector.
    plotSignal(resolvedName) {
      if (!store) {
        wanted.add(resolvedName);
        return say(`${resolvedName} will be plotted when a simulation has run`);
      }
      const columns = itemsNamed(store.signals, resolvedName);
      if (columns.length === 0) return say(`${resolvedName} is not in the simulation's result`, 'warn');
      chooser.add(columns.map((signal) => signal.name));
    },
  };
}

function firstColumns(signals) {
  const shown = signals.length <= all_columns_up_to ? signals : signals.slice(0, first_columns);
  return shown.map((signal) => signal.name);
}

function option({ value, label, title }) {
  return element('option', { value, title: title || undefined }, label);
}

// Options under their group's heading, in the order the groups first appear.
function optionsOf(choices) {
  const groups = [...new Set(choices.map((choice) => choice.group))];
  return groups.map((group) => element('optgroup', { label: group }, choices.filter((choice) => choice.group === group).map(option)));
}
