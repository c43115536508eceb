#!/usr/bin/env node
// A stand-in for `duet studio`, for developing the studio page and for its browser tests: serves
// dist/ (studio.html for "/") and speaks docs/STUDIO.md's protocol on a WebSocket at the same port.
//
//   node tests/mock_studio.mjs --port 0 --fixture tests/fixtures/studio/NAME [--file MODEL.yaml]
//
// NAME.studio.json is the `studio` message (its `text` is replaced by --file's when given). When
// NAME.model.json exists, every `check` is answered with it (the request's seq, and an error
// diagnostic when the text contains "ERROR"); otherwise the mock derives a rough diagram from the
// text itself (blocks, ports, wires, lines), so that diagram edits show up as they would with the
// real server. The model file lives in a temporary copy: `save` writes it, and changing it from
// outside sends `file_changed` (checked every second, as the server does).
// Prints one JSON line: {"url": ..., "file": the temporary copy}.
import http from 'node:http';
import path from 'node:path';
import { createHash } from 'node:crypto';
import { existsSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { parseArgs } from 'node:util';
import { fileURLToPath } from 'node:url';
import { WebSocketServer } from 'ws';
import { LineCounter, isMap, isScalar, isSeq, parseDocument } from 'yaml';
import { staticFiles } from './mock/static_files.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const { values: options } = parseArgs({
  options: {
    port: { type: 'string', default: '8767' },
    host: { type: 'string', default: '127.0.0.1' },
    fixture: { type: 'string', default: path.join(here, 'fixtures/studio/mock_pid_demo') },
    file: { type: 'string' },
    dist: { type: 'string', default: path.join(here, '..', 'dist') },
    'check-delay-ms': { type: 'string', default: '0' },
  },
});

const studioFixture = JSON.parse(readFileSync(`${options.fixture}.studio.json`, 'utf8'));
const modelFixturePath = `${options.fixture}.model.json`;
const modelFixture = existsSync(modelFixturePath) ? JSON.parse(readFileSync(modelFixturePath, 'utf8')) : null;
const library = new Map(studioFixture.library.map((entry) => [entry.type, entry]));
const checkDelayMs = Number(options['check-delay-ms']);

const folder = mkdtempSync(path.join(tmpdir(), 'mock-studio-'));
const modelFile = path.join(folder, studioFixture.file);
writeFileSync(modelFile, options.file ? readFileSync(options.file) : studioFixture.text);

const versionOf = (bytes) => createHash('sha256').update(bytes).digest('hex').slice(0, 16);
const readModel = () => readFileSync(modelFile);
let knownVersion = versionOf(readModel());

// ---- a rough diagram, derived from the text the way the server's would look --------------------

function derive(text, seq) {
  const lineCounter = new LineCounter();
  const document = parseDocument(text, { lineCounter });
  const place = (offset) => lineCounter.linePos(offset);
  const diagnostics = [];
  if (document.errors.length > 0 || !isMap(document.contents)) {
    const first = document.errors[0];
    const { line, col } = first ? place(first.pos[0]) : { line: 1, col: 1 };
    diagnostics.push({ severity: 'error', line, column: col, message: first ? first.message.split('\n')[0] : 'not a model', hint: '' });
    return { type: 'model', seq, ok: false, diagnostics, diagram: null, tasks: [] };
  }
  const root = document.contents;
  const get = (map, key) => (isMap(map) ? map.items.find((pair) => pair.key?.value === key) : undefined);
  const scalar = (map, key) => get(map, key)?.value?.value;
  const source = (node) => text.slice(node.range[0], node.range[1]);
  const modelParameters = [];
  const parametersMap = get(root, 'parameters')?.value;
  if (isMap(parametersMap)) {
    for (const pair of parametersMap.items) {
      const fields = isMap(pair.value) ? Object.fromEntries(pair.value.items.map((p) => [p.key.value, p.value])) : { value: pair.value };
      const { line, col } = place(pair.key.range[0]);
      modelParameters.push({
        name: pair.key.value, value: fields.value ? source(fields.value) : '', type: fields.type?.value ?? 'double',
        unit: fields.unit?.value ?? '', min: fields.min?.value, max: fields.max?.value, description: fields.description?.value ?? '', line, column: col,
      });
    }
  }
  const parameterNames = new Set(modelParameters.map((parameter) => parameter.name));
  const constantNames = new Set((isMap(get(root, 'constants')?.value) ? get(root, 'constants').value.items : []).map((pair) => pair.key.value));
  const declared = new Map((isMap(get(root, 'signals')?.value) ? get(root, 'signals').value.items : []).map((pair) => [pair.key.value, pair]));

  function ports(block, direction, typeEntry) {
    const map = get(block, direction)?.value;
    const found = new Map();
    if (isMap(map)) {
      for (const pair of map.items) {
        const signalNode = isMap(pair.value) ? get(pair.value, 'signal')?.value : pair.value;
        const { line, col } = place(pair.key.range[0]);
        found.set(String(pair.key.value), { port: String(pair.key.value), signal: signalNode?.value != null ? String(signalNode.value) : undefined, line, column: col, kind: 'data' });
      }
    }
    if (typeEntry && !typeEntry.user_defined_ports) {
      let names = typeEntry[direction];
      if (direction === 'inputs' && typeEntry.variadic_inputs) {
        const count = Math.max(2, ...[...found.keys()].map((name) => Number(name.replace(/^u/, '')) || 0));
        names = Array.from({ length: count }, (_, i) => `u${i + 1}`);
      }
      for (const name of [...names, ...(direction === 'inputs' ? typeEntry.optional_inputs : [])]) {
        if (!found.has(name)) found.set(name, { port: name, kind: 'data' });
      }
    }
    return [...found.values()];
  }

  function system(map, systemPath, wireInputs, wireOutputs) {
    const blocks = [];
    const itemsNode = get(map, 'blocks')?.value;
    for (const item of isSeq(itemsNode) ? itemsNode.items.filter(isMap) : []) {
      const name = String(scalar(item, 'name') ?? '?');
      const type = String(scalar(item, 'type') ?? '?');
      const id = systemPath ? `${systemPath}/${name}` : name;
      const typeEntry = library.get(type);
      const namePlace = place((get(item, 'name') ?? item.items[0]).key.range[0]);
      const parametersNode = get(item, 'parameters')?.value;
      const block = {
        id, name, type, line: namePlace.line, column: namePlace.col, end_line: place(Math.max(item.range[0], item.range[1] - 1)).line,
        task: 0, period: scalar(item, 'period') ?? 'inherited', inputs: ports(item, 'inputs', typeEntry), outputs: ports(item, 'outputs', typeEntry),
        parameters: (isMap(parametersNode) ? parametersNode.items : []).map((pair) => {
          const text = isScalar(pair.value) ? String(pair.value.value) : source(pair.value);
          const { line, col } = place(pair.key.range[0]);
          const reference = parameterNames.has(text) || constantNames.has(text) ? text : undefined;
          return { name: String(pair.key.value), text, line, column: col, reference, tunable: parameterNames.has(text) };
        }),
      };
      if (!typeEntry) diagnostics.push({ severity: 'error', line: block.line, column: block.column, message: `unknown block type '${type}'`, hint: '', block: id });
      const enable = get(item, 'enable')?.value;
      if (enable) block.enable = String(enable.value);
      if (type === 'Subsystem') {
        const inner = system(item, id, block.inputs, block.outputs);
        block.system = inner;
        if (block.enable) block.inputs.push({ port: 'enable', signal: block.enable, kind: 'enable', ...(({ line, col }) => ({ line, column: col }))(place(enable.range[0])) });
      }
      blocks.push(block);
    }
    // Wires: every signal this system names, with its driver and readers.
    const wires = new Map();
    const wire = (signal) => {
      if (!wires.has(signal)) {
        const declaration = systemPath ? undefined : declared.get(signal);
        const measurable = declaration && isMap(declaration.value) && scalar(declaration.value, 'measurable') === true;
        const where = declaration ? place(declaration.key.range[0]) : undefined;
        wires.set(signal, {
          id: `${systemPath}:${signal}`, signal, resolved: systemPath ? `${systemPath.replaceAll('/', '.')}.${signal}` : signal,
          measurement: measurable ? signal : undefined, source: undefined, targets: [], type: 'single', unit: declaration && isMap(declaration.value) ? scalar(declaration.value, 'unit') : undefined,
          line: where?.line, column: where?.col,
        });
      }
      return wires.get(signal);
    };
    for (const port of wireInputs ?? []) if (port.kind === 'data') wire(port.port).source = { system_input: port.port };
    for (const port of wireOutputs ?? []) wire(port.port).targets.push({ system_output: port.port });
    for (const block of blocks) {
      for (const port of block.outputs) if (port.signal) {
        const w = wire(port.signal);
        w.source = { block: block.id, port: port.port };
        w.line ??= port.line;
        w.column ??= port.column;
      }
      for (const port of block.inputs) if (port.signal) wire(port.signal).targets.push({ block: block.id, port: port.port });
    }
    for (const w of wires.values()) {
      if (w.source) continue;
      for (const target of w.targets) {
        if (!target.block) continue;
        const port = blocks.find((b) => b.id === target.block).inputs.find((p) => p.port === target.port);
        diagnostics.push({ severity: 'error', line: port.line, column: port.column, message: `input '${port.port}' of block '${target.block}' reads signal '${w.signal}', which nothing drives`, hint: '', block: target.block });
      }
    }
    return { path: systemPath, inputs: (wireInputs ?? []).map(({ port }) => ({ port, signal: port })), outputs: (wireOutputs ?? []).map(({ port }) => ({ port, signal: port })), blocks, wires: [...wires.values()] };
  }

  const diagram = { name: scalar(root, 'name') ?? '', base_period_us: scalar(root, 'base_period_us') ?? 1000, root: system(root, ''), parameters: modelParameters };
  return { type: 'model', seq, ok: !diagnostics.some((d) => d.severity === 'error'), diagnostics, diagram, tasks: [{ index: 0, name: 'rate_1', kind: 'periodic', period_us: diagram.base_period_us, blocks: 1 }] };
}

function answerCheck(text, seq) {
  if (!modelFixture) {
    const model = derive(text, seq);
    if (text.includes('ERROR')) fakeError(model, text);
    return model;
  }
  const model = { ...modelFixture, type: 'model', seq, diagnostics: [...modelFixture.diagnostics] };
  if (text.includes('ERROR')) fakeError(model, text);
  return model;
}

function fakeError(model, text) {
  const before = text.slice(0, text.indexOf('ERROR')).split('\n');
  model.ok = false;
  model.diagnostics.push({ severity: 'error', line: before.length, column: before.at(-1).length + 1, message: 'the mock found ERROR here', hint: 'remove it' });
}

// ---- the protocol ------------------------------------------------------------------------------

const serveDist = staticFiles(path.resolve(options.dist));
const server = http.createServer((request, response) => {
  if (new URL(request.url, 'http://localhost').pathname === '/') request.url = '/studio.html';
  return serveDist(request, response);
});
const sockets = new WebSocketServer({ server, maxPayload: 1 << 20 });
const send = (socket, message) => socket.readyState === socket.OPEN && socket.send(JSON.stringify(message));
const broadcast = (message) => sockets.clients.forEach((socket) => send(socket, message));

sockets.on('connection', (socket) => {
  const text = readModel().toString('utf8');
  send(socket, { ...studioFixture, type: 'studio', version: knownVersion, text });
  send(socket, answerCheck(text, 0));
  socket.on('message', (data) => {
    let request;
    try {
      request = JSON.parse(data.toString());
    } catch {
      send(socket, { type: 'error', message: 'not JSON', request: '' });
      return;
    }
    if (request.type === 'check') setTimeout(() => send(socket, answerCheck(String(request.text), request.seq)), checkDelayMs);
    else if (request.type === 'save') {
      const onDisk = versionOf(readModel());
      if (onDisk !== request.base) {
        send(socket, { type: 'save_refused', reason: 'the file changed on disk', version: onDisk });
        return;
      }
      const bytes = Buffer.from(String(request.text), 'utf8');
      writeFileSync(modelFile, bytes);
      knownVersion = versionOf(bytes);
      send(socket, { type: 'saved', version: knownVersion });
    } else if (request.type === 'reload') send(socket, { type: 'file', text: readModel().toString('utf8'), version: versionOf(readModel()) });
    else send(socket, { type: 'error', message: `the mock does not answer '${request.type}'`, request: request.type });
  });
});

setInterval(() => {
  const onDisk = versionOf(readModel());
  if (onDisk === knownVersion) return;
  knownVersion = onDisk;
  broadcast({ type: 'file_changed', version: onDisk });
}, 1000).unref();

server.listen(Number(options.port), options.host, () => {
  const { port } = server.address();
  console.log(JSON.stringify({ url: `http://${options.host}:${port}/`, file: modelFile }));
});
