// duet studio's page: the model's diagram beside its text, kept in step through the server's
// checks (docs/STUDIO.md). This file only wires the parts together.
import { Connection } from '../connection.js';
import { EventHub } from '../event_hub.js';
import { websocketUrl } from '../websocket_url.js';
import { createLinkIndicator } from '../link_indicator.js';
import { createDiagramView } from './diagram/diagram_view.js';
import { createSimulationPanel } from './panels/simulation_panel.js';
import { createGeneratePanel } from './panels/generate_panel.js';
import { createLivePanel } from './panels/live_panel.js';
import { createEditor } from './editor.js';
import { CheckLoop } from './check_loop.js';
import { blockMarkers, checkSummary, inOpenFile, lintDiagnostics, positionOf } from './diagnostics.js';
import { blockAtLine, findBlock, systemOfBlock, textRangeOf, wireAtCursor, wireSelection } from './selection_sync.js';
import { createDiagramEdits } from './diagram_edits.js';
import { createPalette } from './palette.js';
import { createBlockForm } from './block_form.js';
import { createProblemsList } from './problems_list.js';
import { createFileState } from './file_state.js';
import { createBottomTabs } from './bottom_tabs.js';
import { makeSplitter } from './splitters.js';

const byId = (id) => document.getElementById(id);
const hub = new EventHub();
const stats = { checks: 0, checkLatencyMs: [], lastModelSeq: -1 };
let studio = null;
let lastModel = null;
let diagram = null; // the last model that drew: selections and edits refer to it
let selected = null;
let selectBlockWhenDrawn = null; // a block just added from the palette
const panels = {};

const say = (text, tone = '') => {
  const node = byId('edit-message');
  node.textContent = text;
  node.dataset.tone = tone;
};

const indicator = createLinkIndicator(byId('link-indicator'));
const connection = new Connection(websocketUrl(location), {
  onMessage: (message) => hub.emit(message.type, message),
  onState(state) {
    indicator.socket(state);
    hub.emit('link', state);
  },
});

const checks = new CheckLoop((request) => {
  const sent = connection.send(request);
  if (sent) stats.checks += 1;
  return sent;
});

const editor = createEditor(byId('editor'), {
  onEdit(text) {
    checks.edited(text);
    file.edited();
    showCheckState({ text: 'checking…', state: 'pending' });
  },
  onCursor: (range) => selectFromText(range.head),
  onSave: () => file.save(),
});

const view = createDiagramView(byId('diagram'), {
  onSelect: (selection) => selectFromDiagram(selection),
  onOpenSystem: (path) => say(path ? `inside ${path}` : ''),
  onConnect: (connection) => edits.connect(connection),
  onActivateBlock(id) {
    bottom.show('block');
    byId('block-form').querySelector('input, select')?.focus();
    say(`editing ${id}`);
  },
});

const currentSystem = () => view.currentSystem() ?? '';
const edits = createDiagramEdits({ editor, getDiagram: () => diagram, currentSystem, say });
const file = createFileState({
  connection,
  editor,
  say,
  nodes: {
    fileName: byId('file-name'), dirty: byId('dirty-marker'), save: byId('save'), reload: byId('reload'),
    banner: byId('banner'), bannerText: byId('banner-text'), bannerReload: byId('banner-reload'), bannerDismiss: byId('banner-dismiss'),
  },
});
const palette = createPalette(
  { root: byId('palette'), list: byId('palette-list'), filter: byId('palette-filter'), toggle: byId('palette-toggle') },
  { onAdd: (entry) => (selectBlockWhenDrawn = edits.addBlock(entry) ?? null) },
);
const blockForm = createBlockForm(byId('block-form'), { edits, getLivePanel: () => panels.live });
const problems = createProblemsList(byId('problems'), byId('problem-count'), {
  onJump(diagnostic) {
    if (inOpenFile(diagnostic, studio.file)) {
      const position = positionOf(editor.doc, diagnostic.line, diagnostic.column);
      editor.select(position, position, { focus: true });
    }
    if (diagnostic.block && findBlock(diagram, diagnostic.block)) showInDiagram({ kind: 'block', id: diagnostic.block }, systemOfBlock(diagnostic.block));
  },
});
const bottom = createBottomTabs(byId('bottom'), { onShow: () => blockForm.refresh() });

function showCheckState({ text, state }) {
  const node = byId('check-state');
  node.textContent = text;
  node.dataset.state = state;
}

// ---- the model: text, diagram, diagnostics ------------------------------------------------------

hub.on('studio', (message) => {
  const first = studio === null;
  studio = message;
  byId('file-name').textContent = message.file;
  palette.setLibrary(message.library ?? []);
  blockForm.setModel(null, message.library ?? []);
  if (first || !file.dirty()) {
    editor.load(message.text);
    file.loaded(message);
    checks.loaded(message.text, { answerComing: true });
  } else {
    // Back after a lost connection with unsaved edits: keep them, have them checked.
    checks.loaded(editor.getText(), { answerComing: false });
    file.changedOnDisk(message);
  }
  if (first) createPanels();
});

hub.on('model', (model) => {
  const editTimes = checks.answered(model);
  if (!editTimes) return; // an answer to a text that is no longer the one awaited
  showModel(model).then(() => {
    const now = performance.now();
    for (const time of editTimes) stats.checkLatencyMs.push(now - time);
  });
});

async function showModel(model) {
  lastModel = model;
  stats.lastModelSeq = model.seq;
  const diagnostics = model.diagnostics ?? [];
  editor.setDiagnostics(lintDiagnostics(editor.doc, diagnostics, studio.file));
  problems.show(diagnostics, studio.file);
  const summary = checkSummary(diagnostics);
  if (!model.diagram) {
    // The text does not read as a model: keep the last drawing, dimmed, and say so.
    view.setStale(true);
    showCheckState({ text: `${summary.text} (not a model; the diagram is the last one)`, state: 'error' });
    return;
  }
  showCheckState(summary);
  diagram = model.diagram;
  view.setStale(false);
  await view.setModel(diagram, studio.library, model.tasks ?? []);
  view.setMarkers(blockMarkers(diagnostics));
  blockForm.setModel(diagram);
  if (selectBlockWhenDrawn && findBlock(diagram, selectBlockWhenDrawn)) {
    showInDiagram({ kind: 'block', id: selectBlockWhenDrawn }, systemOfBlock(selectBlockWhenDrawn));
    selectFromDiagram({ kind: 'block', id: selectBlockWhenDrawn });
    selectBlockWhenDrawn = null;
  }
}

hub.on('file', (message) => {
  editor.load(message.text);
  file.loaded(message);
  checks.loaded(message.text, { answerComing: false });
  say('reloaded from disk', 'good');
});
hub.on('saved', (message) => file.saved(message));
hub.on('save_refused', (message) => file.refused(message));
hub.on('file_changed', (message) => file.changedOnDisk(message));
hub.on('error', (error) => {
  if (error.request === 'save') file.failed();
  if (['check', 'save', 'reload', ''].includes(error.request ?? '')) say(`server: ${error.message}`, 'bad');
});

// ---- selection in step: diagram -> text, text -> diagram ----------------------------------------

let selectingFromText = false;

function sameSelection(a, b) {
  return (a?.kind ?? null) === (b?.kind ?? null) && (a?.id ?? null) === (b?.id ?? null);
}

function selectFromDiagram(selection) {
  if (selectingFromText) return;
  selected = selection;
  blockForm.select(selection);
  const range = textRangeOf(diagram, selection, editor.doc);
  if (range) editor.select(range.from, range.to);
  if (selection?.kind !== 'wire') return;
  if (bottom.current === 'simulation') panels.simulation?.plotSignal(selection.resolved);
  else if (panels.live?.connected && selection.measurement) panels.live.scope(selection.measurement);
  else if (bottom.current === 'problems') bottom.show('block');
}

function showInDiagram(selection, system) {
  if (currentSystem() !== system) view.showSystem(system);
  selectingFromText = true;
  try {
    view.select(selection);
  } finally {
    selectingFromText = false;
  }
}

function selectFromText(position) {
  if (!diagram) return;
  const line = editor.doc.lineAt(position);
  const wire = wireAtCursor(diagram, line.number, position - line.from + 1, line.text);
  const block = wire ? null : blockAtLine(diagram.root, line.number);
  const selection = wire ? wireSelection(wire) : block ? { kind: 'block', id: block.id } : null;
  if (sameSelection(selection, selected)) return;
  selected = selection;
  if (selection) showInDiagram(selection, wire ? wire.system : systemOfBlock(block.id));
  else showInDiagram(null, currentSystem());
  blockForm.select(selection);
}

// ---- the panels (Simulation, Generated, Live): they subscribe to the hub themselves -------------

function createPanels() {
  const context = { hub, connection, getText: editor.getText, studio, view };
  const makers = { simulation: createSimulationPanel, generated: createGeneratePanel, live: createLivePanel };
  for (const [name, make] of Object.entries(makers)) {
    try {
      panels[name] = make({ element: byId(name), ...context });
      if (name === 'live') panels.live.onParameter = (parameter, state) => blockForm.readBack(parameter, state);
    } catch (error) {
      // One panel's failure must not take the editor and the diagram with it.
      console.error(`the ${name} panel:`, error);
      byId(name).textContent = `The ${name} panel failed to start: ${error.message}`;
    }
  }
}

// ---- the page's keys and controls ------------------------------------------------------------

document.addEventListener('keydown', (event) => {
  if ((event.ctrlKey || event.metaKey) && event.key === 's' && !event.defaultPrevented) {
    event.preventDefault();
    file.save();
    return;
  }
  const typing = event.target.closest?.('.cm-editor, input, select, textarea');
  if (event.key === 'Delete' && !typing && selected?.kind === 'block') edits.deleteBlock(selected.id);
});
byId('find').addEventListener('input', (event) => {
  const found = view.find(event.target.value);
  if (found) selectFromDiagram(found);
});
makeSplitter(byId('split-vertical'), { property: '--editor-width', axis: 'x', min: 240, max: () => window.innerWidth - 320, invert: true });
makeSplitter(byId('split-horizontal'), { property: '--bottom-height', axis: 'y', min: 120, max: () => window.innerHeight - 200, invert: true });

// For browser tests and benchmarks (README): small on purpose.
window.duetStudio = {
  stats,
  view,
  // Offsets into getText(), whatever the line separator.
  editor: {
    getText: editor.getText,
    setText: editor.setText,
    select: (from, to = from) => editor.select(editor.positionOf(from), editor.positionOf(to)),
    selection: () => {
      const { from, to } = editor.selection();
      return { from: editor.offsetOf(from), to: editor.offsetOf(to) };
    },
  },
  connection,
  hub,
  get lastModel() {
    return lastModel;
  },
  get studio() {
    return studio;
  },
};

connection.open();
