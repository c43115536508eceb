import { ChartStack } from './chart_stack.js';
import { Decimator } from './decimate.js';
import { groupByUnit } from './unit_groups.js';

const legend_refresh_ms = 250;

// The scope's plots: what is drawn (signals, window, pause, zoom) and when (at most once per
// animation frame, only when new data came or the view changed).
//
// Paused, the view draws from a snapshot taken at the pause, while the store keeps taking in
// samples; zooming and exporting then see a stable picture.
export class ScopeView {
  constructor(container, stats) {
    this.stats = stats;
    this.store = null;
    this.signals = []; // the plotted ones, described
    this.windowS = 10;
    this.paused = false;
    this.snapshot = null;
    this.zoom = null; // {min, max} seconds, or null for the latest window
    this.visible = false;
    this.#frameRequested = false;
    this.decimators = [];
    this.charts = new ChartStack(container, {
      syncKey: 'scope',
      xLabel: 'time [s]',
      onSelect: (plot) => this.#selected(plot),
      restingIndex: (plot) => plot.data[0].length - 1,
    });
    // Double-click (or double-tap) undoes the zoom; uPlot's own reset is to the drawn data only.
    container.addEventListener('dblclick', () => {
      this.zoom = null;
      this.requestDraw();
    });
  }

  #frameRequested;
  #legendRefreshed = 0;

  setStore(store) {
    this.store = store;
    this.snapshot = null;
    if (this.paused) this.snapshot = this.#takeSnapshot();
  }

  setSignals(signals) {
    this.signals = signals;
    const groups = groupByUnit(signals);
    this.decimators = groups.map(() => new Decimator());
    this.charts.setGroups(groups);
    this.requestDraw();
  }

  setWindow(seconds) {
    this.windowS = seconds;
    this.zoom = null;
    this.requestDraw();
  }

  setPaused(paused) {
    this.paused = paused;
    this.snapshot = paused ? this.#takeSnapshot() : null;
    if (!paused) this.zoom = null;
    this.requestDraw();
  }

  setVisible(visible) {
    this.visible = visible;
    if (visible) {
      this.charts.resize();
      this.requestDraw();
    }
  }

  // New samples: worth a frame only while live.
  dataArrived() {
    if (!this.paused) this.requestDraw();
  }

  requestDraw() {
    if (this.#frameRequested || !this.visible) return;
    this.#frameRequested = true;
    requestAnimationFrame(() => {
      this.#frameRequested = false;
      this.draw();
    });
  }

  // The data on screen: the snapshot when paused, else the store's live rings.
  source() {
    if (this.snapshot) return this.snapshot;
    if (!this.store) return null;
    return { time: this.store.time.view(), values: this.store.values.map((ring) => ring.view()) };
  }

  draw() {
    const source = this.source();
    if (!source || source.time.length === 0 || !this.visible) return;
    const latest = source.time[source.time.length - 1];
    const from = this.zoom ? this.zoom.min : latest - this.windowS;
    const to = this.zoom ? this.zoom.max : latest;
    // Newest values in the legends a few times a second: readable, and the text changes cost
    // layout and paint that every frame would pay for nothing.
    const now = performance.now();
    const refreshLegend = now - this.#legendRefreshed > legend_refresh_ms || this.paused;
    if (refreshLegend) this.#legendRefreshed = now;
    this.charts.charts.forEach(({ group, plot }, position) => {
      const columns = this.charts.plotWidth(plot);
      const values = group.signals.map((signal) => source.values[signal.index]);
      const data = this.decimators[position].decimate(source.time, values, from, to, columns);
      plot.batch(() => {
        plot.setData(data, false);
        plot.setScale('x', { min: from, max: to });
      });
      if (refreshLegend) this.charts.showRestingValues(plot);
    });
    if (refreshLegend) this.charts.alignAxes();
    this.stats.frames += 1;
  }

  #selected(plot) {
    const { left, width } = plot.select;
    plot.setSelect({ left: 0, top: 0, width: 0, height: 0 }, false);
    if (width < 3) return;
    // Zooming a moving picture is pointless: a drag pauses, then zooms.
    if (!this.paused) {
      this.setPaused(true);
      this.onPausedByZoom?.();
    }
    this.zoom = { min: plot.posToVal(left, 'x'), max: plot.posToVal(left + width, 'x') };
    this.requestDraw();
  }

  #takeSnapshot() {
    if (!this.store) return null;
    return { time: this.store.time.view().slice(), values: this.store.values.map((ring) => ring.view().slice()) };
  }
}
