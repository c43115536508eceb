import { test } from 'node:test';
import assert from 'node:assert/strict';
import { signalsCsv } from '../src/csv.js';
import { websocketUrl } from '../src/websocket_url.js';
import { reconnectDelay } from '../src/reconnect_delay.js';
import { groupByUnit } from '../src/unit_groups.js';
import { formatCounter, formatNumber } from '../src/number_format.js';
import { counterTables, executiveSummary, linkText, taskRows } from '../src/status_tables.js';

test('CSV: time column, one column per signal with its unit, gaps empty', () => {
  const csv = signalsCsv([0, 0.001], [
    { name: 'theta', unit: 'deg', values: [1.5, NaN] },
    { name: 'n, count', unit: '', values: [2, 3] },
  ]);
  assert.equal(csv, 'time_s,theta [deg],"n, count"\n0,1.5,2\n0.001,,3\n');
});

test('the WebSocket is on the page own host and port unless ?ws= says otherwise', () => {
  assert.equal(websocketUrl({ protocol: 'http:', host: '10.0.0.2:8765', search: '' }), 'ws://10.0.0.2:8765/');
  assert.equal(websocketUrl({ protocol: 'https:', host: 'example', search: '' }), 'wss://example/');
  assert.equal(websocketUrl({ protocol: 'http:', host: 'a:1', search: '?ws=ws://b:2/' }), 'ws://b:2/');
});

test('reconnection waits double up to a limit', () => {
  assert.deepEqual([0, 1, 2, 3, 4, 5, 6, 20].map(reconnectDelay), [500, 1000, 2000, 4000, 8000, 10000, 10000, 10000]);
});

test('signals group by unit in first-seen order', () => {
  const groups = groupByUnit([{ name: 'a', unit: 'deg' }, { name: 'b', unit: 'V' }, { name: 'c', unit: 'deg' }, { name: 'd' }]);
  assert.deepEqual(groups.map((group) => [group.unit, group.signals.map((s) => s.name)]), [['deg', ['a', 'c']], ['V', ['b']], ['', ['d']]]);
});

test('numbers read well', () => {
  assert.equal(formatNumber(0.05000000074505806), '0.05');
  assert.equal(formatNumber(12), '12');
  assert.equal(formatNumber(undefined), '—');
  assert.equal(formatCounter(1234567), '1,234,567');
  assert.equal(formatCounter(true), 'yes');
});

test('status: link, executive, tasks and every counter object', () => {
  const status = {
    type: 'status',
    link: { state: 'connected', address: 'tcp:10.0.0.2:5555' },
    executive: { time_s: 12.5, ticks: 12500, core_load: 0.25, overruns: 1, tasks: [{ name: 'control', activations: 10, overruns: 0, min_us: 1, mean_us: 2, max_us: 3 }] },
    application_channel: { open: true, samples: 5, nested: { lost: 0 } },
    note: 'not a table',
  };
  assert.equal(linkText(status.link), 'connected — tcp:10.0.0.2:5555');
  assert.deepEqual(executiveSummary(status.executive)[0], ['core load', '25.0 %']);
  assert.deepEqual(taskRows(status.executive), [['control', 10, 0, 1, 2, 3]]);
  assert.deepEqual(counterTables(status), [['application_channel', [['open', true], ['samples', 5], ['nested.lost', 0]]]]);
});
