// What the studio's browser test and benchmark share: programs started and awaited by the address they print,
// copies of models in folders of their own, and `duet studio` opened in a Chromium page.
import { spawn } from 'node:child_process';
import { copyFile, mkdtemp, readdir } from 'node:fs/promises';
import path from 'node:path';

export class StudioSessions {
  // `duet`: the program; `root`: the source tree (models, web/dist); `work`: a folder for copies; `browser`: Chromium.
  constructor({ duet, root, work, browser }) {
    Object.assign(this, { duet, root, work, browser });
    this.children = [];
  }

  // A child program whose output names an address matching `pattern`; its output kept for failures.
  start(program, args, pattern) {
    const child = spawn(program, args, { stdio: ['ignore', 'pipe', 'pipe'] });
    this.children.push(child);
    let output = '';
    return new Promise((resolve, reject) => {
      const timer = setTimeout(() => reject(new Error(`${path.basename(program)} ${args[0]} said nothing matching ${pattern}:\n${output}`)), 30000);
      const take = (data) => {
        output += data;
        const found = output.match(pattern);
        if (found) {
          clearTimeout(timer);
          resolve({ child, address: found[0], output: () => output });
        }
      };
      child.stdout.on('data', take);
      child.stderr.on('data', take);
      child.on('exit', (code) => reject(new Error(`${path.basename(program)} ended (${code}):\n${output}`)));
    });
  }

  static stop(child) {
    child.removeAllListeners('exit');
    child.kill('SIGINT');
  }

  stopAll() {
    for (const child of this.children) child.kill('SIGINT');
  }

  // A copy of a model's folder (the model, the files beside it: Code blocks' headers), `relative` to the root.
  async copyModel(relative) {
    const from = path.join(this.root, path.dirname(relative));
    const to = await mkdtemp(path.join(this.work, `${path.basename(relative, '.yaml')}-`));
    for (const entry of await readdir(from, { withFileTypes: true })) {
      if (entry.isFile()) await copyFile(path.join(from, entry.name), path.join(to, entry.name));
    }
    return path.join(to, path.basename(relative));
  }

  // `duet studio MODEL` and a page on it, once the diagram is drawn; `firstDrawMs` from opening the page to that.
  async open(model, extra = []) {
    const server = await this.start(this.duet, ['studio', model, '--listen', '127.0.0.1:0', '--web', path.join(this.root, 'web/dist'), ...extra], /http:\/\/127\.0\.0\.1:\d+\//);
    const page = await this.browser.newPage({ viewport: { width: 1600, height: 1000 } });
    const errors = [];
    page.on('pageerror', (error) => errors.push(error.message));
    const opened = Date.now();
    await page.goto(server.address);
    await page.waitForFunction(() => window.duetStudio?.lastModel && document.querySelector('g.block'), null, { timeout: 30000 });
    const firstDrawMs = Date.now() - opened;
    return {
      server,
      page,
      errors,
      firstDrawMs,
      close: async () => {
        await page.close();
        StudioSessions.stop(server.child);
      },
    };
  }
}

export const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];
export const percentile = (values, fraction) => [...values].sort((a, b) => a - b)[Math.min(values.length - 1, Math.floor(values.length * fraction))];

// Live-value labels on the diagram: how many there are and how often the drawing of them changes, over `seconds`.
export function measureLiveRefresh(page, seconds) {
  return page.evaluate((duration) => new Promise((resolve) => {
    let changes = 0;
    let refreshes = 0;
    let seen = -1;
    const observer = new MutationObserver((records) => { changes += records.length; });
    observer.observe(document.getElementById('diagram'), { subtree: true, characterData: true, childList: true });
    // One refresh is one task in which labels changed: count the distinct ones.
    const sampler = setInterval(() => {
      if (changes !== seen) {
        refreshes += 1;
        seen = changes;
      }
    }, 5);
    setTimeout(() => {
      clearInterval(sampler);
      observer.disconnect();
      resolve({ labels: document.querySelectorAll('text.live-value').length, refreshes_per_s: refreshes / duration });
    }, duration * 1000);
  }), seconds);
}

// Drags from one block's port to another's, with the whole system fitted so that both are on screen.
export async function dragPort(page, fromBlock, fromPort, toBlock, toPort) {
  await page.evaluate(() => window.duetStudio.view.fit());
  const box = async (block, port) => (await page.$(`.block[data-id="${block}"] .port[data-port$=":${port}"] .port-hit`)).boundingBox();
  const a = await box(fromBlock, fromPort);
  const b = await box(toBlock, toPort);
  await page.mouse.move(a.x + a.width / 2, a.y + a.height / 2);
  await page.mouse.down();
  await page.mouse.move(b.x + b.width / 2, b.y + b.height / 2, { steps: 8 });
  await page.mouse.up();
}

// `edits` edits of the text (a comment line added at its end), each waited for: the latency from each to the diagram
// and the text showing the server's check of it, in ms.
export async function checkLatencies(page, edits) {
  const latencies = [];
  for (let edit = 0; edit < edits; edit += 1) {
    const before = await page.evaluate(() => window.duetStudio.stats.checkLatencyMs.length);
    await page.evaluate((n) => {
      const text = window.duetStudio.editor.getText();
      window.duetStudio.editor.setText(text.replace(/\n$/, `\n# edit ${n}\n`));
    }, edit);
    await page.waitForFunction((count) => window.duetStudio.stats.checkLatencyMs.length > count, before, { timeout: 5000 });
    latencies.push(await page.evaluate(() => window.duetStudio.stats.checkLatencyMs.at(-1)));
  }
  return latencies;
}
