// Shared by the browser tests: the system's Chromium driven by playwright-core (never a
// downloaded browser), and the tests' command-line conventions.
import { chromium } from 'playwright-core';
import { existsSync } from 'node:fs';

export const chromium_path = process.env.DUET_CHROMIUM || '/usr/bin/chromium';

const chromium_arguments = [
  '--no-sandbox',
  '--disable-gpu',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
];

export async function launchChromium() {
  if (!existsSync(chromium_path)) throw new Error(`no Chromium at ${chromium_path} (set DUET_CHROMIUM)`);
  // playwright gives every launch a fresh temporary profile and removes it on close.
  return chromium.launch({ executablePath: chromium_path, headless: true, args: chromium_arguments });
}

// --name value pairs into an object, with defaults; unknown names are an error.
export function parseOptions(argv, defaults, usage) {
  const options = { ...defaults };
  for (let i = 0; i < argv.length; i += 1) {
    const name = argv[i].replace(/^--/, '');
    if (!argv[i].startsWith('--') || !(name in defaults) || i + 1 >= argv.length) {
      console.error(`${argv[i].startsWith('--') && !(name in defaults) ? `unknown option ${argv[i]}` : `option ${argv[i]} needs a value`}\n${usage}`);
      process.exit(2);
    }
    options[name] = argv[(i += 1)];
  }
  return options;
}

// Polls `check` (which returns a truthy value when done) until it passes or time runs out.
export async function waitFor(description, timeoutMs, check, intervalMs = 100) {
  const deadline = Date.now() + timeoutMs;
  let last;
  while (Date.now() < deadline) {
    last = await check();
    if (last) return last;
    await new Promise((resolve) => setTimeout(resolve, intervalMs));
  }
  throw new Error(`timed out after ${(timeoutMs / 1000).toFixed(1)} s waiting for ${description}`);
}
