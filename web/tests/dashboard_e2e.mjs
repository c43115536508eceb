#!/usr/bin/env node
// The dashboard end to end, against a back end (real or the mock): tunes a parameter, watches a
// signal on the scope, takes a triggered capture, and screenshots every page.
//
//   node tests/dashboard_e2e.mjs --url http://127.0.0.1:PORT/ --artefacts DIR
//        [--parameter P --value 0.05] [--signal theta] [--trigger-level 0|auto] [--timeout-s 30] [--expect-tasks yes]
//        [--plant push|none] [--mdf4 save|none]
//
// --plant push: a simulated plant is behind the target; the Disturb box pushes it (a value out of limits is refused
// on the page first) and restarts it, each answered with its model time. --plant none: the page shows no Disturb box.
// --mdf4 save: the Scope's and the Recorder's "Save as MDF4" download MDF files from the back end; --mdf4 none: the
// buttons are hidden (a back end that writes no MDF4, the mock).
// Prints one JSON line of results; exits 0 when every check passed, 1 naming the failed step.
import { mkdir, readFile } from 'node:fs/promises';
import path from 'node:path';
import { launchChromium, parseOptions, waitFor } from './browser.mjs';

const usage = 'usage: dashboard_e2e.mjs --url URL --artefacts DIR [--parameter P] [--value V] [--signal NAME] [--trigger-level L|auto] [--timeout-s S] [--expect-tasks yes] [--plant push|none] [--mdf4 save|none]';
const options = parseOptions(process.argv.slice(2), { url: '', artefacts: '', parameter: 'P', value: '0.05', signal: 'theta', 'trigger-level': '0', 'timeout-s': '30', 'expect-tasks': 'no', plant: '', mdf4: '' }, usage);
if (!options.url || !options.artefacts) {
  console.error(usage);
  process.exit(2);
}
const timeoutMs = Number(options['timeout-s']) * 1000;
const requested = Number(options.value);
const results = { url: options.url };
let step = 'launching Chromium';

const browser = await launchChromium();
const context = await browser.newContext({ viewport: { width: 480, height: 800 }, hasTouch: true, acceptDownloads: true });
const page = await context.newPage();
const pageErrors = [];
page.on('pageerror', (error) => pageErrors.push(error.message));
const shot = (name) => page.screenshot({ path: path.join(options.artefacts, name) });
const openTab = async (name) => {
  await page.click(`[data-tab="${name}"]`);
  await page.waitForSelector(`#page-${name}:not([hidden])`);
};

try {
  await mkdir(options.artefacts, { recursive: true });

  step = 'loading the page and receiving the description';
  await page.goto(options.url, { timeout: timeoutMs });
  await page.waitForSelector(`input[type=number][data-parameter="${options.parameter}"]`, { timeout: timeoutMs });
  // Remember every recorder state the page is told about, however short-lived.
  // And the latest values of every telemetry signal, by its place in the description (the scope's order), so that
  // `--trigger-level auto` can take a level the signal keeps crossing: the median of its last 200 values.
  await page.evaluate(() => {
    window.e2eRecorderStates = [];
    window.e2eRecent = [];
    const keep = (index, value) => {
      const recent = (window.e2eRecent[index] ??= []);
      recent.push(value);
      if (recent.length > 200) recent.shift();
    };
    window.duet.onMessage = (message) => {
      if (message.type === 'recorder') window.e2eRecorderStates.push(message.state);
      if (message.type === 'telemetry') message.values.forEach((value, index) => keep(index, value));
      if (message.type === 'samples') message.values.forEach((column, index) => column.forEach((value) => keep(index, value)));
    };
  });

  step = `writing ${options.parameter} = ${requested}`;
  await openTab('tuning');
  await page.waitForFunction((name) => document.querySelector(`[data-target-value="${name}"]`)?.dataset.value !== undefined, options.parameter, { timeout: timeoutMs });
  const targetReads = (value) =>
    waitFor(`the target's ${options.parameter} to read ${value}`, timeoutMs, async () => {
      const shown = Number(await page.getAttribute(`[data-target-value="${options.parameter}"]`, 'data-value'));
      return sameAsFloat32(shown, value) ? { value: shown } : null;
    });
  const writeRequested = async () => {
    await moveSlider(page, options.parameter, requested);
    const writeButton = page.locator(`button[data-write="${options.parameter}"]`);
    if (await writeButton.isDisabled()) throw new Error(`Write stayed disabled after setting ${requested} (already the target's value?)`);
    await writeButton.click();
    return targetReads(requested);
  };
  const original = Number(await page.getAttribute(`[data-target-value="${options.parameter}"]`, 'data-value'));
  await writeRequested();

  step = `undoing the write of ${options.parameter}, then writing it again`;
  await page.click(`button[data-undo="${options.parameter}"]`);
  await targetReads(original);
  const target = await writeRequested();
  results.parameter_written = { name: options.parameter, requested, target: target.value, undone_to: original };
  if (options.plant === 'push') results.plant = await disturbThePlant(page, timeoutMs);
  if (options.plant === 'none') {
    step = 'checking that no Disturb box is shown';
    if (await page.isVisible('#plant-controls')) throw new Error('a Disturb box shows without a plant behind the target');
  }
  await shot('tuning.png');

  step = `plotting ${options.signal} on the scope`;
  await openTab('scope');
  const box = page.locator(`input[data-signal="${options.signal}"]`);
  if ((await box.count()) === 0) throw new Error(`no signal named ${options.signal} in the description`);
  if (!(await box.isChecked())) {
    await page.click('.signal-picker summary');
    await box.check();
  }
  const before = await page.evaluate(() => ({ ...window.duet.stats }));
  await page.waitForTimeout(1500);
  const after = await page.evaluate(() => ({ ...window.duet.stats }));
  if (after.samples <= before.samples) throw new Error(`no samples arrived in 1.5 s (${after.samples} in all)`);
  if (after.frames <= before.frames) throw new Error(`the scope did not redraw in 1.5 s (${after.frames} frames in all)`);
  const legend = await page.locator('#scope-plot .u-legend').allTextContents();
  if (!legend.some((text) => text.includes(options.signal))) throw new Error(`${options.signal} is not in the scope's legend`);
  results.samples = after.samples;
  results.frames = after.frames;
  results.frames_per_s = Math.round(((after.frames - before.frames) / 1.5) * 10) / 10;
  if (options.mdf4) results.scope_mdf4 = await saveAsMdf4(page, '#scope-mdf4', options.mdf4);
  await shot('scope.png');
  await page.setViewportSize({ width: 1280, height: 800 });
  await page.waitForTimeout(600);
  await shot('scope_desktop.png');
  await page.setViewportSize({ width: 480, height: 800 });

  // `auto`: the median of the signal's last 20 values, a level it crosses again soon unless it drifts away; if it
  // has not within a third of the time allowed, the recorder is armed again at the level of then.
  const automatic = options['trigger-level'] === 'auto';
  const levelNow = () =>
    page.evaluate((name) => {
      const names = [...document.querySelectorAll('input[data-signal]')].map((box) => box.dataset.signal);
      const recent = (window.e2eRecent[names.indexOf(name)] ?? []).slice(-20).sort((a, b) => a - b);
      return recent.length > 0 ? recent[Math.floor(recent.length / 2)] : NaN;
    }, options.signal);
  step = `capturing ${options.signal} through ${options['trigger-level']}`;
  await openTab('recorder');
  await page.selectOption('#recorder-signal', options.signal);
  await page.selectOption('#recorder-edge', 'either');
  await page.fill('#recorder-pre', '0.5');
  await page.fill('#recorder-post', '1');
  const attempts = automatic ? 3 : 1;
  for (let attempt = 1; ; attempt += 1) {
    const level = automatic ? await levelNow() : Number(options['trigger-level']);
    if (!Number.isFinite(level)) throw new Error(`no values of ${options.signal} to choose a trigger level from`);
    results.trigger_level = level;
    step = `capturing ${options.signal} through ${level}`;
    await page.fill('#recorder-level', String(level));
    await page.click('#recorder-arm');
    try {
      await waitFor('the recorder to trigger', timeoutMs / attempts, () =>
        page.evaluate(() => window.e2eRecorderStates.includes('triggered')),
      );
      break;
    } catch (error) {
      if (attempt === attempts) throw error;
    }
  }
  const captured = await waitFor('a plotted capture', timeoutMs, async () => Number(await page.getAttribute('#recorder-plot', 'data-captured')) || 0);
  if ((await page.locator('#recorder-plot canvas').count()) === 0) throw new Error('the capture has no chart');
  results.captured = captured;
  results.recorder_state = await page.textContent('#recorder-state');
  if (options.mdf4) results.recorder_mdf4 = await saveAsMdf4(page, '#recorder-mdf4', options.mdf4);
  await shot('recorder.png');

  step = 'showing the status';
  await openTab('status');
  await page.waitForSelector('#status-tasks tbody tr, #status-counters table', { timeout: timeoutMs });
  if (options['expect-tasks'] === 'yes') {
    step = "showing the executive's task table";
    await page.waitForSelector('#status-tasks tbody tr', { timeout: timeoutMs });
    results.tasks = await page.locator('#status-tasks tbody tr').count();
  }
  results.link = await page.textContent('#status-link');
  await shot('status.png');

  step = 'checking for script errors';
  if (pageErrors.length > 0) throw new Error(pageErrors.join('; '));
  results.ok = true;
  console.log(JSON.stringify(results));
  await browser.close();
  process.exit(0);
} catch (error) {
  results.ok = false;
  results.failed_step = step;
  results.error = error.message.split('\n')[0];
  if (pageErrors.length > 0) results.page_errors = pageErrors;
  await page.screenshot({ path: path.join(options.artefacts, 'failure.png') }).catch(() => {});
  console.log(JSON.stringify(results));
  console.error(`dashboard_e2e: failed ${step}: ${results.error}`);
  await browser.close();
  process.exit(1);
}

// The Disturb box: a push out of limits is refused on the page; a push and a restart are answered with the model time
// they act from, the restart's no earlier than the push's.
// `save`: the button downloads an MDF file (its name and size); `none`: the button is hidden.
async function saveAsMdf4(page, button, expected) {
  step = `${expected === 'save' ? 'saving' : 'not offering'} an MDF4 file (${button})`;
  if (expected === 'none') {
    if (await page.isVisible(button)) throw new Error(`${button} shows, though the back end writes no MDF4`);
    return 'hidden';
  }
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: 20000 }), page.click(button)]);
  const file = await download.path();
  const bytes = await readFile(file);
  const identification = bytes.subarray(0, 8).toString('latin1');
  if (identification !== 'MDF     ') throw new Error(`${download.suggestedFilename()} starts with "${identification}", not "MDF     "`);
  if (!download.suggestedFilename().endsWith('.mf4')) throw new Error(`the file is named ${download.suggestedFilename()}`);
  return { name: download.suggestedFilename(), bytes: bytes.length };
}

async function disturbThePlant(page, timeoutMs) {
  step = 'showing the Disturb box';
  await page.waitForSelector('#plant-controls:not([hidden]) [data-plant-action="push"]', { timeout: timeoutMs });
  const applied = async (action, after) => {
    await page.click(`[data-plant-action="${action}"]`);
    return waitFor(`${action} to be applied`, timeoutMs, async () => {
      const last = await page.$eval('#plant-last', (node) => ({ action: node.dataset.action, time: Number(node.dataset.timeS), text: node.textContent }));
      return last.action === action && last.time > after ? last : null;
    });
  };
  step = 'pushing with a force out of limits';
  await page.fill('[data-plant-argument="push.force_n"]', '500');
  await page.click('[data-plant-action="push"]');
  const refused = await page.textContent('#plant-last');
  if (!refused.includes('outside')) throw new Error(`a 500 N push was not refused on the page: "${refused}"`);
  step = 'pushing the plant';
  await page.fill('[data-plant-argument="push.force_n"]', '3');
  const push = await applied('push', 0);
  step = 'restarting the plant';
  const restart = await applied('restart', push.time - 1e-9);
  return { push_time_s: push.time, restart_time_s: restart.time, last: restart.text };
}

// The slider, as a user would leave it: value set, then input and change fired. When the value is
// off the slider's step grid it would snap, so the number field takes it instead.
async function moveSlider(page, name, value) {
  const landed = await page.evaluate(
    ({ name, value }) => {
      const slider = document.querySelector(`input[type=range][data-parameter="${name}"]`);
      if (!slider) return null;
      slider.value = String(value);
      slider.dispatchEvent(new Event('input', { bubbles: true }));
      slider.dispatchEvent(new Event('change', { bubbles: true }));
      return Number(slider.value);
    },
    { name, value },
  );
  if (landed === null || !sameAsFloat32(landed, value)) await page.fill(`input[type=number][data-parameter="${name}"]`, String(value));
  const field = Number(await page.inputValue(`input[type=number][data-parameter="${name}"]`));
  if (!sameAsFloat32(field, value)) throw new Error(`the number field shows ${field}, not ${value}`);
}

function sameAsFloat32(a, b) {
  return Number.isFinite(a) && (Math.fround(a) === Math.fround(b) || Math.abs(a - b) <= 1e-6 * Math.max(1, Math.abs(b)));
}
