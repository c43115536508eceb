#!/usr/bin/env node
// A stand-in for duet's back ends, for developing the dashboard and for its browser tests:
// serves dist/ over HTTP and speaks docs/DASHBOARD.md's protocol on a WebSocket at the same port.
//
//   node tests/mock_backend.mjs [--port 8765] [--host 127.0.0.1] [--mode samples|telemetry] [--rate 1000]
//        [--plant yes|no]
//
// `samples` mode is `duet monitor` (1 kHz in 20 ms blocks); `telemetry` mode is `duet-bridge` (one
// message per sample, 100 Hz unless --rate says otherwise). With `--plant yes` (the default) a simulated plant is
// behind the target, as under duet pil: the description has `plant`, and `plant` requests are answered. Prints
// `listening http://HOST:PORT/`.
import http from 'node:http';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { fileURLToPath } from 'node:url';
import { WebSocketServer } from 'ws';
import { description, initialParameters, sampleAt } from './mock/signals.mjs';
import { MockRecorder } from './mock/recorder.mjs';
import { staticFiles } from './mock/static_files.mjs';
import { answerPlant, plantDescription } from './mock/plant.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const { values: options } = parseArgs({
  options: {
    port: { type: 'string', default: '8765' },
    host: { type: 'string', default: '127.0.0.1' },
    mode: { type: 'string', default: 'samples' },
    rate: { type: 'string' },
    plant: { type: 'string', default: 'yes' },
    dist: { type: 'string', default: path.join(here, '..', 'dist') },
  },
});
if (!['samples', 'telemetry'].includes(options.mode)) {
  console.error(`mock_backend: --mode is samples or telemetry, not '${options.mode}'`);
  process.exit(2);
}
const rate = Number(options.rate ?? (options.mode === 'samples' ? 1000 : 100));
const block_ms = 20;
const describedAs = {
  ...description,
  backend: options.mode === 'samples' ? 'monitor' : 'bridge',
  telemetry_period_us: Math.round(1e6 / rate),
  ...(options.plant === 'yes' ? { plant: plantDescription } : {}),
};
const parameters = initialParameters();
const recorder = new MockRecorder(
  describedAs.telemetry.map((item) => item.name),
  30 * rate,
);
const counters = { samples: 0, messages_sent: 0, messages_dropped: 0, requests: 0, bad_requests: 0 };
const plantCounters = { requests: 0, applied: 0, refused: 0 };

const server = http.createServer(staticFiles(path.resolve(options.dist)));
const sockets = new WebSocketServer({ server, maxPayload: 4096 });

function send(socket, message) {
  if (socket.readyState !== socket.OPEN) return;
  // Like the real back ends: a client that cannot keep up loses samples, not answers.
  if ((message.type === 'samples' || message.type === 'telemetry') && socket.bufferedAmount > 4 << 20) {
    counters.messages_dropped += 1;
    return;
  }
  socket.send(JSON.stringify(message));
  counters.messages_sent += 1;
}
function broadcast(message) {
  const text = JSON.stringify(message);
  for (const socket of sockets.clients) {
    if (socket.readyState !== socket.OPEN) continue;
    if ((message.type === 'samples' || message.type === 'telemetry') && socket.bufferedAmount > 4 << 20) {
      counters.messages_dropped += 1;
      continue;
    }
    socket.send(text);
    counters.messages_sent += 1;
  }
}

function parameterMessage(name, status) {
  const index = describedAs.parameters.findIndex((item) => item.name === name);
  return { type: 'parameter', index, name, value: parameters[name], status };
}

function welcome(socket) {
  send(socket, describedAs);
  for (const { name } of describedAs.parameters) send(socket, parameterMessage(name, 'reported'));
}

// One handler per request type, as the real back ends have.
const handlers = {
  set(socket, request) {
    const item = describedAs.parameters.find((candidate) => candidate.name === request.name);
    if (typeof request.name !== 'string' || typeof request.value !== 'number') return send(socket, { type: 'error', message: 'set needs "name" (a string) and "value" (a number)' });
    if (!item) return send(socket, { type: 'error', message: `no parameter named '${request.name}'` });
    if (request.value < item.min || request.value > item.max) return send(socket, { type: 'error', message: `parameter ${item.name}: ${request.value} is outside its limits [${item.min}, ${item.max}]` });
    if (item.type !== 'float32' && item.type !== 'float64' && !Number.isInteger(request.value)) return send(socket, { type: 'error', message: `parameter ${item.name} is an integer (${item.type}): ${request.value} is not` });
    parameters[item.name] = item.type === 'float32' ? Math.fround(request.value) : request.value;
    broadcast(parameterMessage(item.name, 'applied'));
  },
  describe: (socket) => welcome(socket),
  status: (socket) => send(socket, statusMessage()),
  record(socket, request) {
    const problem = recorder.arm(request);
    if (problem) return send(socket, { type: 'error', message: problem });
    broadcast(recorderMessage('armed'));
  },
  plant(socket, request) {
    if (!describedAs.plant) return send(socket, { type: 'plant', error: 'no simulated plant behind this target (no --plant-control)' });
    plantCounters.requests += 1;
    const answer = answerPlant(request, sent / rate);
    if (answer.error) {
      plantCounters.refused += 1;
      return send(socket, answer);
    }
    plantCounters.applied += 1;
    broadcast(answer); // every page shows the last push
  },
  cancel_record() {
    recorder.cancel();
    broadcast({ type: 'recorder', state: 'idle' });
  },
};

function recorderMessage(state) {
  const { signal, level, edge, pre_s, post_s } = recorder.armed ?? {};
  return { type: 'recorder', state, signal, level, edge, pre_s, post_s };
}

sockets.on('connection', (socket) => {
  welcome(socket);
  socket.on('message', (data) => {
    counters.requests += 1;
    let request;
    try {
      request = JSON.parse(String(data));
    } catch {
      request = null;
    }
    const handler = request && typeof request.type === 'string' && Object.hasOwn(handlers, request.type) ? handlers[request.type] : null;
    if (!handler) {
      counters.bad_requests += 1;
      return send(socket, { type: 'error', message: `unknown request: ${String(data).slice(0, 80)}` });
    }
    handler(socket, request);
  });
});

// The sampling clock: samples are due at `rate` per second since the start; each tick sends every
// sample that fell due, as one block (samples mode) or one message each (telemetry mode).
const startedMs = performance.timeOrigin + performance.now();
let sent = 0;
const task_names = ['control 1 kHz', 'telemetry 100 Hz', 'battery 10 Hz', 'background'];
function produce() {
  const nowMs = performance.timeOrigin + performance.now();
  const due = Math.floor(((nowMs - startedMs) / 1000) * rate);
  const time = [];
  const rows = [];
  for (; sent < due; sent += 1) {
    const t = sent / rate;
    const row = sampleAt(t, parameters, startedMs + t * 1000);
    time.push(t);
    rows.push(row);
    const event = recorder.add(t, row);
    if (event === 'triggered') broadcast(recorderMessage('triggered'));
    else if (event) broadcast(event);
  }
  counters.samples = sent;
  if (time.length === 0 || sockets.clients.size === 0) return;
  if (options.mode === 'samples') {
    const values = describedAs.telemetry.map((_, s) => rows.map((row) => row[s]));
    broadcast({ type: 'samples', time_s: time, values });
  } else {
    rows.forEach((row, i) => broadcast({ type: 'telemetry', sample: Math.round(time[i] * rate), values: row }));
  }
}
setInterval(produce, options.mode === 'samples' ? block_ms : Math.max(1, 1000 / rate));

function statusMessage() {
  const elapsed = sent / rate;
  return {
    type: 'status',
    link: { state: 'connected', address: `mock ${options.mode} at ${rate} Hz` },
    executive: {
      time_s: elapsed,
      ticks: sent,
      core_load: 0.31 + 0.05 * Math.sin(elapsed),
      overruns: Math.floor(elapsed / 600),
      tasks: task_names.map((name, i) => ({
        name,
        activations: Math.floor(elapsed * [1000, 100, 10, 1][i]),
        overruns: 0,
        min_us: [42.1, 18.5, 7.2, 310][i],
        mean_us: [47.9, 21.3, 8.1, 415][i],
        max_us: [88.4, 35.0, 12.6, 905][i],
      })),
    },
    daq: { odt_sent: sent * 2, odt_lost: 0, overruns: 0, queue_high_water: 3 },
    websocket: { clients: sockets.clients.size, ...counters },
    ...(describedAs.plant ? { plant: { link: { state: 'open', address: 'mock' }, ...plantCounters } } : {}),
  };
}
setInterval(() => broadcast(statusMessage()), 1000);

server.on('error', (error) => {
  console.error(`mock_backend: ${error.message}`);
  process.exit(1);
});
sockets.on('error', () => {}); // the server's own 'error' above says it once
server.listen(Number(options.port), options.host, () => {
  const { address, port } = server.address();
  console.log(`listening http://${address}:${port}/`);
});
for (const signal of ['SIGINT', 'SIGTERM']) process.on(signal, () => process.exit(0));
