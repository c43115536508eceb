import { element } from '../../dom.js';
import { createBreadcrumb } from './breadcrumb.js';
import { describeBlock } from './block_description.js';
import { createConnectDrag } from './connect_drag.js';
import { drawScene } from './draw_scene.js';
import { elkLayout } from './elk_layout.js';
import { findInModel } from './find.js';
import { keptLayout } from './kept_layout.js';
import { createLegend } from './legend.js';
import { createLiveLabels } from './live_labels.js';
import { markersInSystem, worstSeverity } from './markers.js';
import { indexDiagram, nearestExistingSystem, systemOfBlock, wireSelection } from './model_index.js';
import { createPanZoom } from './pan_zoom.js';
import { buildScene } from './scene.js';
import { svgElement } from './svg.js';
import { taskColours } from './task_colours.js';
import { createToolbar } from './toolbar.js';
import { createTooltip } from './tooltip.js';

// The diagram view: one system of the model drawn as blocks and wires, navigable into
// subsystems, selectable, annotated with markers and live values. See the API in the brief
// (docs/STUDIO.md has the diagram's JSON).
export function createDiagramView(container, callbacks = {}) {
  const state = {
    diagram: null, index: indexDiagram(null), libraryByType: new Map(), tasks: [], colourOf: taskColours([]),
    shown: '', drawnSystem: null, views: new Map(), scene: null, drawing: null, layouts: new Map(), selection: null, markers: new Map(),
    stats: { system: '', blocks: 0, wires: 0, layoutMs: 0, drawMs: 0 }, renderCount: 0,
  };

  const svg = svgElement('svg', { class: 'diagram-canvas', role: 'img', 'aria-label': 'block diagram' },
    svgElement('defs', {}, svgElement('marker', { id: 'diagram-arrow', viewBox: '0 0 8 8', refX: 8, refY: 4, markerWidth: 8, markerHeight: 8, markerUnits: 'userSpaceOnUse', orient: 'auto' },
      svgElement('path', { d: 'M0,0L8,4L0,8Z', class: 'arrow-head' }))));
  const viewport = svgElement('g', { class: 'viewport' });
  const overlay = svgElement('g', { class: 'overlay' });
  viewport.append(overlay);
  svg.append(viewport);
  const breadcrumb = createBreadcrumb((path) => showSystem(path));
  const legend = createLegend();
  const toolbar = createToolbar({
    onFind: (text) => {
      const found = find(text);
      if (found) callbacks.onSelect?.(found);
      return found;
    },
    onZoom: (factor) => panZoom.zoomBy(factor),
    onFit: () => fit(),
    onRelayout: () => relayout(),
  });
  container.classList.add('duet-diagram', 'live-off');
  container.append(svg, element('div', { class: 'diagram-top' }, breadcrumb.root, toolbar.root), legend.root);
  const tooltip = createTooltip(container);
  const panZoom = createPanZoom(svg, viewport, { isBackground: (target) => !target.closest('.block, .wire, .system-port') });
  const liveLabels = createLiveLabels();
  createConnectDrag(svg, overlay, (x, y) => panZoom.toDrawing(x, y), (connection) => callbacks.onConnect?.(connection));

  // --- drawing

  async function render({ relayoutNow = false } = {}) {
    const token = ++state.renderCount;
    const system = state.index.systems.get(state.shown);
    if (!system) return;
    const scene = buildScene(system, state.tasks);
    const remembered = state.layouts.get(state.shown);
    const layoutStart = performance.now();
    const layout = remembered && !relayoutNow ? keptLayout(scene, remembered) : await elkLayout(scene);
    // A newer model or system came while ELK worked: this drawing is already out of date.
    if (token !== state.renderCount) return;
    const drawStart = performance.now();
    state.layouts.set(state.shown, layout);
    state.scene = scene;
    state.drawing?.root.remove();
    state.drawing = drawScene(scene, layout, state.colourOf);
    viewport.insertBefore(state.drawing.root, overlay);
    liveLabels.attach(state.drawing.root);
    applyMarkers();
    applySelection();
    breadcrumb.update(state.diagram, state.shown);
    // A system comes back as it was left; a system seen for the first time or laid out anew is fitted.
    if (!remembered || relayoutNow) fit();
    else if (state.drawnSystem !== state.shown) panZoom.restore(state.views.get(state.shown) ?? panZoom.view());
    state.drawnSystem = state.shown;
    state.stats = {
      system: state.shown,
      blocks: state.drawing.blocks.size,
      wires: state.drawing.wires.size,
      layoutMs: Math.round(drawStart - layoutStart),
      drawMs: Math.round(performance.now() - drawStart),
    };
  }

  function applyMarkers() {
    if (!state.drawing) return;
    for (const group of state.drawing.blocks.values()) {
      group.classList.remove('marker-error', 'marker-warning');
      group.querySelector('.marker-badge')?.remove();
    }
    for (const [id, list] of markersInSystem(state.markers, state.shown)) {
      const group = state.drawing.blocks.get(id);
      if (!group) continue;
      const severity = worstSeverity(list);
      group.classList.add(`marker-${severity}`);
      const width = Number(group.querySelector('.block-box').getAttribute('width'));
      group.append(svgElement('g', { class: 'marker-badge', transform: `translate(${width},0)` },
        svgElement('circle', { r: 8 }), svgElement('text', { y: 4, 'text-anchor': 'middle' }, list.length > 1 ? String(list.length) : '!')));
    }
  }

  function selectedElement() {
    const selection = state.selection;
    if (!selection || !state.drawing) return null;
    return (selection.kind === 'block' ? state.drawing.blocks : state.drawing.wires).get(selection.id) ?? null;
  }

  function applySelection() {
    svg.querySelectorAll('.selected').forEach((node) => node.classList.remove('selected'));
    selectedElement()?.classList.add('selected');
  }

  // The drawing-coordinates box of the selected element, to scroll it into view.
  function selectedBox() {
    const { selection, scene } = state;
    const layout = state.layouts.get(state.shown);
    if (!selection || !layout || !scene) return null;
    if (selection.kind === 'block') {
      const at = layout.positions.get(selection.id);
      const node = scene.nodes.get(selection.id);
      return at && node ? { x: at.x, y: at.y, width: node.geometry.width, height: node.geometry.height } : null;
    }
    const route = layout.routes.get(selection.id);
    if (!route) return null;
    const points = route.branches.flat();
    const xs = points.map((point) => point.x);
    const ys = points.map((point) => point.y);
    return { x: Math.min(...xs), y: Math.min(...ys), width: Math.max(...xs) - Math.min(...xs), height: Math.max(...ys) - Math.min(...ys) };
  }

  // --- navigation and selection

  function showSystem(path) {
    const target = nearestExistingSystem(state.index, path);
    if (target === state.shown && state.drawing) return Promise.resolve();
    state.views.set(state.shown, panZoom.view());
    state.shown = target;
    tooltip.hide();
    callbacks.onOpenSystem?.(target);
    return render();
  }

  // The system that draws a selection: a block's parent, a wire's own system.
  function systemOf(selection) {
    if (selection.kind === 'block') return state.index.blocks.has(selection.id) ? systemOfBlock(selection.id) : null;
    return state.index.wires.get(selection.id)?.system ?? null;
  }

  async function select(selection) {
    state.selection = selection;
    const system = selection ? systemOf(selection) : null;
    if (system !== null && system !== state.shown) await showSystem(system);
    applySelection();
    const box = selectedBox();
    if (box) panZoom.reveal(box);
  }

  function find(text) {
    const found = findInModel(state.index, text);
    if (found) select(found);
    return found;
  }

  function fit() {
    const layout = state.layouts.get(state.shown);
    if (layout) panZoom.fit(layout.box);
  }

  function relayout() {
    return render({ relayoutNow: true });
  }

  // --- pointer: select, open, hover

  const blockAt = (target) => target.closest?.('.block');
  const wireAt = (target) => target.closest?.('.wire');

  svg.addEventListener('click', (event) => {
    const block = blockAt(event.target);
    if (block && event.target.closest('.open-button')) {
      showSystem(block.dataset.id);
      return;
    }
    const wire = wireAt(event.target);
    let selection = null;
    if (block) selection = { kind: 'block', id: block.dataset.id };
    else if (wire && state.index.wires.has(wire.dataset.id)) selection = wireSelection(state.index.wires.get(wire.dataset.id));
    state.selection = selection;
    applySelection();
    callbacks.onSelect?.(selection);
  });
  svg.addEventListener('dblclick', (event) => {
    const block = blockAt(event.target);
    if (!block) return;
    const entry = state.index.blocks.get(block.dataset.id);
    if (entry?.block.system) showSystem(block.dataset.id);
    else if (entry) callbacks.onActivateBlock?.(block.dataset.id);
  });
  svg.addEventListener('pointerover', (event) => {
    const block = blockAt(event.target);
    if (block) {
      const entry = state.index.blocks.get(block.dataset.id);
      if (!entry) return;
      const description = describeBlock(entry.block, state.libraryByType.get(entry.block.type), state.index.parameters);
      const markers = markersInSystem(state.markers, state.shown).get(block.dataset.id) ?? [];
      tooltip.showBlock(description, markers, event.clientX, event.clientY);
      return;
    }
    const wire = wireAt(event.target);
    const entry = wire && state.index.wires.get(wire.dataset.id);
    if (entry) tooltip.showWire(entry.wire, event.clientX, event.clientY);
    else tooltip.hide();
  });
  svg.addEventListener('pointerleave', () => tooltip.hide());
  svg.addEventListener('pointerdown', () => tooltip.hide());

  // --- the API

  return {
    setModel(diagram, library, tasks) {
      // No diagram (the text does not read as a model): the last good drawing stays, dimmed.
      if (!diagram?.root) {
        container.classList.add('stale');
        return Promise.resolve();
      }
      state.diagram = diagram;
      state.index = indexDiagram(diagram);
      state.libraryByType = new Map((library ?? []).map((entry) => [entry.type, entry]));
      state.tasks = tasks ?? [];
      state.colourOf = taskColours(state.tasks);
      legend.update(state.tasks, [...state.index.blocks.values()].map((entry) => entry.block.task));
      // Layouts of systems that are gone are kept no longer.
      for (const path of state.layouts.keys()) if (!state.index.systems.has(path)) state.layouts.delete(path);
      const shown = nearestExistingSystem(state.index, state.shown);
      if (shown !== state.shown) {
        state.shown = shown;
        callbacks.onOpenSystem?.(shown);
      }
      if (state.selection && systemOf(state.selection) === null) state.selection = null;
      return render();
    },
    setStale(stale) {
      container.classList.toggle('stale', Boolean(stale));
    },
    showSystem,
    currentSystem: () => state.shown,
    select,
    setMarkers(markers) {
      state.markers = markers ?? new Map();
      applyMarkers();
    },
    setLiveValues(values) {
      liveLabels.setValues(values);
    },
    setLiveMode(on) {
      container.classList.toggle('live-off', !on);
      liveLabels.setEnabled(Boolean(on));
    },
    fit,
    zoomBy: (factor) => panZoom.zoomBy(factor),
    relayout,
    find,
    stats: () => ({ ...state.stats }),
    destroy() {
      state.renderCount += 1;
      container.replaceChildren();
      container.classList.remove('duet-diagram', 'live-off', 'stale');
    },
  };
}
