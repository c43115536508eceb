#!/usr/bin/env node
// The thesis' tuning story on the bridge's page, end to end: against the robot's firmware on the emulated Cortex-M4
// and the simulated robot (duet pil), in headless Chromium, with nothing but the page.
//
//   node tests/tuning_story_e2e.mjs --url http://127.0.0.1:PORT/ --artefacts DIR [--timeout-s 60]
//
// 1. The page says the PID is in effect with the calibration's gains, and the robot balances.
// 2. A push; P doubled from the page (now Linux's gains, P in use twice the old); the same push again: the response,
//    measured from the page's own telemetry (theta at 100 Hz), changes the way the README says.
// 3. P negated: the robot falls and the page reports the safety stop.
// 4. P back and Restart: the robot is carried back up and balances again.
// 5. The LQR chosen from the page, then the PID again.
// Prints one JSON line of results; exits 0 when every check passed, 1 naming the failed step.
import { mkdir } from 'node:fs/promises';
import path from 'node:path';
import { launchChromium, parseOptions, waitFor } from './browser.mjs';
import { responseToPush } from './push_response.mjs';

const usage = 'usage: tuning_story_e2e.mjs --url URL --artefacts DIR [--timeout-s S]';
const options = parseOptions(process.argv.slice(2), { url: '', artefacts: '', 'timeout-s': '60' }, usage);
if (!options.url || !options.artefacts) {
  console.error(usage);
  process.exit(2);
}
const timeoutMs = Number(options['timeout-s']) * 1000;
const results = { url: options.url };
let step = 'launching Chromium';

const browser = await launchChromium();
const page = await (await browser.newContext({ viewport: { width: 1280, height: 900 } })).newPage();
const pageErrors = [];
page.on('pageerror', (error) => pageErrors.push(error.message));
const shot = (name) => page.screenshot({ path: path.join(options.artefacts, name), fullPage: true });

// What the Now panel shows for a signal, and its number.
const now = (name) => page.textContent(`[data-now="${name}"]`);
const nowNumber = async (name) => Number(await page.getAttribute(`[data-now="${name}"]`, 'data-value'));
const nowReads = (name, text, ms = timeoutMs) =>
  waitFor(`Now to show ${name} = ${text}`, ms, async () => ((await now(name)) === text ? text : null));

// The page's telemetry as it arrived: [time_s, theta] from the samples' numbers and the description's period.
const theta = () => page.evaluate(() => window.e2eTheta);
const modelTime = async () => (await page.evaluate(() => window.e2eTheta.at(-1)?.[0])) ?? 0;
const untilModelTime = (time_s) =>
  waitFor(`the model's time to reach ${time_s} s`, timeoutMs, async () => ((await modelTime()) >= time_s ? true : null), 50);
const standing = (seconds) =>
  waitFor(`|theta| < 1 degree for ${seconds} s`, timeoutMs, async () => {
    const samples = await theta();
    const end = samples.at(-1)?.[0] ?? 0;
    const recent = samples.filter(([time]) => time > end - seconds);
    return end > seconds && recent.every(([, value]) => Math.abs(value) < 1) ? end : null;
  });

const writeParameter = async (name, value) => {
  await page.fill(`input[type=number][data-parameter="${name}"]`, String(value));
  await page.click(`button[data-write="${name}"]`);
  await waitFor(`the firmware to take ${name} = ${value}`, timeoutMs, async () => {
    const shown = Number(await page.getAttribute(`[data-target-value="${name}"]`, 'data-value'));
    return Math.abs(shown - value) <= 1e-6 * Math.max(1, Math.abs(value)) ? shown : null;
  });
};
const chooseController = async (text) => {
  await page.selectOption('select[data-choice="use_lqr"]', { label: text });
  await page.click('button[data-write="use_lqr"]');
  await nowReads('controller', text);
};

// Pushes through the Disturb box; returns the model time the plant applied it at.
const push = async () => {
  const before = await page.getAttribute('#plant-last', 'data-time-s');
  await page.click('button[data-plant-action="push"]');
  const applied = await waitFor('the plant to apply the push', timeoutMs, async () => {
    const time = await page.getAttribute('#plant-last', 'data-time-s');
    const action = await page.getAttribute('#plant-last', 'data-action');
    return time !== null && time !== before && action === 'push' ? Number(time) : null;
  });
  return applied;
};
const measurePush = async (label) => {
  const at = await push();
  await untilModelTime(at + 4);
  const response = responseToPush(await theta(), at, 4);
  results[label] = response;
  return response;
};

try {
  await mkdir(options.artefacts, { recursive: true });

  step = 'loading the page: the description with the plant, the PID in effect';
  await page.goto(options.url, { timeout: timeoutMs });
  await page.evaluate(() => {
    window.e2eTheta = [];
    window.duet.onMessage = (message) => {
      if (message.type === 'description') window.e2eDescription = message;
      const description = window.e2eDescription;
      if (message.type !== 'telemetry' || !description) return;
      const index = description.telemetry.findIndex((item) => item.name === 'theta');
      window.e2eTheta.push([(message.sample * description.telemetry_period_us) / 1e6, message.values[index]]);
    };
    window.duet.connection.send({ type: 'describe' }); // the first description came before this hook
  });
  await page.waitForSelector('button[data-plant-action="push"]', { timeout: timeoutMs });
  await page.click('[data-tab="tuning"]');
  await nowReads('controller', 'PID');
  await nowReads('gains_from', 'calibration');

  step = 'the robot balancing on its own';
  await nowReads('robot_state', 'balancing');
  await standing(2);
  const p = await nowNumber('p_gain');
  results.p_calibrated = p;
  await shot('1-balancing.png');

  step = 'a push with the calibrated gains';
  const calibrated = await measurePush('push_calibrated_p');
  await standing(2);

  step = 'P doubled from the page, then the same push';
  await writeParameter('P', 2 * p);
  await nowReads('gains_from', 'Linux');
  await waitFor('P in use to double', timeoutMs, async () => (Math.abs((await nowNumber('p_gain')) - 2 * p) < 1e-6 ? true : null));
  await standing(2);
  const doubled = await measurePush('push_doubled_p');
  await shot('2-p-doubled.png');
  // More P stiffens the tilt loop: the same push tilts the robot less and it swings back faster.
  if (!(doubled.peak_deg < calibrated.peak_deg)) {
    throw new Error(`with P doubled the push tilted the robot ${doubled.peak_deg} degrees, not less than ${calibrated.peak_deg}`);
  }

  step = 'P negated: the robot falls and the page reports the safety stop';
  await writeParameter('P', -p);
  await nowReads('robot_state', 'stopped');
  await shot('3-stopped.png');

  step = 'P back, Restart: the robot is carried back up and balances again';
  await writeParameter('P', p);
  await page.click('button[data-plant-action="restart"]');
  await waitFor('the plant to apply the restart', timeoutMs, async () => ((await page.getAttribute('#plant-last', 'data-action')) === 'restart' ? true : null));
  await nowReads('robot_state', 'balancing');
  await standing(3);
  await shot('4-restarted.png');

  step = 'the LQR chosen from the page, and the PID again';
  await chooseController('LQR');
  await standing(2);
  await chooseController('PID');
  await standing(2);
  await shot('5-pid-again.png');

  if (pageErrors.length) throw new Error(`the page threw: ${pageErrors.join('; ')}`);
  results.ok = true;
  console.log(JSON.stringify(results));
} catch (error) {
  results.ok = false;
  results.failed_step = step;
  results.error = error.message;
  await shot('failure.png').catch(() => {});
  console.log(JSON.stringify(results));
  process.exitCode = 1;
} finally {
  await browser.close();
}
