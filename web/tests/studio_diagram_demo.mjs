// The diagram view alone in headless Chromium, on a fixture: bundles the view (esbuild, IIFE)
// into a temporary page, draws the fixture, measures layout and drawing, exercises navigation,
// selection, markers and live values, and saves screenshots.
//
//   node tests/studio_diagram_demo.mjs --fixture tests/fixtures/studio/diagram_small.json \
//        [--library tests/fixtures/studio/balbot.studio.json] [--shots /tmp/diagram] [--open SYSTEM]
//
// Prints one JSON line: {stats, steps...}; exits 1 naming the failed step.
import { build } from 'esbuild';
import { mkdtemp, mkdir, readFile, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchChromium, parseOptions } from './browser.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const usage = 'usage: node tests/studio_diagram_demo.mjs --fixture FILE [--library FILE] [--shots DIR] [--open SYSTEM] [--width PX] [--height PX]';
const options = parseOptions(process.argv.slice(2), { fixture: '', library: '', shots: '/tmp/studio_diagram', open: '', width: '1400', height: '900' }, usage);
if (!options.fixture) {
  console.error(usage);
  process.exit(2);
}

// A fixture is a `model` message (diagram, tasks), optionally with `library`; a `studio` message
// given by --library supplies the library otherwise.
const model = JSON.parse(await readFile(options.fixture, 'utf8'));
const library = options.library ? JSON.parse(await readFile(options.library, 'utf8')).library : model.library;

const folder = await mkdtemp(path.join(tmpdir(), 'studio-diagram-'));
await mkdir(options.shots, { recursive: true });
await writeFile(path.join(folder, 'entry.js'), `import { createDiagramView } from ${JSON.stringify(path.join(here, '../src/studio/diagram/diagram_view.js'))};
window.events = [];
window.view = createDiagramView(document.getElementById('diagram'), {
  onSelect: (selection) => window.events.push(['select', selection]),
  onOpenSystem: (path) => window.events.push(['open', path]),
  onConnect: (connection) => window.events.push(['connect', connection]),
  onActivateBlock: (id) => window.events.push(['activate', id]),
});
`);
await build({ entryPoints: [path.join(folder, 'entry.js')], outfile: path.join(folder, 'view.js'), bundle: true, format: 'iife', target: ['es2022'], logLevel: 'warning', absWorkingDir: path.join(here, '..') });
const css = await readFile(path.join(here, '../src/studio/diagram/diagram.css'), 'utf8');
await writeFile(path.join(folder, 'index.html'), `<!doctype html><meta charset="utf-8"><style>body{margin:0}#diagram{width:100vw;height:100vh}${css}</style>
<div id="diagram"></div><script src="view.js"></script>`);

const steps = {};
const browser = await launchChromium();
try {
  const page = await browser.newPage({ viewport: { width: Number(options.width), height: Number(options.height) } });
  const problems = [];
  page.on('pageerror', (error) => problems.push(String(error)));
  await page.goto(`file://${folder}/index.html`);
  const step = async (name, action) => {
    try {
      steps[name] = await action();
    } catch (error) {
      console.log(JSON.stringify({ failed: name, error: String(error), steps, problems }));
      process.exit(1);
    }
  };
  const check = (condition, message) => { if (!condition) throw new Error(message); };

  await step('first_draw', async () => {
    const wall = await page.evaluate(async ({ diagram, library, tasks }) => {
      const start = performance.now();
      await window.view.setModel(diagram, library, tasks);
      return Math.round(performance.now() - start);
    }, { diagram: model.diagram, library, tasks: model.tasks });
    const stats = await page.evaluate(() => window.view.stats());
    const blocks = await page.locator('g.block[data-id]').count();
    const wires = await page.locator('g.wire[data-id]').count();
    check(blocks === stats.blocks && blocks === model.diagram.root.blocks.length, `drew ${blocks} blocks, stats say ${stats.blocks}, the model has ${model.diagram.root.blocks.length}`);
    check(wires === stats.wires, `drew ${wires} wires, stats say ${stats.wires}`);
    await page.screenshot({ path: path.join(options.shots, 'top.png') });
    // At scale 1 too: the fitted overview of a big system is too small to judge text by.
    await page.evaluate(() => {
      const scale = Number(/scale\(([^)]+)\)/.exec(document.querySelector('.viewport').getAttribute('transform'))[1]);
      window.view.zoomBy(1 / scale);
    });
    await page.screenshot({ path: path.join(options.shots, 'top_scale1.png') });
    await page.evaluate(() => window.view.fit());
    return { wallMs: wall, ...stats };
  });

  await step('open_subsystem', async () => {
    const subsystem = options.open || model.diagram.root.blocks.find((block) => block.system && block.system.blocks.length > 1)?.id;
    check(subsystem, 'no subsystem to open');
    await page.dblclick(`g.block[data-id="${subsystem}"] .block-name`);
    await page.waitForSelector(`nav.breadcrumb a.current[data-path="${subsystem}"]`);
    const crumbs = await page.locator('nav.breadcrumb a[data-path]').count();
    check(crumbs === subsystem.split('/').length + 1, `breadcrumb has ${crumbs} levels`);
    await page.screenshot({ path: path.join(options.shots, 'subsystem.png') });
    await page.click('nav.breadcrumb a[data-path=""]');
    await page.waitForSelector('nav.breadcrumb a.current[data-path=""]');
    return subsystem;
  });

  await step('select_and_tooltip', async () => {
    const block = model.diagram.root.blocks.find((candidate) => candidate.parameters?.length && !candidate.system) ?? model.diagram.root.blocks[0];
    await page.click(`g.block[data-id="${block.id}"] .block-type`);
    check(await page.locator(`g.block.selected[data-id="${block.id}"]`).count() === 1, 'clicked block not selected');
    await page.hover(`g.block[data-id="${block.id}"] .block-name`);
    await page.waitForSelector('.diagram-tooltip:not([hidden])');
    const text = await page.locator('.diagram-tooltip').innerText();
    check(text.includes(block.type), `tooltip lacks the type: ${text}`);
    await page.screenshot({ path: path.join(options.shots, 'tooltip.png') });
    return block.id;
  });

  await step('markers_and_live_values', async () => {
    const measured = model.diagram.root.wires.filter((wire) => wire.measurement);
    const result = await page.evaluate(({ names, inner }) => {
      window.view.setMarkers(new Map([[inner, [{ severity: 'error', message: 'demo error' }]]]));
      window.view.setLiveMode(true);
      const values = new Map(names.map((name, i) => [name, i % 3 === 0 ? [0.02, 0, 0.019, 1.5, 2.25] : Math.PI * (i + 1)]));
      window.view.setLiveValues(values);
      return new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => resolve(
        [...document.querySelectorAll('text.live-value')].filter((label) => label.textContent !== '').length))));
    }, { names: measured.map((wire) => wire.measurement), inner: model.diagram.root.blocks.find((block) => block.system)?.system.blocks[0]?.id ?? model.diagram.root.blocks[0].id });
    check(result > 0, 'no live value shown');
    check(await page.locator('g.block.marker-error').count() === 1, 'the marker inside a subsystem does not mark its box');
    await page.screenshot({ path: path.join(options.shots, 'live.png') });
    return { labelsShown: result };
  });

  await step('live_refresh_rate', () => page.evaluate(async (names) => {
    // Values at 50 Hz for 2 s: the labels must keep up (frames, not a queue).
    let sent = 0;
    const start = performance.now();
    let longest = 0;
    await new Promise((resolve) => {
      const timer = setInterval(() => {
        const t0 = performance.now();
        window.view.setLiveValues(new Map(names.map((name, i) => [name, Math.sin(sent / 10 + i) * 100])));
        longest = Math.max(longest, performance.now() - t0);
        sent += 1;
        if (performance.now() - start > 2000) { clearInterval(timer); resolve(); }
      }, 20);
    });
    return { updatesSent: sent, hz: Math.round(sent / ((performance.now() - start) / 1000)), longestCallMs: Math.round(longest * 100) / 100 };
  }, model.diagram.root.wires.filter((wire) => wire.measurement).map((wire) => wire.measurement)));

  await step('find', async () => {
    const inner = model.diagram.root.blocks.find((block) => block.system)?.system.blocks[0];
    const found = await page.evaluate((name) => window.view.find(name), inner.name);
    check(found, `find ${inner.name} found nothing`);
    await page.waitForTimeout(50);
    await page.screenshot({ path: path.join(options.shots, 'find.png') });
    return found;
  });

  await step('connect_by_drag', async () => {
    // From the first block with an output to another block with an input, port to port.
    const blocks = model.diagram.root.blocks;
    const source = blocks.find((block) => block.outputs?.length);
    const target = blocks.find((block) => block !== source && block.inputs?.some((port) => port.kind === 'data'));
    const input = target.inputs.find((port) => port.kind === 'data');
    await page.evaluate(() => window.view.showSystem(''));
    await page.evaluate(({ s, t }) => window.view.select({ kind: 'block', id: s }), { s: source.id });
    const from = await page.locator(`g.block[data-id="${source.id}"] .port[data-port="out:${source.outputs[0].port}"] .port-hit`).boundingBox();
    await page.mouse.move(from.x + from.width / 2, from.y + from.height / 2);
    await page.mouse.down();
    await page.mouse.move(from.x + 40, from.y + 40, { steps: 4 });
    check(await page.locator('.rubber-band').count() === 1, 'no rubber band while dragging');
    await page.evaluate((id) => window.view.select({ kind: 'block', id }), target.id);
    const to = await page.locator(`g.block[data-id="${target.id}"] .port[data-port="in:${input.port}"] .port-hit`).boundingBox();
    await page.mouse.move(to.x + to.width / 2, to.y + to.height / 2, { steps: 6 });
    await page.mouse.up();
    const connect = await page.evaluate(() => window.events.filter(([kind]) => kind === 'connect').at(-1)?.[1]);
    check(connect && connect.from.block === source.id && connect.to.block === target.id && connect.to.port === input.port, `connect event: ${JSON.stringify(connect)}`);
    return connect;
  });

  await step('click_wire', async () => {
    const wire = model.diagram.root.wires.find((candidate) => candidate.source && candidate.targets.length);
    await page.evaluate((id) => window.view.select({ kind: 'wire', id }), wire.id);
    const line = page.locator(`g.wire[data-id="${wire.id}"] .wire-line`).first();
    const box = await line.boundingBox();
    await page.evaluate(() => window.view.select(null));
    // The middle of a bounding box may miss an L-shaped line: click where the path is.
    const point = await line.evaluate((path) => {
      const at = path.getPointAtLength(path.getTotalLength() / 2);
      const matrix = path.getScreenCTM();
      return { x: at.x * matrix.a + matrix.e, y: at.y * matrix.d + matrix.f };
    });
    await page.mouse.click(point.x, point.y);
    const selected = await page.evaluate(() => window.events.filter(([kind]) => kind === 'select').at(-1)?.[1]);
    check(selected?.kind === 'wire' && selected.id === wire.id, `clicked ${wire.id} near ${JSON.stringify(box)}, selected ${JSON.stringify(selected)}`);
    check(await page.locator(`g.wire.selected[data-id="${wire.id}"]`).count() === 1, 'the wire is not highlighted');
    return selected.id;
  });

  await step('edit_keeps_positions', async () => {
    const edited = structuredClone(model.diagram);
    const source = edited.root.blocks.find((block) => block.outputs?.length && !block.system);
    const signal = source.outputs[0].signal;
    edited.root.blocks.push({ id: 'added_by_demo', name: 'added_by_demo', type: 'Gain', task: source.task, inputs: [{ port: 'u', signal, kind: 'data' }], outputs: [], parameters: [] });
    edited.root.wires.find((wire) => wire.signal === signal).targets.push({ block: 'added_by_demo', port: 'u' });
    const before = await page.evaluate(() => Object.fromEntries([...document.querySelectorAll('g.block')].map((g) => [g.dataset.id, g.getAttribute('transform')])));
    await page.evaluate(({ diagram, library, tasks }) => { window.view.setStale(true); return window.view.setModel(diagram, library, tasks); }, { diagram: edited, library, tasks: model.tasks });
    const after = await page.evaluate(() => Object.fromEntries([...document.querySelectorAll('g.block')].map((g) => [g.dataset.id, g.getAttribute('transform')])));
    const moved = Object.keys(before).filter((id) => before[id] !== after[id]);
    check(moved.length === 0, `moved: ${moved.join(', ')}`);
    check(after.added_by_demo, 'the added block is not drawn');
    check(await page.locator('.duet-diagram.stale').count() === 1, 'not dimmed when stale');
    await page.screenshot({ path: path.join(options.shots, 'edited_stale.png') });
    await page.evaluate(() => window.view.setStale(false));
    return { layoutMs: (await page.evaluate(() => window.view.stats())).layoutMs };
  });

  await step('relayout', () => page.evaluate(async () => {
    await window.view.showSystem('');
    await window.view.relayout();
    return window.view.stats();
  }));
  check(problems.length === 0, `page errors: ${problems.join('; ')}`);
  console.log(JSON.stringify({ steps, events: await page.evaluate(() => window.events.length) }));
} finally {
  await browser.close();
  await rm(folder, { recursive: true, force: true });
}
