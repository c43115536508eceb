// The studio page in headless Chromium against tests/mock_studio.mjs (skipped without Chromium):
// byte-identical round trip of a CRLF file, the edit -> check -> shown loop, diagnostics, the
// gold scenario (a Gain put between two connected blocks by palette, drags and the form, saved),
// renaming from a wire, deleting with the Delete key, and the reload banner.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { existsSync } from 'node:fs';
import { copyFile, mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'esbuild';
import { parse } from 'yaml';
import { chromium_path, launchChromium } from './browser.mjs';
import { dragPort } from './studio_session.mjs';

const web = path.join(path.dirname(fileURLToPath(import.meta.url)), '..');
const no_chromium = !existsSync(chromium_path) && `no Chromium at ${chromium_path}`;

let folder;
let mock;
let server;
let browser;
let page;
const errors = [];

async function startMock(modelFile) {
  mock = spawn(process.execPath, [path.join(web, 'tests/mock_studio.mjs'), '--port', '0', '--dist', folder, '--file', modelFile], { stdio: ['ignore', 'pipe', 'inherit'] });
  return new Promise((resolve) => mock.stdout.once('data', (data) => resolve(JSON.parse(data))));
}

before(async () => {
  if (no_chromium) return;
  folder = await mkdtemp(path.join(tmpdir(), 'studio-page-'));
  await build({ entryPoints: [path.join(web, 'src/studio/main.js')], outfile: path.join(folder, 'studio.js'), bundle: true, format: 'iife', logLevel: 'warning' });
  for (const [from, to] of [['src/studio.html', 'studio.html'], ['src/theme.css', 'theme.css'], ['src/charts.css', 'charts.css'], ['src/studio/studio.css', 'studio.css'], ['src/studio/diagram/diagram.css', 'diagram.css'], ['src/studio/panels/panels.css', 'panels.css'], ['node_modules/uplot/dist/uPlot.min.css', 'uPlot.min.css']]) {
    await copyFile(path.join(web, from), path.join(folder, to));
  }
  // pid_demo with CRLF line ends, the text the page must hand back byte for byte.
  const crlf = (await readFile(path.join(web, '../apps/pid_demo/pid_demo.yaml'), 'utf8')).replaceAll('\n', '\r\n');
  await writeFile(path.join(folder, 'pid_demo.yaml'), crlf);
  server = await startMock(path.join(folder, 'pid_demo.yaml'));
  browser = await launchChromium();
  page = await browser.newPage({ viewport: { width: 1500, height: 900 } });
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto(server.url);
  await page.waitForFunction(() => window.duetStudio?.stats.lastModelSeq === 0 && document.querySelector('.block[data-id="pid"]'), null, { timeout: 20000 });
});

after(async () => {
  await browser?.close();
  mock?.kill();
  if (folder) await rm(folder, { recursive: true, force: true });
  assert.deepEqual(errors, []);
});

const onDisk = () => readFile(server.file, 'utf8');
const message = () => page.textContent('#edit-message');
const waitForChecked = () => page.waitForFunction(() => !window.duetStudio.connection || document.getElementById('check-state').dataset.state !== 'pending');

test('the text round-trips byte for byte: a CRLF file saved unedited is the same file', { skip: no_chromium }, async () => {
  const before = await onDisk();
  assert.equal(await page.evaluate(() => window.duetStudio.editor.getText()), before);
  await page.evaluate(() => window.duetStudio.editor.setText(window.duetStudio.editor.getText()));
  await page.keyboard.press('Control+s');
  await page.waitForFunction(() => document.getElementById('edit-message').textContent === 'saved');
  assert.equal(await onDisk(), before);
});

test('typing is checked: errors show on the text, in Problems and on the block; the latency is recorded', { skip: no_chromium }, async () => {
  const original = await page.evaluate(() => window.duetStudio.editor.getText());
  await page.evaluate(() => {
    const text = window.duetStudio.editor.getText();
    window.duetStudio.editor.select(text.indexOf('inputs: {u: theta}, outputs: {y: angle_magnitude}') + 'inputs: {u: '.length + 5);
  });
  await page.focus('.cm-content');
  // `theta` -> `thetaX`: an input reading a signal nothing drives.
  await page.keyboard.type('X', { delay: 20 });
  await page.waitForFunction(() => document.getElementById('check-state').textContent === '1 error');
  assert.equal(await page.locator('.cm-lintRange-error').count(), 1);
  assert.equal(await page.locator('.cm-lint-marker-error').count(), 1);
  assert.match(await page.textContent('#problems'), /reads signal 'thetaX'/);
  const stats = await page.evaluate(() => window.duetStudio.stats);
  assert.ok(stats.checks >= 1 && stats.checkLatencyMs.length >= 1 && stats.lastModelSeq >= 1, JSON.stringify(stats));
  await page.keyboard.press('Control+z');
  await page.waitForFunction(() => document.getElementById('check-state').textContent === 'checked');
  assert.equal(await page.evaluate(() => window.duetStudio.editor.getText()), original);
});

test('a text that is not a model keeps the last drawing, dimmed, and still shows the error', { skip: no_chromium }, async () => {
  const original = await page.evaluate(() => window.duetStudio.editor.getText());
  try {
    await page.evaluate(() => window.duetStudio.editor.setText(`${window.duetStudio.editor.getText()}\n  - {name: broken, [\n`));
    await page.waitForFunction(() => /not a model/.test(document.getElementById('check-state').textContent));
    assert.ok(await page.locator('.block[data-id="pid"]').count(), 'the last drawing stays');
    assert.ok(await page.$eval('#diagram', (node) => node.classList.contains('stale')), 'dimmed');
    // Problems lists it; a click scrolls the text there, where the gutter marks the line.
    await page.click('[data-bottom-tab="problems"]');
    await page.click('#problems .problem');
    await page.waitForSelector('.cm-lint-marker-error');
  } finally {
    await page.evaluate((text) => window.duetStudio.editor.setText(text), original);
  }
  await page.waitForFunction(() => document.getElementById('check-state').textContent === 'checked');
  assert.equal(await page.$eval('#diagram', (node) => node.classList.contains('stale')), false);
});

test('gold scenario: a Gain between two connected blocks, its k set, saved; the file is otherwise unchanged', { skip: no_chromium }, async () => {
  const before = await onDisk();
  await page.click('.palette-entry[data-type="Gain"]');
  await page.waitForSelector('.block[data-id="gain_1"]');
  await dragPort(page, 'compare_angle', 'y', 'gain_1', 'u');
  await page.waitForFunction(() => /gain_1\.u reads error/.test(document.getElementById('edit-message').textContent));
  await page.waitForSelector('.block[data-id="gain_1"] .port[data-port$=":y"]');
  await dragPort(page, 'gain_1', 'y', 'pid', 'error');
  await page.waitForFunction(() => /pid\.error reads gain_1_y/.test(document.getElementById('edit-message').textContent));
  await page.click('[data-bottom-tab="block"]');
  await page.click('.block[data-id="gain_1"]');
  await page.fill('[data-field="parameter:k"]', '-');
  await page.press('[data-field="parameter:k"]', 'Enter');
  assert.match(await page.textContent('#block-form .field-problem'), /a number/, 'an invalid value is refused before writing');
  await page.fill('[data-field="parameter:k"]', '0.5');
  await page.press('[data-field="parameter:k"]', 'Enter');
  await page.waitForFunction(() => window.duetStudio.editor.getText().includes('{k: 0.5}'));
  await waitForChecked();
  await page.keyboard.press('Control+s');
  await page.waitForFunction(() => document.getElementById('edit-message').textContent === 'saved');
  assert.equal(await page.$eval('#dirty-marker', (node) => node.hidden), true);

  const after = await onDisk();
  const oldLines = before.split('\r\n');
  const newLines = after.split('\r\n');
  assert.ok(!after.replaceAll('\r\n', '').includes('\n'), 'every line still ends in CRLF');
  assert.equal(newLines.length, oldLines.length + 1);
  const changed = oldLines.slice(0, -1).flatMap((line, i) => (line === newLines[i] ? [] : [[line, newLines[i]]]));
  assert.deepEqual(changed, [['    inputs: {error: error}', '    inputs: {error: gain_1_y}']]);
  assert.equal(newLines.at(-2), '  - {name: gain_1, type: Gain, parameters: {k: 0.5}, inputs: {u: error}, outputs: {y: gain_1_y}}');
  assert.equal(parse(after).blocks.at(-1).parameters.k, 0.5);
});

test('diagram and text select each other', { skip: no_chromium }, async () => {
  await page.click('.block[data-id="pid"]');
  const selected = await page.evaluate(() => {
    const { from, to } = window.duetStudio.editor.selection();
    return window.duetStudio.editor.getText().slice(from, to);
  });
  assert.match(selected, /^ {2}- name: pid\r\n {4}type: DiscretePid\r\n[\s\S]*outputs: \{y: pid_output\}$/);
  await page.evaluate(() => {
    const text = window.duetStudio.editor.getText();
    window.duetStudio.editor.select(text.indexOf('name: magnitude'));
  });
  await page.focus('.cm-content');
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => window.duetStudio.view.currentSystem() === 'monitor');
  assert.match(await page.textContent('#block-form .form-head'), /monitor\/magnitude/);
});

test('rename a signal from its wire, then delete a block with the Delete key; undo puts it back', { skip: no_chromium }, async () => {
  await page.evaluate(() => window.duetStudio.view.showSystem(''));
  await page.click('[data-bottom-tab="block"]');
  const before = await page.evaluate(() => window.duetStudio.editor.getText());
  await page.evaluate(() => {
    const text = window.duetStudio.editor.getText();
    window.duetStudio.editor.select(text.indexOf('outputs: {y: angle_magnitude}') + 'outputs: {y: '.length + 2);
  });
  await page.focus('.cm-content');
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => /signal angle_magnitude/.test(document.querySelector('#block-form .form-head')?.textContent));
  await page.fill('[data-field="signal-name"]', 'angle_size_abs');
  await page.click('[data-action="rename"]');
  const renamed = await page.evaluate(() => window.duetStudio.editor.getText());
  assert.equal(renamed, before.replaceAll('angle_magnitude', 'angle_size_abs'));
  await waitForChecked();

  await page.click('.block[data-id="angle_size"]');
  await page.keyboard.press('Delete');
  await page.waitForFunction(() => !window.duetStudio.editor.getText().includes('name: angle_size,'));
  assert.equal(await page.evaluate(() => window.duetStudio.editor.getText()), renamed.replace(/ {2}- \{name: angle_size, [^\r]*\r\n/, ''));
  await page.focus('.cm-content');
  await page.keyboard.press('Control+z');
  await page.keyboard.press('Control+z');
  assert.equal(await page.evaluate(() => window.duetStudio.editor.getText()), before);
});

test('a file changed on disk: a banner, a refused save, and Reload takes the disk text', { skip: no_chromium }, async () => {
  const outside = `${await onDisk()}# changed elsewhere\r\n`;
  await writeFile(server.file, outside);
  await page.waitForSelector('#banner:not([hidden])', { timeout: 5000 });
  await page.evaluate(() => window.duetStudio.editor.setText(`${window.duetStudio.editor.getText()}# mine\r\n`));
  await page.click('#banner-dismiss');
  await page.keyboard.press('Control+s');
  await page.waitForSelector('#banner:not([hidden])');
  assert.match(await page.textContent('#banner-text'), /Not saved/);
  assert.equal(await onDisk(), outside, 'never overwritten');
  await page.click('#banner-reload');
  await page.waitForFunction((text) => window.duetStudio.editor.getText() === text, outside);
  assert.equal(await page.$eval('#dirty-marker', (node) => node.hidden), true);
});
