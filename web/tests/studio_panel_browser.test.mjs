// The three studio panels in headless Chromium, fed recorded-style messages through a fake hub
// and connection (the studio server is not needed): what they send, what they show, and the
// live values' rate to the diagram. Skipped where there is no Chromium.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync } from 'node:fs';
import { copyFile, mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'esbuild';
import { chromium_path, launchChromium, waitFor } from './browser.mjs';

const web = path.dirname(path.dirname(fileURLToPath(import.meta.url)));
const no_chromium = !existsSync(chromium_path) && `no Chromium at ${chromium_path}`;

// The page: each panel in a box the size of a bottom tab, the fakes on window.harness.
const harness = `
import { EventHub } from './src/event_hub.js';
import { createLivePanel } from './src/studio/panels/live_panel.js';
import { createSimulationPanel } from './src/studio/panels/simulation_panel.js';
import { createGeneratePanel } from './src/studio/panels/generate_panel.js';
const hub = new EventHub();
const sent = [];
const connection = { send: (request) => (sent.push(request), true) };
const diagram = { values: [], modes: [] };
const view = { setLiveValues: (values) => diagram.values.push(values), setLiveMode: (on) => diagram.modes.push(on) };
const studio = {
  file: 'balbot.yaml',
  plants: [{ name: 'none', description: 'no plant' }, { name: 'balbot', description: 'the robot' }],
  files: ['balbot.yaml', 'heater.yaml', 'disturbed.yaml'],
  defaults: { plant: 'balbot', scenario: 'disturbed.yaml', duration_s: 5, xcp: '' },
};
const common = { hub, connection, getText: () => 'name: demo\\n', studio, view };
const live = createLivePanel({ ...common, element: document.getElementById('live') });
const simulation = createSimulationPanel({ ...common, element: document.getElementById('simulation') });
createGeneratePanel({ ...common, element: document.getElementById('generate') });
// 1 kHz DAQ in 20 ms blocks, as duet monitor sends it.
let daq = 0;
function startDaq() {
  let t = 0;
  daq = setInterval(() => {
    const time_s = [];
    const values = [[], [], [], []];
    for (let i = 0; i < 20; i += 1) {
      t += 0.001;
      time_s.push(t);
      values[0].push(Math.sin(t));
      values[1].push(0.02);
      values[2].push(0.5);
      values[3].push(11.7);
    }
    hub.emit('samples', { type: 'samples', time_s, values });
  }, 20);
}
window.harness = { hub, sent, diagram, live, simulation, startDaq, stopDaq: () => clearInterval(daq) };
`;

const page_html = `<!doctype html><html><head><meta charset="utf-8">
<link rel="stylesheet" href="uPlot.min.css"><link rel="stylesheet" href="theme.css"><link rel="stylesheet" href="charts.css"><link rel="stylesheet" href="panels.css">
<style>.tab { width: 1000px; height: 340px; }</style><script src="harness.js" defer></script></head>
<body><div class="tab" id="live"></div><div class="tab" id="simulation"></div><div class="tab" id="generate"></div></body></html>`;

let folder;
let browser;
let page;
const errors = [];

before(async () => {
  if (no_chromium) return;
  folder = await mkdtemp(path.join(tmpdir(), 'studio-panels-'));
  await build({ stdin: { contents: harness, resolveDir: web, sourcefile: 'harness.js' }, outfile: path.join(folder, 'harness.js'), bundle: true, format: 'iife', logLevel: 'warning' });
  await writeFile(path.join(folder, 'index.html'), page_html);
  await copyFile(path.join(web, 'node_modules/uplot/dist/uPlot.min.css'), path.join(folder, 'uPlot.min.css'));
  for (const sheet of ['theme.css', 'charts.css']) await copyFile(path.join(web, 'src', sheet), path.join(folder, sheet));
  await copyFile(path.join(web, 'src/studio/panels/panels.css'), path.join(folder, 'panels.css'));
  browser = await launchChromium();
  page = await browser.newPage({ viewport: { width: 1040, height: 1100 } });
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto(`file://${folder}/index.html`);
  await page.waitForFunction(() => window.harness);
});

after(async () => {
  await browser?.close();
  if (folder) await rm(folder, { recursive: true, force: true });
  assert.deepEqual(errors, []);
});

const description = {
  type: 'description',
  application: 'balbot',
  backend: 'monitor',
  telemetry_period_us: 1000,
  telemetry: [{ name: 'theta', unit: 'deg' }, { name: 'linux_gains[0]' }, { name: 'linux_gains[1]' }, { name: 'battery', unit: 'V' }],
  parameters: [{ name: 'P', type: 'float32', min: 0, max: 1 }],
};

test('live: connect, the wires get values at 20 Hz, the scope plots, parameters read back', { skip: no_chromium }, async () => {
  await page.click('#live button.primary');
  assert.deepEqual(await page.evaluate(() => window.harness.sent.at(-1)), { type: 'connect', address: 'tcp://127.0.0.1:5555' });
  await page.evaluate((message) => {
    const { hub, live, startDaq } = window.harness;
    hub.emit('external', { type: 'external', state: 'open', address: 'tcp://127.0.0.1:5555' });
    live.scope('linux_gains'); // before the description: kept until it comes
    hub.emit('description', message);
    hub.emit('parameter', { type: 'parameter', index: 0, name: 'P', value: 0.025, status: 'reported' });
    startDaq();
  }, description);
  await page.waitForTimeout(2000);
  const seen = await page.evaluate(() => {
    const { live, diagram } = window.harness;
    live.scope('theta');
    const last = diagram.values.at(-1);
    return { stats: { ...live.stats }, connected: live.connected, modes: diagram.modes, last: Object.fromEntries(last), P: live.parameter('P'), chips: [...document.querySelectorAll('#live .plotted-chip')].map((chip) => chip.dataset.signal) };
  });
  assert.equal(seen.connected, true);
  assert.deepEqual(seen.modes, [true]);
  assert.ok(seen.stats.samples >= 500, `samples: ${seen.stats.samples}`);
  // 20 Hz over 2 s at most (timers run late on a busy machine, never early): not once per block
  // (50 Hz), nor stopped.
  assert.ok(seen.stats.liveUpdates >= 15 && seen.stats.liveUpdates <= 42, `live updates: ${seen.stats.liveUpdates}`);
  assert.ok(seen.stats.lastLiveUpdateMs > 0);
  assert.deepEqual(Object.keys(seen.last), ['theta', 'linux_gains', 'battery']);
  assert.deepEqual(seen.last.linux_gains, [0.02, 0.5]);
  assert.deepEqual(seen.P, { value: 0.025, status: 'reported' });
  assert.deepEqual(seen.chips, ['linux_gains[0]', 'linux_gains[1]', 'theta']);
  assert.ok(seen.stats.frames > 5, `scope frames: ${seen.stats.frames}`);

  const written = await page.evaluate(() => {
    const { hub, live, sent } = window.harness;
    const answers = [];
    live.onParameter = (name, answer) => answers.push([name, answer]);
    const ok = live.write('P', 0.05);
    hub.emit('parameter', { type: 'parameter', index: 0, name: 'P', value: 0.05, status: 'applied' });
    return { ok, request: sent.at(-1), answers, P: live.parameter('P') };
  });
  assert.equal(written.ok, true);
  assert.deepEqual(written.request, { type: 'set', name: 'P', value: 0.05 });
  assert.deepEqual(written.answers, [['P', { value: 0.05, status: 'applied', message: undefined }]]);
  assert.deepEqual(written.P, { value: 0.05, status: 'applied' });
});

test('live: a hidden tab draws nothing; closing ends live mode and the updates', { skip: no_chromium }, async () => {
  const frames = await page.evaluate(async () => {
    const node = document.getElementById('live');
    node.hidden = true; // as the shell's bottom tabs hide a panel
    await new Promise((resolve) => setTimeout(resolve, 200));
    const before = window.harness.live.stats.frames;
    await new Promise((resolve) => setTimeout(resolve, 500));
    const hidden = window.harness.live.stats.frames - before;
    node.hidden = false;
    await new Promise((resolve) => setTimeout(resolve, 500));
    return { hidden, shown: window.harness.live.stats.frames - before - hidden };
  });
  assert.equal(frames.hidden, 0);
  assert.ok(frames.shown > 1, `frames once shown again: ${frames.shown}`);
  const closed = await page.evaluate(async () => {
    const { hub, live, diagram, stopDaq } = window.harness;
    hub.emit('external', { type: 'external', state: 'closed', address: 'tcp://127.0.0.1:5555', problem: 'connection refused' });
    const updates = live.stats.liveUpdates;
    await new Promise((resolve) => setTimeout(resolve, 300));
    stopDaq();
    return { modes: diagram.modes, more: live.stats.liveUpdates - updates, connected: live.connected, state: document.querySelector('#live .external-state').textContent, problem: document.querySelector('#live .external-problem').textContent, write: live.write('P', 0.1) };
  });
  assert.deepEqual(closed.modes, [true, false]);
  assert.equal(closed.more, 0);
  assert.equal(closed.connected, false);
  assert.match(closed.state, /^closed/);
  assert.equal(closed.problem, 'connection refused');
  assert.equal(closed.write, false);
});

function fakeSimulation(id, points, names, extra = {}) {
  const time_s = Array.from({ length: points }, (_, i) => i * 0.001);
  return { type: 'simulation', id, names, units: names.map((name) => (name.startsWith('u') ? 'V' : 'deg')), time_s, columns: names.map((_, c) => time_s.map((t) => Math.sin(t * (c + 1)))), decimated_by: 1, cancelled: false, ...extra };
}

test('simulation: Run sends the request, progress shows, the result is plotted, a wire adds its columns', { skip: no_chromium }, async () => {
  await page.click('#simulation button.primary');
  assert.deepEqual(await page.evaluate(() => window.harness.sent.at(-1)), { type: 'simulate', text: 'name: demo\n', id: 1, duration_s: 5, plant: 'balbot', scenario: 'disturbed.yaml' });
  await page.evaluate(() => window.harness.hub.emit('simulation_progress', { type: 'simulation_progress', id: 1, fraction: 0.5 }));
  assert.equal(await page.$eval('#simulation progress', (bar) => bar.value), 0.5);
  await page.evaluate((result) => window.harness.hub.emit('simulation', result), fakeSimulation(1, 20000, ['theta', 'rate', 'u[0]', 'u[1]', 'x', 'y', 'z']));
  const plotted = async () => page.$$eval('#simulation .plotted-chip', (chips) => chips.map((chip) => chip.dataset.signal));
  assert.deepEqual(await plotted(), ['theta', 'rate', 'u[0]', 'u[1]']);
  await waitFor('the simulation charts', 2000, () => page.$$eval('#simulation .uplot', (charts) => charts.length === 2));
  await page.evaluate(() => window.harness.simulation.plotSignal('z'));
  assert.deepEqual(await plotted(), ['theta', 'rate', 'u[0]', 'u[1]', 'z']);
  // A cancelled run shows what came; its columns keep the plotted choice where they can.
  await page.click('#simulation button.primary');
  await page.evaluate((result) => window.harness.hub.emit('simulation', result), fakeSimulation(2, 300, ['theta', 'rate'], { cancelled: true }));
  assert.deepEqual(await plotted(), ['theta', 'rate']);
  assert.match(await page.$eval('#simulation .panel-message', (node) => node.textContent), /cancelled/);
  await page.click('#simulation button.primary');
  await page.evaluate(() => window.harness.hub.emit('error', { type: 'error', request: 'simulate', message: 'unknown plant' }));
  assert.match(await page.$eval('#simulation .panel-message', (node) => node.textContent), /unknown plant/);
  assert.equal(await page.$eval('#simulation button.primary', (button) => button.disabled), false);
  // The page's socket lost during a run: Run is offered again.
  await page.click('#simulation button.primary');
  await page.evaluate(() => window.harness.hub.emit('link', { name: 'waiting', retryInMs: 500 }));
  assert.equal(await page.$eval('#simulation button.primary', (button) => button.disabled), false);
  assert.match(await page.$eval('#simulation .panel-message', (node) => node.textContent), /lost/);
});

test('generated: the files, a file text, the tasks, the verdict', { skip: no_chromium }, async () => {
  await page.click('#generate button.primary');
  assert.deepEqual(await page.evaluate(() => window.harness.sent.at(-1)), { type: 'generate', text: 'name: demo\n', wcet_us: {}, interarrival_us: {} });
  await page.evaluate(() =>
    window.harness.hub.emit('generated', {
      type: 'generated',
      files: [{ name: 'm.hpp', text: '#pragma once\n' }, { name: 'm.cpp', text: '#include "m.hpp"\n' }],
      tasks: [{ index: 0, name: 'base', function: 'step_rate_1', kind: 'periodic', period_us: 1000, blocks: 4 }, { index: 1, name: 'isr', function: 'task_EXTI0', kind: 'interrupt', interrupt: 'EXTI0', priority: 2, blocks: 1 }],
      schedulability: { verdict: 'not schedulable', schedulable: false, report: 'base overruns' },
    }),
  );
  await page.click('#generate .file-list li:nth-child(2) button');
  const shown = await page.evaluate(() => ({
    files: [...document.querySelectorAll('#generate .file-name')].map((node) => node.textContent),
    text: document.querySelector('#generate .file-text').textContent,
    rows: [...document.querySelectorAll('#generate tbody tr')].map((row) => [...row.cells].map((cell) => cell.textContent)),
    verdict: document.querySelector('#generate .verdict').className,
    report: document.querySelector('#generate .report').textContent,
  }));
  assert.deepEqual(shown.files, ['m.hpp', 'm.cpp']);
  assert.equal(shown.text, '#include "m.hpp"\n');
  assert.deepEqual(shown.rows, [['base', 'periodic', '1 ms', '4', '', ''], ['isr', 'interrupt', 'EXTI0, priority 2', '1', '', '']]);
  assert.equal(shown.verdict, 'verdict bad');
  assert.equal(shown.report, 'base overruns');
  // The times the verdict needs, given in the table, go with the next request; a cleared or bad one does not.
  await page.fill('#generate input[data-task="step_rate_1"][data-time="wcet_us"]', '20');
  await page.fill('#generate input[data-task="task_EXTI0"][data-time="wcet_us"]', '5');
  await page.fill('#generate input[data-task="task_EXTI0"][data-time="interarrival_us"]', '1000');
  await page.fill('#generate input[data-task="task_EXTI0"][data-time="wcet_us"]', '');
  assert.equal(await page.$('#generate input[data-task="step_rate_1"][data-time="interarrival_us"]'), null, 'a periodic task has no interarrival time');
  await page.click('#generate button.primary');
  assert.deepEqual(await page.evaluate(() => window.harness.sent.at(-1)), { type: 'generate', text: 'name: demo\n', wcet_us: { step_rate_1: 20 }, interarrival_us: { task_EXTI0: 1000 } });
});
