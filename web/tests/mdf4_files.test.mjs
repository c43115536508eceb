import { test } from 'node:test';
import assert from 'node:assert/strict';
import { attachmentName, backendHttpUrl, createMdf4Files, scopeRequest } from '../src/mdf4_files.js';

const offer = { recorder: 'recorder.mf4', scope: 'scope.mf4', max_request_bytes: 1000 };

// A fetch that records its calls and answers with `answer` (status, body, headers).
function fakeFetch(answer) {
  const calls = [];
  const fetchFile = async (url, init) => {
    calls.push({ url, init });
    if (answer instanceof Error) throw answer;
    return new Response(answer.body, { status: answer.status, headers: answer.headers ?? {} });
  };
  return { calls, fetchFile };
}

function files(answer, websocketUrl = 'ws://127.0.0.1:8765/') {
  const fake = fakeFetch(answer);
  const saved = [];
  const mdf4 = createMdf4Files({ websocketUrl, fetchFile: fake.fetchFile, save: (name, blob) => saved.push({ name, blob }) });
  return { mdf4, calls: fake.calls, saved };
}

test('the files are at the back end of the WebSocket, over HTTP or HTTPS', () => {
  assert.equal(backendHttpUrl('ws://127.0.0.1:8765/', 'recorder.mf4'), 'http://127.0.0.1:8765/recorder.mf4');
  assert.equal(backendHttpUrl('wss://board/', 'scope.mf4'), 'https://board/scope.mf4');
});

test('the scope request holds the times and each shown signal, gaps as null', () => {
  const request = scopeRequest(Float64Array.of(0, 0.001, 0.002), [
    { name: 'theta', unit: 'deg', values: Float64Array.of(1.5, NaN, -2) },
    { name: 'count', values: [1, 2, Infinity] },
  ]);
  assert.deepEqual(request, {
    time_s: [0, 0.001, 0.002],
    signals: [
      { name: 'theta', unit: 'deg', values: [1.5, null, -2] },
      { name: 'count', unit: '', values: [1, 2, null] },
    ],
  });
});

test('the file name is the one the back end gave', () => {
  assert.equal(attachmentName('attachment; filename="capture-theta-2024-05-01T12-30-05.mf4"', 'x.mf4'), 'capture-theta-2024-05-01T12-30-05.mf4');
  assert.equal(attachmentName(null, 'x.mf4'), 'x.mf4');
});

test('nothing is asked of a back end that does not offer MDF4', async () => {
  const { mdf4, calls } = files({ status: 200, body: 'MDF' });
  mdf4.describe({ telemetry: [] });
  assert.equal(mdf4.available, false);
  assert.equal((await mdf4.recorder()).ok, false);
  assert.equal((await mdf4.scope([0], [{ name: 'a', values: [1] }])).ok, false);
  assert.equal(calls.length, 0);
});

test('the recorder file is fetched and saved under the back end name', async () => {
  const { mdf4, calls, saved } = files({ status: 200, body: 'MDF     4.20', headers: { 'Content-Disposition': 'attachment; filename="capture-theta.mf4"' } });
  mdf4.describe({ mdf4: offer });
  assert.equal(mdf4.available, true);
  const result = await mdf4.recorder();
  assert.equal(result.ok, true);
  assert.match(result.message, /saved capture-theta\.mf4/);
  assert.deepEqual(calls.map((call) => [call.url, call.init.method]), [['http://127.0.0.1:8765/recorder.mf4', 'GET']]);
  assert.equal(saved.length, 1);
  assert.equal(saved[0].name, 'capture-theta.mf4');
  assert.equal(await saved[0].blob.text(), 'MDF     4.20');
});

test('the scope samples are posted as JSON and the answer saved', async () => {
  const { mdf4, calls, saved } = files({ status: 200, body: 'MDF' });
  mdf4.describe({ mdf4: offer });
  const result = await mdf4.scope(Float64Array.of(0, 1), [{ name: 'theta', unit: 'deg', values: Float64Array.of(2, NaN) }]);
  assert.equal(result.ok, true);
  assert.equal(calls[0].url, 'http://127.0.0.1:8765/scope.mf4');
  assert.equal(calls[0].init.method, 'POST');
  assert.equal(calls[0].init.headers['Content-Type'], 'application/json');
  assert.deepEqual(JSON.parse(calls[0].init.body), { time_s: [0, 1], signals: [{ name: 'theta', unit: 'deg', values: [2, null] }] });
  assert.equal(saved[0].name, 'scope.mf4');
});

test('the back end refusal, a back end that does not answer and too many samples are said', async () => {
  const refused = files({ status: 400, body: 'scope.mf4: "time_s"[2] (0.5) is before the time preceding it\n' });
  refused.mdf4.describe({ mdf4: offer });
  assert.deepEqual(await refused.mdf4.scope([0, 1, 0.5], [{ name: 'a', values: [1, 2, 3] }]), {
    ok: false,
    message: 'MDF4: scope.mf4: "time_s"[2] (0.5) is before the time preceding it',
  });
  assert.equal(refused.saved.length, 0);

  const away = files(new TypeError('Failed to fetch'));
  away.mdf4.describe({ mdf4: offer });
  assert.match((await away.mdf4.recorder()).message, /did not answer \(Failed to fetch\)/);

  const large = files({ status: 200, body: 'MDF' });
  large.mdf4.describe({ mdf4: offer });
  const many = new Float64Array(500);
  const result = await large.mdf4.scope(many, [{ name: 'a', values: many }]);
  assert.equal(result.ok, false);
  assert.match(result.message, /more than the back end takes .*choose fewer signals/);
  assert.equal(large.calls.length, 0);
});
