// The browser end-to-end test against the mock back end, in both of its shapes: `duet monitor`
// (samples blocks at 1 kHz) and `duet-bridge` (one telemetry message per sample). Needs dist/
// (npm run build) and Chromium; run with `npm run e2e:mock`.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { runScript, startMock } from './start_mock.mjs';

for (const mode of ['samples', 'telemetry']) {
  test(`dashboard end to end against the mock in ${mode} mode`, { timeout: 90000 }, async () => {
    // Under duet pil a plant is behind the target; the board's bridge has none.
    const plant = mode === 'samples' ? 'yes' : 'no';
    const mock = await startMock(['--mode', mode, '--plant', plant]);
    const artefacts = await mkdtemp(path.join(tmpdir(), `duet-e2e-${mode}-`));
    try {
      const run = await runScript('dashboard_e2e.mjs', ['--url', mock.url, '--artefacts', artefacts, '--parameter', 'P', '--value', '0.05', '--signal', 'theta', '--trigger-level', '0', '--timeout-s', '30', '--plant', plant === 'yes' ? 'push' : 'none', '--mdf4', 'none']);
      assert.equal(run.code, 0, `dashboard_e2e failed:\n${run.stdout}${run.stderr}`);
      const results = JSON.parse(run.stdout.trim().split('\n').pop());
      assert.equal(results.ok, true);
      assert.ok(Math.abs(results.parameter_written.target - 0.05) < 1e-6);
      assert.ok(results.samples > 0 && results.frames > 0 && results.captured > 0);
      assert.deepEqual([results.scope_mdf4, results.recorder_mdf4], ['hidden', 'hidden']);  // the mock writes no MDF4
      if (plant === 'yes') assert.ok(results.plant.restart_time_s >= results.plant.push_time_s, JSON.stringify(results.plant));
    } finally {
      mock.stop();
      await rm(artefacts, { recursive: true, force: true });
    }
  });
}
