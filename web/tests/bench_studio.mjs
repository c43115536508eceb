// duet studio's figures (docs/PERFORMANCE.md), in headless Chromium against the real server:
//   layout    the robot's top level (106 blocks of its 171) laid out and drawn: the view's own layout and drawing
//             times, and the time from opening the page to the drawing, over --runs fresh pages (median, max)
//   check     edit-to-checked latency: from an edit of the text to the diagram and the text showing the server's
//             check of it, over --edits edits (median, p95)
//   live      with every live value of the robot's top level visible (the whole system fitted), against the
//             firmware built for the PC in real time (balbot_sil --xcp, DAQ of every measurable signal at 1 kHz):
//             label refreshes per second, samples per second, and whether a backlog grows (the newest sample's
//             model time against the wall clock, at the start and the end of --seconds)
// Prints one JSON line. Usage: bench/studio.sh, or
//   node bench_studio.mjs --duet DUET --root SOURCE_DIR --sil BALBOT_SIL [--runs 5] [--edits 40] [--seconds 10]
import { mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { launchChromium, parseOptions } from './browser.mjs';
import { checkLatencies, measureLiveRefresh, median, percentile, StudioSessions } from './studio_session.mjs';

const usage = 'usage: node bench_studio.mjs --duet DUET --root SOURCE_DIR --sil BALBOT_SIL [--runs N] [--edits N] [--seconds S]';
const options = parseOptions(process.argv.slice(2), { duet: '', root: '', sil: '', runs: '5', edits: '40', seconds: '10' }, usage);
if (!options.duet || !options.root || !options.sil) {
  console.error(usage);
  process.exit(2);
}
const work = await mkdtemp(path.join(tmpdir(), 'duet-studio-bench-'));
const browser = await launchChromium();
const sessions = new StudioSessions({ duet: path.resolve(options.duet), root: path.resolve(options.root), work, browser });
const results = {};

async function layout() {
  const model = await sessions.copyModel('apps/balbot/balbot.yaml');
  const runs = [];
  for (let run = 0; run < Number(options.runs); run += 1) {
    const session = await sessions.open(model);
    const stats = await session.page.evaluate(() => window.duetStudio.view.stats());
    runs.push({ layout_and_draw_ms: stats.layoutMs + stats.drawMs, opened_to_drawn_ms: session.firstDrawMs, blocks: stats.blocks });
    await session.close();
  }
  const pick = (key) => runs.map((run) => run[key]);
  results.layout = {
    blocks: runs[0].blocks,
    layout_and_draw_ms: { median: median(pick('layout_and_draw_ms')), max: Math.max(...pick('layout_and_draw_ms')) },
    opened_to_drawn_ms: { median: median(pick('opened_to_drawn_ms')), max: Math.max(...pick('opened_to_drawn_ms')) },
  };
}

async function check() {
  const model = await sessions.copyModel('apps/balbot/balbot.yaml');
  const session = await sessions.open(model);
  const { page } = session;
  const latencies = await checkLatencies(page, Number(options.edits));
  results.check = { edits: latencies.length, median_ms: median(latencies), p95_ms: percentile(latencies, 0.95) };
  await session.close();
}

async function live() {
  const target = await sessions.start(path.resolve(options.sil), ['--plant', 'balbot', '--scenario', path.join(options.root, 'apps/balbot/scenarios/disturbed.yaml'), '--real-time', '--duration', '600', '--xcp', '127.0.0.1:0'], /tcp:\/\/127\.0\.0\.1:\d+/);
  const model = await sessions.copyModel('apps/balbot/balbot.yaml');
  const session = await sessions.open(model, ['--xcp', target.address]);
  const { page } = session;
  await page.waitForSelector('text.live-value[data-measurement="theta"]', { timeout: 30000 });
  await page.evaluate(() => window.duetStudio.view.fit());
  // How far the newest sample lags the wall clock, up to a constant: compared at the start and the end.
  await page.evaluate(() => {
    window.duetStudio.hub.on('status', (status) => (window.lastStatus = status));
    window.lag = [];
    window.duetStudio.hub.on('samples', (message) => {
      const newest = message.time_s.at(-1);
      if (newest !== undefined) window.lag.push({ wall_s: performance.now() / 1000, model_s: newest });
    });
  });
  const refresh = await measureLiveRefresh(page, Number(options.seconds));
  const lags = await page.evaluate(() => window.lag);
  const lagAt = (sample) => (sample.wall_s - lags[0].wall_s) - (sample.model_s - lags[0].model_s);
  const firstSecond = lags.filter((sample) => sample.wall_s - lags[0].wall_s < 1);
  const lastSecond = lags.filter((sample) => lags.at(-1).wall_s - sample.wall_s < 1);
  const samples = (lags.at(-1).model_s - lags[0].model_s) / (lags.at(-1).wall_s - lags[0].wall_s);
  results.live = {
    ...refresh,
    model_s_per_wall_s: samples,
    lag_growth_ms: 1000 * (median(lastSecond.map(lagAt)) - median(firstSecond.map(lagAt))),
    messages_dropped_for_the_page: await page.evaluate(() => window.lastStatus?.dashboard?.messages_dropped_for_clients ?? null),
  };
  await session.close();
  StudioSessions.stop(target.child);
}

try {
  await layout();
  await check();
  await live();
  console.log(JSON.stringify(results));
} finally {
  await browser.close();
  sessions.stopAll();
  await rm(work, { recursive: true, force: true });
}
