// Diagram edits as minimal splices of the model's YAML text. The `yaml` package only tells us
// where things are (node ranges); we never re-stringify the document, so every line we do not
// touch keeps its bytes: comments, key order, flow `{...}` or block style.
//
// Every edit returns a list of changes {from, to, insert}, to be applied one after the other
// (applyChanges), each against the text the previous ones left. Offsets are string offsets into
// the text given, whose lines are separated by "\n" (the editor converts).
import { parseDocument, isMap, isSeq, isScalar } from 'yaml';

export class ModelEditError extends Error {}

export function applyChanges(text, changes) {
  let result = text;
  for (const change of changes) result = result.slice(0, change.from) + change.insert + result.slice(change.to);
  return result;
}

function parse(text) {
  const document = parseDocument(text, { keepSourceTokens: true });
  // An edit located in a half-read document could land anywhere; ask for the text to be fixed first.
  if (document.errors.length > 0) throw new ModelEditError(`the YAML does not read (${document.errors[0].message.split('\n')[0]}): fix the text first`);
  if (!isMap(document.contents)) throw new ModelEditError('the text is not a model (no top-level map)');
  return document;
}

function pairOf(map, key) {
  return map.items.find((pair) => (isScalar(pair.key) ? pair.key.value : pair.key) === key);
}

function scalarText(node) {
  return isScalar(node) ? String(node.value) : undefined;
}

function lineStart(text, offset) {
  return text.lastIndexOf('\n', offset - 1) + 1;
}

function lineEnd(text, offset) {
  const end = text.indexOf('\n', offset);
  return end < 0 ? text.length : end;
}

// Where a node's own text ends: a block collection's range also covers the comments and blank
// lines after it, which belong to whatever follows.
function contentEnd(text, node) {
  let end;
  if (isScalar(node) || node.flow) end = node.range[1];
  else if (isMap(node)) {
    const last = node.items.at(-1);
    end = last ? contentEnd(text, last.value ?? last.key) : node.range[1];
  } else if (isSeq(node)) {
    const last = node.items.at(-1);
    end = last ? contentEnd(text, last) : node.range[1];
  } else end = node.range[1];
  while (end > 0 && /\s/.test(text[end - 1])) end -= 1;
  return end;
}

// The column a block collection's entries start at, as spaces.
function indentOf(text, offset) {
  return ' '.repeat(offset - lineStart(text, offset));
}

function systemMap(document, systemPath) {
  let system = document.contents;
  for (const name of systemPath ? systemPath.split('/') : []) {
    system = blockMapIn(system, name);
    if (!system) throw new ModelEditError(`no subsystem '${systemPath}' in the text`);
  }
  return system;
}

function blocksOf(system) {
  const blocks = pairOf(system, 'blocks')?.value;
  return isSeq(blocks) ? blocks.items.filter(isMap) : [];
}

function blockMapIn(system, name) {
  return blocksOf(system).find((block) => scalarText(pairOf(block, 'name')?.value) === name);
}

function splitId(blockId) {
  const parts = blockId.split('/');
  return { systemPath: parts.slice(0, -1).join('/'), name: parts.at(-1) };
}

function blockMap(document, blockId) {
  const { systemPath, name } = splitId(blockId);
  const block = blockMapIn(systemMap(document, systemPath), name);
  if (!block) throw new ModelEditError(`no block '${blockId}' in the text`);
  return block;
}

// Adds `key: value` to a map in its own style: inside the braces of a flow map, or as a new line
// at the map's indentation. `before` names a key the new one should precede when present, so that
// a block keeps the usual order (inputs before outputs).
function addEntry(text, map, key, value, before) {
  const entry = `${key}: ${value}`;
  const following = before ? pairOf(map, before) : undefined;
  if (map.flow) {
    if (following) return { from: following.key.range[0], to: following.key.range[0], insert: `${entry}, ` };
    const last = map.items.at(-1);
    if (!last) return { from: map.range[0] + 1, to: map.range[0] + 1, insert: entry };
    const at = contentEnd(text, last.value ?? last.key);
    return { from: at, to: at, insert: `, ${entry}` };
  }
  const first = map.items[0];
  const indent = indentOf(text, first.key.range[0]);
  if (following) {
    const at = following.key.range[0];
    return { from: at, to: at, insert: `${entry}\n${indent}` };
  }
  const at = lineEnd(text, contentEnd(text, map));
  return { from: at, to: at, insert: `\n${indent}${entry}` };
}

function replaceNode(node, insert) {
  return { from: node.range[0], to: node.range[1], insert };
}

// The node naming the signal of a port entry: the value itself, or a Code block's `{signal: ...}`.
function portSignalNode(value) {
  if (isMap(value)) return pairOf(value, 'signal')?.value;
  return value;
}

// Sets one entry of a block's `inputs`/`outputs`/`parameters` map, adding the map when missing.
function setBlockEntry(text, block, section, key, value) {
  const sectionPair = pairOf(block, section);
  if (!sectionPair || sectionPair.value == null || (isScalar(sectionPair.value) && sectionPair.value.value == null)) {
    if (sectionPair) throw new ModelEditError(`'${section}' of the block is empty: write it as a map first`);
    const before = { parameters: 'inputs', inputs: 'outputs' }[section];
    const following = before && pairOf(block, before) ? before : before === 'inputs' && pairOf(block, 'outputs') ? 'outputs' : undefined;
    return [addEntry(text, block, section, `{${key}: ${value}}`, following)];
  }
  if (!isMap(sectionPair.value)) throw new ModelEditError(`'${section}' of the block is not a map`);
  const existing = pairOf(sectionPair.value, key);
  if (!existing) return [addEntry(text, sectionPair.value, key, value)];
  if (section === 'parameters') return [replaceNode(existing.value, value)];
  const signalNode = portSignalNode(existing.value);
  if (!signalNode) throw new ModelEditError(`port '${key}' names no signal to replace`);
  return [replaceNode(signalNode, value)];
}

export function setPortSignal(text, blockId, direction, port, signal) {
  return setBlockEntry(text, blockMap(parse(text), blockId), direction, port, signal);
}

// The text of a new block item: flow style, on one line, at the indentation of its siblings.
function blockItemText({ name, type, parameters }) {
  const fields = [`name: ${name}`, `type: ${type}`];
  if (parameters.length > 0) fields.push(`parameters: {${parameters.map(([key, value]) => `${key}: ${value}`).join(', ')}}`);
  return `{${fields.join(', ')}}`;
}

export function addBlock(text, systemPath, block) {
  const document = parse(text);
  const system = systemMap(document, systemPath);
  const item = blockItemText(block);
  const blocksPair = pairOf(system, 'blocks');
  const blocks = blocksPair?.value;
  if (!blocksPair || blocks == null || (isScalar(blocks) && blocks.value == null)) {
    if (blocksPair) return [{ from: blocksPair.key.range[1], to: contentEnd(text, blocksPair.value ?? blocksPair.key), insert: `: [${item}]` }];
    return [addEntry(text, system, 'blocks', `[${item}]`)];
  }
  if (!isSeq(blocks)) throw new ModelEditError("'blocks' is not a list");
  if (blocks.flow) {
    const last = blocks.items.at(-1);
    if (!last) return [{ from: blocks.range[0] + 1, to: blocks.range[0] + 1, insert: item }];
    const at = contentEnd(text, last);
    return [{ from: at, to: at, insert: `, ${item}` }];
  }
  // The dash of the first item gives the column; the new item goes on a line after the last one.
  const firstStart = blocks.items[0].range[0];
  const dashLine = text.slice(lineStart(text, firstStart), firstStart);
  const dashIndent = dashLine.match(/^(\s*)-/)?.[1] ?? '';
  const at = lineEnd(text, contentEnd(text, blocks));
  return [{ from: at, to: at, insert: `\n${dashIndent}- ${item}` }];
}

export function deleteBlock(text, blockId) {
  const document = parse(text);
  const { systemPath } = splitId(blockId);
  const blocks = pairOf(systemMap(document, systemPath), 'blocks').value;
  const block = blockMap(document, blockId);
  const index = blocks.items.indexOf(block);
  if (blocks.flow) {
    // In `[a, b, c]`: take the item with the comma before it (or after it, for the first).
    const neighbour = blocks.items[index - 1] ?? blocks.items[index + 1];
    if (!neighbour) return [{ from: blocks.range[0] + 1, to: blocks.range[1] - 1, insert: '' }];
    if (index > 0) return [{ from: contentEnd(text, neighbour), to: contentEnd(text, block), insert: '' }];
    return [{ from: block.range[0], to: neighbour.range[0], insert: '' }];
  }
  const start = lineStart(text, block.range[0]);
  if (!/^\s*-\s+$/.test(text.slice(start, block.range[0]))) throw new ModelEditError(`block '${blockId}' does not start its own line`);
  const end = lineEnd(text, contentEnd(text, block));
  if (blocks.items.length === 1) {
    // The last block of a list: leave an empty list rather than a `blocks:` without value.
    const blocksPair = pairOf(systemMap(document, systemPath), 'blocks');
    return [{ from: blocksPair.key.range[1], to: end, insert: ': []' }];
  }
  return [{ from: start, to: Math.min(end + 1, text.length), insert: '' }];
}

export function setBlockParameter(text, blockId, name, value) {
  return setBlockEntry(text, blockMap(parse(text), blockId), 'parameters', name, value);
}

// Removes an optional parameter's entry (with its separating comma or its line).
export function removeBlockParameter(text, blockId, name) {
  const block = blockMap(parse(text), blockId);
  const parameters = pairOf(block, 'parameters')?.value;
  const pair = isMap(parameters) ? pairOf(parameters, name) : undefined;
  if (!pair) return [];
  const index = parameters.items.indexOf(pair);
  const pairEnd = contentEnd(text, pair.value ?? pair.key);
  if (parameters.flow) {
    const previous = parameters.items[index - 1];
    const next = parameters.items[index + 1];
    if (previous) return [{ from: contentEnd(text, previous.value ?? previous.key), to: pairEnd, insert: '' }];
    if (next) return [{ from: pair.key.range[0], to: next.key.range[0], insert: '' }];
    return [{ from: parameters.range[0] + 1, to: parameters.range[1] - 1, insert: '' }];
  }
  if (parameters.items.length === 1) {
    const sectionPair = pairOf(block, 'parameters');
    return [{ from: sectionPair.key.range[1], to: lineEnd(text, pairEnd), insert: ': {}' }];
  }
  const start = lineStart(text, pair.key.range[0]);
  return [{ from: start, to: Math.min(lineEnd(text, pairEnd) + 1, text.length), insert: '' }];
}

// A model parameter's value under the top-level `parameters:` (`{value: ...}` or a bare value).
export function setModelParameterValue(text, name, value) {
  const document = parse(text);
  const parameters = pairOf(document.contents, 'parameters')?.value;
  const pair = isMap(parameters) ? pairOf(parameters, name) : undefined;
  if (!pair) throw new ModelEditError(`no model parameter '${name}' in the text`);
  if (!isMap(pair.value)) return [replaceNode(pair.value, value)];
  const valuePair = pairOf(pair.value, 'value');
  if (!valuePair) return [addEntry(text, pair.value, 'value', value)];
  return [{ from: valuePair.value.range[0], to: contentEnd(text, valuePair.value), insert: value }];
}

// Every place a system names its signals: its blocks' port values (a Code block's `signal:`),
// their `enable:` and `trigger: {signal:}`, and, seen from inside, the keys of the subsystem's own
// `inputs`/`outputs` (its inner signal names), plus the top level's `signals:` declarations.
function signalPlaces(document, systemPath) {
  const places = [];
  const system = systemMap(document, systemPath);
  for (const block of blocksOf(system)) {
    for (const direction of ['inputs', 'outputs']) {
      const ports = pairOf(block, direction)?.value;
      if (!isMap(ports)) continue;
      for (const pair of ports.items) {
        const node = portSignalNode(pair.value);
        if (isScalar(node)) places.push(node);
      }
    }
    const enable = pairOf(block, 'enable')?.value;
    if (isScalar(enable)) places.push(enable);
    const trigger = pairOf(block, 'trigger')?.value;
    const triggerSignal = isMap(trigger) ? pairOf(trigger, 'signal')?.value : undefined;
    if (isScalar(triggerSignal)) places.push(triggerSignal);
  }
  if (systemPath) {
    const { systemPath: parentPath, name } = splitId(systemPath);
    const own = blockMapIn(systemMap(document, parentPath), name);
    for (const direction of ['inputs', 'outputs']) {
      const ports = pairOf(own, direction)?.value;
      if (isMap(ports)) for (const pair of ports.items) if (isScalar(pair.key)) places.push(pair.key);
    }
  } else {
    const declarations = pairOf(document.contents, 'signals')?.value;
    if (isMap(declarations)) for (const pair of declarations.items) if (isScalar(pair.key)) places.push(pair.key);
  }
  return places;
}

// Renames a signal everywhere this system names it; the changes run from the end of the text to
// its start, so each one's offsets hold after the ones before it.
export function renameSignal(text, systemPath, oldName, newName) {
  if (!isIdentifier(newName)) throw new ModelEditError(`'${newName}' is not a name (letters, digits, _; not starting with a digit)`);
  const document = parse(text);
  const places = signalPlaces(document, systemPath);
  if (places.some((node) => String(node.value) === newName)) throw new ModelEditError(`this system already has a signal '${newName}'`);
  return places
    .filter((node) => String(node.value) === oldName)
    .sort((a, b) => b.range[0] - a.range[0])
    .map((node) => replaceNode(node, newName));
}

// Names already taken in a system: its blocks' names and its signals' names.
export function systemNames(text, systemPath) {
  const document = parse(text);
  const system = systemMap(document, systemPath);
  const blocks = new Set(blocksOf(system).map((block) => scalarText(pairOf(block, 'name')?.value)));
  const signals = new Set(signalPlaces(document, systemPath).map((node) => String(node.value)));
  return { blocks, signals };
}

// Connects an output to an input. The input takes the output's signal; an output without one
// gets a new name (`block_port`, unique in the system) first. The second change is computed on the
// text the first one left, since both may touch the same block.
export function connectPorts(text, from, to) {
  const { systemPath } = splitId(to.block);
  let signal = from.signal;
  const changes = [];
  let current = text;
  if (!signal) {
    const { signals } = systemNames(text, systemPath);
    signal = uniqueName(`${splitId(from.block).name}_${from.port}`, signals);
    const outputChanges = setPortSignal(current, from.block, 'outputs', from.port, signal);
    changes.push(...outputChanges);
    current = applyChanges(current, outputChanges);
  }
  changes.push(...setPortSignal(current, to.block, 'inputs', to.port, signal));
  return { changes, signal };
}

export function isIdentifier(name) {
  return /^[A-Za-z_][A-Za-z0-9_]*$/.test(name);
}

// `base` itself when free, else base_2, base_3, ...
export function uniqueName(base, taken) {
  if (!taken.has(base)) return base;
  for (let n = 2; ; n += 1) if (!taken.has(`${base}_${n}`)) return `${base}_${n}`;
}

// A new block's name: its type in snake case, numbered (gain_1, gain_2, ...) as Simulink does.
export function newBlockName(type, taken) {
  const stem = type.replace(/([a-z0-9])([A-Z])/g, '$1_$2').toLowerCase().replace(/[^a-z0-9_]/g, '_');
  for (let n = 1; ; n += 1) if (!taken.has(`${stem}_${n}`)) return `${stem}_${n}`;
}

// How a value the user typed is written: numbers, names, `true`/`false` and flow lists as they
// are; anything else (`>=`, `+-`, text with spaces) double-quoted, so that YAML reads it back as
// the same string.
export function yamlValue(typed) {
  const value = typed.trim();
  if (/^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(value)) return value;
  if (isIdentifier(value)) return value;
  if (/^\[.*\]$/s.test(value)) {
    const probe = parseDocument(`v: ${value}`);
    if (probe.errors.length === 0 && isSeq(probe.contents.get('v', true))) return value;
  }
  return JSON.stringify(value);
}
