// Writes what a running `duet studio` sends a page that joins: NAME.studio.json (the `studio` message) and
// NAME.model.json (the first `model`), the fixtures the diagram demo and the mock server read. Refresh them after
// changing the server's messages:
//   duet studio apps/balbot/balbot.yaml --listen 127.0.0.1:8790 &
//   node tests/capture_studio.mjs ws://127.0.0.1:8790/ tests/fixtures/studio/balbot
import { writeFileSync } from 'node:fs';
import WebSocket from 'ws';

const [url, prefix] = process.argv.slice(2);
if (!url || !prefix) {
  console.error('usage: node tests/capture_studio.mjs ws://HOST:PORT/ PREFIX');
  process.exit(2);
}
const socket = new WebSocket(url);
const captured = {};
socket.on('error', (error) => {
  console.error(`capture_studio: ${error.message}`);
  process.exit(1);
});
socket.on('message', (data) => {
  const message = JSON.parse(data.toString());
  if (message.type !== 'studio' && message.type !== 'model') return;
  captured[message.type] ??= message;
  if (!captured.studio || !captured.model) return;
  writeFileSync(`${prefix}.studio.json`, `${JSON.stringify(captured.studio, null, 1)}\n`);
  writeFileSync(`${prefix}.model.json`, `${JSON.stringify(captured.model, null, 1)}\n`);
  console.log(`wrote ${prefix}.studio.json and ${prefix}.model.json`);
  process.exit(0);
});
