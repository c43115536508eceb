#!/usr/bin/env node
// How the Scope page keeps up: frames drawn per second, main-thread CPU time per second and,
// given a signal that carries the target's wall-clock time in ms, the latency from sampling to
// the page receiving the sample.
//
//   node tests/bench_scope.mjs --url URL [--seconds 10] [--latency-signal NAME] [--signals 8] [--page scope]
//
// --page tuning measures the same stream with no plotting: the cost of receiving alone.
// Prints one JSON line.
import { launchChromium, parseOptions, waitFor } from './browser.mjs';

const usage = 'usage: bench_scope.mjs --url URL [--seconds 10] [--latency-signal NAME] [--signals 8] [--page scope]';
const options = parseOptions(process.argv.slice(2), { url: '', seconds: '10', 'latency-signal': '', signals: '8', page: 'scope' }, usage);
if (!options.url) {
  console.error(usage);
  process.exit(2);
}
const seconds = Number(options.seconds);

const browser = await launchChromium();
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  // The latency hook goes in before the page's own script runs, so it sees the description (the
  // signal's position) without asking the back end for it again.
  await page.addInitScript((signal) => {
    const bench = { latencies: [], index: -1 };
    let duet;
    Object.defineProperty(window, 'bench', { value: bench });
    Object.defineProperty(window, 'duet', {
      configurable: true,
      get: () => duet,
      set(value) {
        duet = value;
        duet.onMessage = (message, arrivalMs) => {
          if (message.type === 'description') bench.index = message.telemetry.findIndex((item) => item.name === signal);
          if (bench.index < 0) return;
          if (message.type === 'samples') for (const sampled of message.values[bench.index]) bench.latencies.push(arrivalMs - sampled);
          else if (message.type === 'telemetry') bench.latencies.push(arrivalMs - message.values[bench.index]);
        };
      },
    });
  }, options['latency-signal']);
  const pageUrl = new URL(options.url);
  pageUrl.hash = 'scope';
  await page.goto(pageUrl.href);
  await page.waitForSelector('input[data-signal]', { state: 'attached', timeout: 30000 });
  const plotted = await page.evaluate((count) => {
    const boxes = [...document.querySelectorAll('input[data-signal]')];
    boxes.forEach((box, i) => {
      if (box.checked !== i < count) box.click();
    });
    return boxes.filter((box) => box.checked).map((box) => box.dataset.signal);
  }, Number(options.signals));
  await waitFor('samples to arrive', 30000, () => page.evaluate(() => window.duet.stats.samples > 0));

  if (options['latency-signal'] && (await page.evaluate(() => window.bench.index)) < 0) {
    throw new Error(`no telemetry signal named ${options['latency-signal']}`);
  }
  if (options.page !== 'scope') await page.click(`[data-tab="${options.page}"]`);
  await page.waitForTimeout(1000); // settle

  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Performance.enable');
  const metrics = async () => Object.fromEntries((await cdp.send('Performance.getMetrics')).metrics.map(({ name, value }) => [name, value]));
  const processCpu = await processCpuReader(browser);
  const stats = () => page.evaluate(() => ({ ...window.duet.stats, now: performance.now() }));

  await page.evaluate(() => (window.bench.latencies = []));
  const start = { metrics: await metrics(), stats: await stats(), cpu: await processCpu() };
  await page.waitForTimeout(seconds * 1000);
  const end = { metrics: await metrics(), stats: await stats(), cpu: await processCpu() };

  const elapsedS = (end.stats.now - start.stats.now) / 1000;
  const perSecond = (key) => round(((end.metrics[key] - start.metrics[key]) * 1000) / elapsedS);
  const result = {
    url: options.url,
    page: options.page,
    seconds: round(elapsedS),
    signals: plotted.length,
    frames_per_s: round((end.stats.frames - start.stats.frames) / elapsedS),
    samples_per_s: round((end.stats.samples - start.stats.samples) / elapsedS),
    messages_per_s: round((end.stats.messages - start.stats.messages) / elapsedS),
    main_thread_task_ms_per_s: perSecond('TaskDuration'),
    script_ms_per_s: perSecond('ScriptDuration'),
    layout_ms_per_s: perSecond('LayoutDuration'),
    js_heap_mb: round(end.metrics.JSHeapUsedSize / 1e6),
  };
  if (start.cpu && end.cpu) {
    result.renderer_cpu_ms_per_s = round(((end.cpu.renderer - start.cpu.renderer) * 1000) / elapsedS);
    result.browser_cpu_ms_per_s = round(((end.cpu.all - start.cpu.all) * 1000) / elapsedS);
  }
  if (options['latency-signal']) {
    const latencies = await page.evaluate(() => window.bench.latencies);
    result.latency_ms = summarise(latencies);
  }
  console.log(JSON.stringify(result));
} catch (error) {
  console.error(`bench_scope: ${error.message.split('\n')[0]}`);
  process.exitCode = 1;
} finally {
  await browser.close();
}

// The browser's processes' CPU seconds through CDP's SystemInfo, when the browser offers it.
async function processCpuReader(browser) {
  let session;
  try {
    session = await browser.newBrowserCDPSession();
    await session.send('SystemInfo.getProcessInfo');
  } catch {
    return async () => null;
  }
  return async () => {
    const { processInfo } = await session.send('SystemInfo.getProcessInfo');
    const sum = (list) => list.reduce((total, process) => total + process.cpuTime, 0);
    return { renderer: sum(processInfo.filter((process) => process.type === 'renderer')), all: sum(processInfo) };
  };
}

function summarise(values) {
  if (values.length === 0) return { count: 0 };
  const sorted = Float64Array.from(values).sort();
  const at = (share) => sorted[Math.min(sorted.length - 1, Math.floor(share * sorted.length))];
  return { count: sorted.length, median: round(at(0.5)), p95: round(at(0.95)), max: round(sorted[sorted.length - 1]) };
}

function round(value) {
  return Math.round(value * 100) / 100;
}
