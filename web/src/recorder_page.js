import { element, replaceChildren } from './dom.js';
import { ChartStack } from './chart_stack.js';
import { groupByUnit } from './unit_groups.js';
import { signalsCsv } from './csv.js';
import { downloadText, timestampForFile } from './download.js';
import { formatNumber } from './number_format.js';

// The Recorder page: arms the back end's triggered capture and plots what it sends back, on a
// time axis relative to the trigger (0 = the trigger, marked by a line).
export function createRecorderPage({ hub, connection, mdf4 }) {
  const form = document.getElementById('recorder-form');
  const signalSelect = document.getElementById('recorder-signal');
  const levelField = document.getElementById('recorder-level');
  const edgeSelect = document.getElementById('recorder-edge');
  const preField = document.getElementById('recorder-pre');
  const postField = document.getElementById('recorder-post');
  const stateText = document.getElementById('recorder-state');
  const settingsText = document.getElementById('recorder-settings');
  const captureInfo = document.getElementById('recorder-capture-info');
  const exportButton = document.getElementById('recorder-export');
  const mdf4Button = document.getElementById('recorder-mdf4');
  const message = document.getElementById('recorder-message');
  let signals = [];
  let capture = null;
  let shownCapture = null;
  let visible = false;

  const charts = new ChartStack(document.getElementById('recorder-plot'), {
    syncKey: 'recorder',
    xLabel: 'time from trigger [s]',
    xAuto: true,
    minHeight: 150,
    onDraw: drawTriggerLine,
    onSelect: zoomAll,
    restingIndex: (plot) => triggerIndex(plot.data[0]),
  });

  // A drag zooms every chart of the capture alike; a double-click resets (uPlot's own).
  function zoomAll(plot) {
    const { left, width } = plot.select;
    plot.setSelect({ left: 0, top: 0, width: 0, height: 0 }, false);
    if (width < 3) return;
    const range = { min: plot.posToVal(left, 'x'), max: plot.posToVal(left + width, 'x') };
    for (const chart of charts.charts) chart.plot.setScale('x', range);
  }

  const say = (text, tone = 'muted') => {
    message.textContent = text;
    message.className = `message ${tone}`;
  };

  hub.on('description', (description) => {
    const previous = signalSelect.value;
    signals = (description.telemetry ?? []).map((item, index) => ({ ...item, index }));
    replaceChildren(signalSelect, signals.map((signal) => element('option', { value: signal.name }, signal.unit ? `${signal.name} [${signal.unit}]` : signal.name)));
    if (signals.some((signal) => signal.name === previous)) signalSelect.value = previous;
    mdf4Button.hidden = !mdf4.available;
  });

  form.addEventListener('submit', (event) => {
    event.preventDefault();
    const request = {
      type: 'record',
      signal: signalSelect.value,
      level: levelField.valueAsNumber,
      edge: edgeSelect.value,
      pre_s: preField.valueAsNumber,
      post_s: postField.valueAsNumber,
    };
    for (const key of ['level', 'pre_s', 'post_s']) {
      if (!Number.isFinite(request[key])) return say(`${key.replace('_s', '-trigger time')} is not a number`, 'bad');
    }
    if (request.pre_s < 0 || request.post_s < 0) return say('times cannot be negative', 'bad');
    if (!connection.send(request)) return say('not connected', 'bad');
    say('arming…');
  });
  document.getElementById('recorder-cancel').addEventListener('click', () => {
    if (!connection.send({ type: 'cancel_record' })) say('not connected', 'bad');
  });

  hub.on('recorder', (recorder) => {
    stateText.textContent = recorder.state ?? 'unknown';
    stateText.className = `state ${recorder.state ?? ''}`;
    settingsText.textContent = recorder.signal
      ? `${recorder.signal} ${recorder.edge ?? ''} through ${formatNumber(recorder.level)}, ${formatNumber(recorder.pre_s)} s before, ${formatNumber(recorder.post_s)} s after`
      : '';
    say('');
  });
  hub.on('error', (error) => say(`back end: ${error.message}`, 'bad'));

  hub.on('capture', (next) => {
    capture = next;
    exportButton.disabled = false;
    mdf4Button.disabled = false;
    captureInfo.textContent = `${next.signal} ${next.edge} through ${formatNumber(next.level)} at ${formatNumber(next.trigger_time_s, 9)} s, ${next.time_s?.length ?? 0} samples`;
    if (visible) plotCapture();
  });

  exportButton.addEventListener('click', () => {
    if (!capture) return;
    const columns = capturedSignals(capture).map((signal) => ({ name: signal.name, unit: signal.unit, values: capture.values[signal.index] }));
    downloadText(`capture-${capture.signal}-${timestampForFile()}.csv`, signalsCsv(capture.time_s, columns), 'text/csv');
  });

  // The back end keeps the capture it sent last and writes it; this page shows that capture too.
  mdf4Button.addEventListener('click', async () => {
    mdf4Button.disabled = true;
    say('writing the MDF4 file…');
    const { ok, message: result } = await mdf4.recorder();
    mdf4Button.disabled = false;
    say(result, ok ? 'muted' : 'bad');
  });

  function capturedSignals(which) {
    return signals.filter((signal) => Array.isArray(which.values?.[signal.index]));
  }

  // Charts are made while the page shows, so they get its real size.
  function plotCapture() {
    if (!capture || shownCapture === capture) return;
    shownCapture = capture;
    const captured = capturedSignals(capture);
    charts.setGroups(groupByUnit(captured));
    const trigger = capture.trigger_time_s ?? 0;
    const time = Float64Array.from(capture.time_s, (t) => t - trigger);
    for (const { group, plot } of charts.charts) {
      plot.setData([time, ...group.signals.map((signal) => capture.values[signal.index].map((v) => (typeof v === 'number' ? v : null)))]);
      charts.showRestingValues(plot);
    }
    charts.alignAxes();
    document.getElementById('recorder-plot').dataset.captured = String(time.length);
  }

  return {
    show() {
      visible = true;
      charts.resize();
      plotCapture();
    },
    hide() {
      visible = false;
    },
  };
}

// The first sample at or after the trigger (time 0 on the capture's axis).
function triggerIndex(time) {
  if (!time || time.length === 0) return null;
  const index = time.findIndex((t) => t >= 0);
  return index < 0 ? time.length - 1 : index;
}

// The trigger instant (x = 0) as a dashed vertical line across the plotting area.
function drawTriggerLine(plot) {
  const x = plot.valToPos(0, 'x', true);
  const { left, top, width, height } = plot.bbox;
  if (!(x >= left && x <= left + width)) return;
  const context = plot.ctx;
  context.save();
  context.strokeStyle = '#c0392b';
  context.lineWidth = Math.max(1, window.devicePixelRatio || 1);
  context.setLineDash([6, 4]);
  context.beginPath();
  context.moveTo(x, top);
  context.lineTo(x, top + height);
  context.stroke();
  context.restore();
}
