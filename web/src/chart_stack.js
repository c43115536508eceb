import uPlot from 'uplot';
import { colourFor } from './palette.js';
import { formatNumber } from './number_format.js';

// Wide containers put each chart's legend (the cursor readout) beside the chart, narrow ones
// under it: height is what a stack of charts runs short of first.
const legend_beside_from_px = 760;
const legend_beside_width_px = 230;

// A column of uPlot charts, one per group of signals (see unit_groups.js), sharing the cursor and
// filling their container: each chart gets an equal share of the height, at least `minHeight`,
// and follows the container's size through a ResizeObserver.
//
// `restingIndex(plot)` names the data point the legend shows while no cursor is on the chart
// (the newest sample on the scope), so the readout is useful on a touch screen too.
export class ChartStack {
  #observer;

  constructor(container, { syncKey, xLabel, xAuto = false, minHeight = 140, onSelect, onDraw, restingIndex }) {
    this.container = container;
    this.options = { syncKey, xLabel, xAuto, minHeight, onSelect, onDraw, restingIndex };
    this.charts = []; // {group, plot}
    this.#observer = new ResizeObserver(() => this.resize());
    this.#observer.observe(container);
  }

  // Shows the resting values in a chart's legend, unless a cursor is on it.
  showRestingValues(plot) {
    const index = this.options.restingIndex?.(plot);
    if (index !== undefined && index !== null && index >= 0 && !(plot.cursor.left >= 0)) plot.setLegend({ idx: index });
  }

  // Every chart's y axis as wide as the widest one's, so their time axes line up. Only grows
  // while a stack lives: a width that shrank back and forth would make the plots jitter.
  #axisWidth = (plot, values, axisIndex, cycleNumber) => {
    if (cycleNumber > 1) return plot.axes[axisIndex]._size; // settle instead of oscillating
    this.#widestAxis = Math.max(this.#widestAxis, wantedAxisWidth(plot, values, axisIndex));
    return this.#widestAxis;
  };

  #widestAxis = 0;

  // Redraws the charts whose y axis is narrower than the widest (after all got data once).
  alignAxes() {
    for (const { plot } of this.charts) if (plot.axes[1]._size !== this.#widestAxis) plot.redraw(false, true);
  }

  setGroups(groups) {
    for (const { plot } of this.charts) plot.destroy();
    this.#widestAxis = 0;
    this.container.replaceChildren();
    const size = this.#chartSize(groups.length);
    this.charts = groups.map((group, position) => {
      const holder = document.createElement('div');
      holder.className = 'chart';
      this.container.append(holder);
      const isLast = position === groups.length - 1;
      const plot = new uPlot(this.#plotOptions(group, size, isLast), [[], ...group.signals.map(() => [])], holder);
      return { group, plot };
    });
    // The legend's height is only known once drawn; size again with it.
    this.resize();
  }

  // The plotting area's width in CSS pixels: one decimated column per pixel.
  plotWidth(plot) {
    return Math.max(1, Math.round(plot.bbox.width / (window.devicePixelRatio || 1)));
  }

  resize() {
    if (this.charts.length === 0 || this.container.clientWidth === 0) return;
    const size = this.#chartSize(this.charts.length);
    for (const { plot } of this.charts) {
      if (plot.width !== size.width || plot.height !== size.height) plot.setSize(size);
    }
  }

  #chartSize(count) {
    const beside = this.container.clientWidth >= legend_beside_from_px;
    this.container.classList.toggle('legend-beside', beside);
    const width = Math.max(200, this.container.clientWidth - 2 - (beside ? legend_beside_width_px : 0));
    const legend = beside ? 0 : (this.charts[0]?.plot.root.querySelector('.u-legend')?.offsetHeight ?? 24);
    const share = Math.floor(this.container.clientHeight / Math.max(1, count)) - legend - 6;
    // Beside their legends, charts can be lower and still read well.
    const minimum = beside ? Math.round(this.options.minHeight * 0.8) : this.options.minHeight;
    return { width, height: Math.max(minimum, share) };
  }

  #plotOptions(group, size, isLast) {
    const { syncKey, xLabel, xAuto, onSelect, onDraw } = this.options;
    const font = '12px system-ui, sans-serif';
    return {
      ...size,
      scales: { x: { time: false, auto: xAuto } },
      legend: { live: true },
      cursor: {
        sync: syncKey ? { key: syncKey } : undefined,
        drag: { x: true, y: false, setScale: false },
        points: { size: 6 },
        y: false, // a horizontal crosshair means nothing across charts of different units
      },
      series: [
        { label: xLabel, value: (plot, value) => (value == null ? '—' : value.toFixed(3)) },
        ...group.signals.map((signal) => ({
          label: signal.unit ? `${signal.name} [${signal.unit}]` : signal.name,
          stroke: colourFor(signal.index),
          width: 1,
          points: { show: false },
          value: (plot, value) => (value == null ? '—' : formatNumber(value, 5)),
        })),
      ],
      axes: [
        { font, size: isLast ? 36 : 28, label: isLast ? xLabel : undefined, labelSize: 16, labelFont: font, grid: { stroke: '#e8e8e8' } },
        // Short charts still get three or more ticks: 20 px between them is enough for 12 px text.
        { font, label: group.unit || undefined, labelSize: 16, labelFont: font, space: 20, size: this.#axisWidth, grid: { stroke: '#e8e8e8' } },
      ],
      hooks: {
        setSelect: onSelect ? [(plot) => onSelect(plot)] : [],
        draw: onDraw ? [(plot) => onDraw(plot)] : [],
        setCursor: [(plot) => this.showRestingValues(plot)],
      },
    };
  }
}

// Room for the widest tick label, so long numbers are not clipped and short ones waste no width.
function wantedAxisWidth(plot, values, axisIndex) {
  const longest = (values ?? []).reduce((most, text) => Math.max(most, String(text).length), 0);
  return Math.ceil(longest * 7 + 18 + (plot.axes[axisIndex].label ? 16 : 0));
}
