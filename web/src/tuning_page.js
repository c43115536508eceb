import { TuningRow } from './tuning_row.js';
import { presetText, readPreset } from './preset.js';
import { downloadText, timestampForFile } from './download.js';

// The Tuning page: a row per parameter, Write all, and presets saved to and loaded from files.
export function createTuningPage({ hub, connection }) {
  const list = document.getElementById('tuning-parameters');
  const message = document.getElementById('tuning-message');
  const writeAllButton = document.getElementById('tuning-write-all');
  const presetInput = document.getElementById('preset-file');
  let rows = new Map();
  let description = null;

  const say = (text, tone = 'muted') => {
    message.textContent = text;
    message.className = `message ${tone}`;
  };
  const write = (name, value) => connection.send({ type: 'set', name, value });
  const refreshWriteAll = () => {
    writeAllButton.disabled = ![...rows.values()].some((row) => row.changed);
  };

  hub.on('description', (next) => {
    description = next;
    const previous = rows;
    rows = new Map();
    for (const parameter of next.parameters ?? []) {
      const row = new TuningRow(parameter, { write });
      // A repeated description (target back, or `describe`) keeps what was being edited and
      // the undo history of unchanged parameters.
      const old = previous.get(parameter.name);
      if (old && old.parameter.type === parameter.type) {
        row.history = old.history;
        if (old.changed) row.propose(old.edited);
      }
      rows.set(parameter.name, row);
    }
    list.replaceChildren(...[...rows.values()].map((row) => row.node));
    document.getElementById('tuning-application').textContent = next.application ?? '';
    if (rows.size === 0) say('The target describes no parameters.');
    refreshWriteAll();
  });

  hub.on('parameter', (answer) => {
    const row = rows.get(answer.name) ?? [...rows.values()][answer.index];
    if (!row) return say(`parameter ${answer.name ?? answer.index}: ${answer.status}`, 'bad');
    row.received(answer);
    if (answer.status === 'clamped' || answer.status === 'failed' || answer.status === 'unknown parameter' || answer.status === 'malformed') {
      say(`${row.name}: ${answer.status}${answer.message ? ` — ${answer.message}` : ''}`, answer.status === 'clamped' ? 'warn' : 'bad');
    }
    refreshWriteAll();
  });

  hub.on('error', (error) => say(`back end: ${error.message}`, 'bad'));
  hub.on('channel', (channel) => {
    if (channel.open === false) say('The target went away; values shown are the last known.', 'warn');
  });

  // Any edit changes what Write all would do.
  list.addEventListener('input', refreshWriteAll);
  list.addEventListener('click', () => setTimeout(refreshWriteAll));

  writeAllButton.addEventListener('click', () => {
    const written = [...rows.values()].filter((row) => row.changed && row.writeEdited());
    say(written.length ? `writing ${written.map((row) => row.name).join(', ')}` : 'nothing to write');
    refreshWriteAll();
  });

  document.getElementById('preset-save').addEventListener('click', () => {
    if (!description) return say('no description yet', 'bad');
    const values = {};
    for (const row of rows.values()) {
      const value = typeof row.edited === 'number' ? row.edited : row.target;
      if (typeof value === 'number') values[row.name] = value;
    }
    downloadText(`${description.application || 'preset'}-${timestampForFile()}.json`, presetText(description.application, values), 'application/json');
  });

  document.getElementById('preset-load').addEventListener('click', () => presetInput.click());
  presetInput.addEventListener('change', async () => {
    const file = presetInput.files[0];
    presetInput.value = ''; // the same file again must fire `change` too
    if (!file || !description) return;
    const { values, warnings } = readPreset(await file.text(), description.parameters ?? [], description.application);
    for (const [name, value] of Object.entries(values)) rows.get(name).propose(value);
    refreshWriteAll();
    const loaded = `${file.name}: ${Object.keys(values).length} values in the fields, not written yet`;
    say(warnings.length ? `${loaded}; ${warnings.join('; ')}` : loaded, warnings.length ? 'warn' : 'muted');
  });

  return { show() {}, hide() {} };
}
