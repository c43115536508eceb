import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { parse } from 'yaml';
import {
  addBlock, applyChanges, connectPorts, deleteBlock, ModelEditError, newBlockName, removeBlockParameter, renameSignal,
  setBlockParameter, setModelParameterValue, setPortSignal, systemNames, uniqueName, yamlValue,
} from '../src/studio/yaml_edit.js';

const model = (path) => readFileSync(new URL(`../../${path}`, import.meta.url), 'utf8');
const pidDemo = model('apps/pid_demo/pid_demo.yaml');
const balbot = model('apps/balbot/balbot.yaml');
const blockTour = model('apps/block_tour/block_tour.yaml');

// The lines an edit changed: what was there and what is there now, between the common first
// and last lines. Everything outside them is byte-identical by construction of this comparison.
function lineDiff(before, after) {
  const a = before.split('\n');
  const b = after.split('\n');
  let head = 0;
  while (head < a.length && head < b.length && a[head] === b[head]) head += 1;
  let tail = 0;
  while (tail < a.length - head && tail < b.length - head && a[a.length - 1 - tail] === b[b.length - 1 - tail]) tail += 1;
  return { removed: a.slice(head, a.length - tail), added: b.slice(head, b.length - tail), at: head + 1 };
}

function edit(text, changes) {
  const after = applyChanges(text, changes);
  return { after, ...lineDiff(text, after), model: parse(after) };
}

function findBlock(modelObject, id) {
  let blocks = modelObject.blocks;
  let block;
  for (const name of id.split('/')) {
    block = blocks.find((b) => b.name === name);
    blocks = block?.blocks;
  }
  return block;
}

test('add a block at the top level: one new flow-style line after the last block, same indentation', () => {
  const result = edit(pidDemo, addBlock(pidDemo, '', { name: 'gain_1', type: 'Gain', parameters: [['k', '1']] }));
  assert.deepEqual(result.removed, []);
  assert.deepEqual(result.added, ['  - {name: gain_1, type: Gain, parameters: {k: 1}}']);
  assert.equal(result.at, pidDemo.split('\n').indexOf('  - {name: trim_ramp, type: Sum, inputs: {u1: offset_before, u2: trim_step}, outputs: {y: offset_next}}') + 2);
  assert.deepEqual(findBlock(result.model, 'gain_1'), { name: 'gain_1', type: 'Gain', parameters: { k: 1 } });
  assert.equal(result.after.endsWith('\n'), true, 'the final newline stays');
});

test('add a block after a block-style last item and into a nested subsystem, keeping comments', () => {
  // balbot ends with a block-style item; its subsystems hold flow-style items at a deeper indentation.
  const top = edit(balbot, addBlock(balbot, '', { name: 'abs_1', type: 'Abs', parameters: [] }));
  assert.deepEqual(top.added, ['  - {name: abs_1, type: Abs}']);
  assert.equal(top.model.blocks.at(-1).name, 'abs_1');
  assert.equal(top.model.blocks.at(-2).name, 'messages_to_step');

  const inner = edit(balbot, addBlock(balbot, 'hall_left', { name: 'gain_1', type: 'Gain', parameters: [['k', '2']] }));
  assert.deepEqual(inner.removed, []);
  assert.deepEqual(inner.added, ['      - {name: gain_1, type: Gain, parameters: {k: 2}}']);
  assert.equal(findBlock(inner.model, 'hall_left').blocks.at(-1).name, 'gain_1');
  assert.equal(findBlock(inner.model, 'hall_left').blocks.at(-2).name, 'previous');
  assert.match(inner.after, /# Travel: 2 pi r_w \/ 450/);
});

test('add into a block-style sequence whose last item ends with comments keeps them after it', () => {
  const text = 'blocks:\n  - name: a\n    type: Abs\n    # about a\n\n  # the end\n';
  const result = edit(text, addBlock(text, '', { name: 'b', type: 'Sign', parameters: [] }));
  assert.equal(result.after, 'blocks:\n  - name: a\n    type: Abs\n  - {name: b, type: Sign}\n    # about a\n\n  # the end\n');
  assert.deepEqual(result.model.blocks.map((b) => b.name), ['a', 'b']);
});

test('add into a flow-style blocks list, an empty one and a system without blocks', () => {
  const flow = 'name: m\nblocks: [{name: a, type: Abs}]  # one\n';
  assert.equal(applyChanges(flow, addBlock(flow, '', { name: 'b', type: 'Sign', parameters: [] })), 'name: m\nblocks: [{name: a, type: Abs}, {name: b, type: Sign}]  # one\n');
  const empty = 'name: m\nblocks: []\n';
  assert.equal(applyChanges(empty, addBlock(empty, '', { name: 'b', type: 'Sign', parameters: [] })), 'name: m\nblocks: [{name: b, type: Sign}]\n');
  const none = 'name: m\nbase_period_us: 100\n';
  assert.equal(applyChanges(none, addBlock(none, '', { name: 'b', type: 'Sign', parameters: [] })), 'name: m\nbase_period_us: 100\nblocks: [{name: b, type: Sign}]\n');
});

test('connect: a new input key in a flow map, an existing output signal reused', () => {
  let text = applyChanges(pidDemo, addBlock(pidDemo, '', { name: 'gain_1', type: 'Gain', parameters: [['k', '1']] }));
  const { changes, signal } = connectPorts(text, { block: 'compare_angle', port: 'y', signal: 'error' }, { block: 'gain_1', port: 'u' });
  assert.equal(signal, 'error');
  const result = edit(text, changes);
  assert.deepEqual(result.removed, ['  - {name: gain_1, type: Gain, parameters: {k: 1}}']);
  assert.deepEqual(result.added, ['  - {name: gain_1, type: Gain, parameters: {k: 1}, inputs: {u: error}}']);
  text = result.after;

  // The gain's y has no signal yet: it gets gain_1_y on its outputs, and the PID's error input takes it.
  const second = connectPorts(text, { block: 'gain_1', port: 'y' }, { block: 'pid', port: 'error' });
  assert.equal(second.signal, 'gain_1_y');
  const connected = edit(text, second.changes);
  assert.deepEqual(findBlock(connected.model, 'gain_1').outputs, { y: 'gain_1_y' });
  assert.deepEqual(findBlock(connected.model, 'pid').inputs, { error: 'gain_1_y' });
  // Only the gain's line and the PID's input line changed; the block-style PID keeps its layout.
  // Only the PID's input line and the gain's line changed; the block-style PID keeps its layout.
  const changed = lineDiff(text, connected.after);
  const beforeLines = text.split('\n');
  const afterLines = connected.after.split('\n');
  assert.equal(afterLines.length, beforeLines.length);
  const differing = beforeLines.flatMap((line, i) => (line === afterLines[i] ? [] : [[line, afterLines[i]]]));
  assert.deepEqual(differing, [
    ['    inputs: {error: error}', '    inputs: {error: gain_1_y}'],
    ['  - {name: gain_1, type: Gain, parameters: {k: 1}, inputs: {u: error}}', '  - {name: gain_1, type: Gain, parameters: {k: 1}, inputs: {u: error}, outputs: {y: gain_1_y}}'],
  ]);
  assert.ok(changed.removed.length > 0);
});

test('connect into an input that has a signal replaces only that value', () => {
  const result = edit(pidDemo, setPortSignal(pidDemo, 'add_trim', 'inputs', 'u2', 'theta'));
  assert.deepEqual(result.removed, ['  - {name: add_trim, type: Sum, inputs: {u1: reference, u2: offset}, outputs: {y: setpoint}}']);
  assert.deepEqual(result.added, ['  - {name: add_trim, type: Sum, inputs: {u1: reference, u2: theta}, outputs: {y: setpoint}}']);
});

test('ports: block-style maps get a new line at their indentation; a missing inputs map goes before outputs', () => {
  const text = 'blocks:\n  - name: s\n    type: Sum\n    inputs:\n      u1: a   # first\n    outputs: {y: b}\n  - {name: c, type: Counter, outputs: {y: n}}\n';
  assert.equal(applyChanges(text, setPortSignal(text, 's', 'inputs', 'u2', 'z')), 'blocks:\n  - name: s\n    type: Sum\n    inputs:\n      u1: a   # first\n      u2: z\n    outputs: {y: b}\n  - {name: c, type: Counter, outputs: {y: n}}\n');
  assert.equal(applyChanges(text, setPortSignal(text, 'c', 'inputs', 'reset', 'r')), 'blocks:\n  - name: s\n    type: Sum\n    inputs:\n      u1: a   # first\n    outputs: {y: b}\n  - {name: c, type: Counter, inputs: {reset: r}, outputs: {y: n}}\n');
  const blockStyle = 'blocks:\n  - name: g\n    type: Gain\n    parameters: {k: 2}\n    outputs: {y: b}\n';
  assert.equal(applyChanges(blockStyle, setPortSignal(blockStyle, 'g', 'inputs', 'u', 'a')), 'blocks:\n  - name: g\n    type: Gain\n    parameters: {k: 2}\n    inputs: {u: a}\n    outputs: {y: b}\n');
  const bare = 'blocks:\n  - name: g\n    type: Gain\n';
  assert.equal(applyChanges(bare, setPortSignal(bare, 'g', 'outputs', 'y', 'b')), 'blocks:\n  - name: g\n    type: Gain\n    outputs: {y: b}\n');
});

test("a Code block's port takes the signal in its {signal: ...} map", () => {
  const result = edit(pidDemo, setPortSignal(pidDemo, 'motor_logic', 'inputs', 'duty', 'command'));
  assert.deepEqual(result.removed, ['    inputs: {duty: {signal: duty, type: single}, stop: {signal: stop, type: boolean}}']);
  assert.deepEqual(result.added, ['    inputs: {duty: {signal: command, type: single}, stop: {signal: stop, type: boolean}}']);
});

test('connect inside a nested subsystem names the signal locally and edits only the subsystem', () => {
  const { changes, signal } = connectPorts(balbot, { block: 'hall_left/signed', port: 'y', signal: 'speed' }, { block: 'hall_left/previous', port: 'u' });
  assert.equal(signal, 'speed');
  const result = edit(balbot, changes);
  assert.deepEqual(result.added, ['      - {name: previous, type: UnitDelay, parameters: {initial: 0}, inputs: {u: speed}, outputs: {y: before}}']);
  // hall_right has a block of the same name, untouched.
  assert.deepEqual(findBlock(result.model, 'hall_right/previous').inputs, { u: 'travelled' });
});

test('rename a top-level signal: every port value, enable/trigger uses and its declaration; nothing inside subsystems', () => {
  const result = edit(pidDemo, renameSignal(pidDemo, '', 'stop', 'halt_now'));
  const m = result.model;
  assert.ok('halt_now' in m.signals && !('stop' in m.signals));
  assert.equal(Object.keys(m.signals).indexOf('halt_now'), Object.keys(parse(pidDemo).signals).indexOf('stop'), 'the declaration stays in place');
  assert.deepEqual(findBlock(m, 'stop_any').outputs, { y: 'halt_now' });
  assert.deepEqual(findBlock(m, 'motors_off').inputs, { on: 'nothing', condition: 'halt_now', off: 'pid_output' });
  assert.deepEqual(findBlock(m, 'motor_logic').inputs.stop, { signal: 'halt_now', type: 'boolean' });
  assert.deepEqual(findBlock(m, 'stop_events').trigger, { edge: 'rising', signal: 'halt_now' });
  // The port *name* `stop` of motor_logic is not a signal name: it stays.
  assert.ok('stop' in findBlock(m, 'motor_logic').inputs);
  // Same line count, and every changed line had 'stop' on it.
  assert.equal(result.removed.length, result.added.length);
  const afterLines = result.after.split('\n');
  const differing = pidDemo.split('\n').filter((line, i) => line !== afterLines[i]);
  assert.equal(differing.length, 7); // the declaration, stop_any, motors_off, led, motor_logic, stop_events, stop_to_supervision
  assert.ok(differing.every((line) => /\bstop\b/.test(line)));
  assert.ok(result.after.includes('  halt_now: {type: boolean, measurable: true, description: "the safety stop (LED0)"}\n'));
});

test("rename inside a subsystem: its blocks' ports and the subsystem's own port key in the parent", () => {
  const result = edit(pidDemo, renameSignal(pidDemo, 'monitor', 'e', 'error_in'));
  const monitor = findBlock(result.model, 'monitor');
  assert.deepEqual(monitor.inputs, { error_in: 'error_slow' });
  assert.deepEqual(findBlock(result.model, 'monitor/magnitude').inputs, { u: 'error_in' });
  assert.deepEqual(result.removed, ['    inputs: {e: error_slow}', '    outputs: {integral: iae}', '    blocks:', '      - {name: magnitude, type: Abs, inputs: {u: e}, outputs: {y: e_magnitude}}']);
  assert.deepEqual(result.added, ['    inputs: {error_in: error_slow}', '    outputs: {integral: iae}', '    blocks:', '      - {name: magnitude, type: Abs, inputs: {u: error_in}, outputs: {y: e_magnitude}}']);
  // The parent's signal that feeds it keeps its name.
  assert.deepEqual(findBlock(result.model, 'error_to_supervision').outputs, { y: 'error_slow' });
});

test('rename refuses a name in use and a malformed name', () => {
  assert.throws(() => renameSignal(pidDemo, '', 'stop', 'theta'), ModelEditError);
  assert.throws(() => renameSignal(pidDemo, '', 'stop', '2x'), ModelEditError);
});

test('delete a flow-style block (its line), a block-style block (all its lines) and a nested one', () => {
  const flow = edit(pidDemo, deleteBlock(pidDemo, 'angle_size'));
  assert.deepEqual(flow.removed, ['  - {name: angle_size, type: Abs, inputs: {u: theta}, outputs: {y: angle_magnitude}}']);
  assert.deepEqual(flow.added, []);
  const block = edit(pidDemo, deleteBlock(pidDemo, 'pid'));
  assert.deepEqual(block.removed, ['  - name: pid', '    type: DiscretePid', '    parameters: {p: Kp, i: Ki, d: Kd, n: N, lower: -1, upper: 1}', '    inputs: {error: error}', '    outputs: {y: pid_output}']);
  assert.deepEqual(block.added, []);
  assert.ok(block.after.includes('  # The controller.\n  - {name: angle_size'), 'the comment before it stays');
  const nested = edit(balbot, deleteBlock(balbot, 'filter/kalman'));
  assert.deepEqual(findBlock(nested.model, 'filter').blocks, []);
  assert.deepEqual(nested.added, ['    blocks: []']);
  const last = edit(balbot, deleteBlock(balbot, 'messages_to_step'));
  assert.equal(last.model.blocks.at(-1).name, 'lqr_to_step');
  assert.ok(last.after.endsWith('outputs: {y: lqr_linux}}\n'));
});

test('delete from a flow list takes the comma with it', () => {
  const text = 'blocks: [{name: a, type: Abs}, {name: b, type: Sign}, {name: c, type: Not}]\n';
  assert.equal(applyChanges(text, deleteBlock(text, 'a')), 'blocks: [{name: b, type: Sign}, {name: c, type: Not}]\n');
  assert.equal(applyChanges(text, deleteBlock(text, 'b')), 'blocks: [{name: a, type: Abs}, {name: c, type: Not}]\n');
  assert.equal(applyChanges(text, deleteBlock(text, 'c')), 'blocks: [{name: a, type: Abs}, {name: b, type: Sign}]\n');
});

test('block parameters: replace a value, add one, remove one, in flow and block style', () => {
  const replaced = edit(pidDemo, setBlockParameter(pidDemo, 'position', 'k', '0.004'));
  assert.deepEqual(replaced.added, ['  - {name: position, type: Gain, parameters: {k: 0.004}, inputs: {u: count_single}, outputs: {y: index}}']);
  const added = edit(pidDemo, setBlockParameter(pidDemo, 'add_trim', 'signs', '"+-"'));
  assert.deepEqual(added.added, ['  - {name: add_trim, type: Sum, parameters: {signs: "+-"}, inputs: {u1: reference, u2: offset}, outputs: {y: setpoint}}']);
  assert.equal(findBlock(added.model, 'add_trim').parameters.signs, '+-');
  const quoted = edit(pidDemo, setBlockParameter(pidDemo, 'beyond_limit', 'operator', '">="'));
  assert.deepEqual(quoted.added, ['    parameters: {operator: ">=", value: angle_limit}']);
  const removed = edit(pidDemo, removeBlockParameter(pidDemo, 'pid', 'n'));
  assert.deepEqual(removed.added, ['    parameters: {p: Kp, i: Ki, d: Kd, lower: -1, upper: 1}']);
  const first = edit(pidDemo, removeBlockParameter(pidDemo, 'pid', 'p'));
  assert.deepEqual(first.added, ['    parameters: {i: Ki, d: Kd, n: N, lower: -1, upper: 1}']);
  const text = 'blocks:\n  - name: s\n    type: Saturation\n    parameters:\n      lower: -1  # low\n      upper: 1\n';
  assert.equal(applyChanges(text, setBlockParameter(text, 's', 'upper', '2')), text.replace('upper: 1', 'upper: 2'));
  assert.equal(applyChanges(text, removeBlockParameter(text, 's', 'lower')), 'blocks:\n  - name: s\n    type: Saturation\n    parameters:\n      upper: 1\n');
});

test("a model parameter's value, flow and block style, a matrix", () => {
  const kp = edit(pidDemo, setModelParameterValue(pidDemo, 'Kp', '0.03'));
  assert.deepEqual(kp.added, ['  Kp: {value: 0.03, type: single, min: 0, max: 1, unit: "1/deg", description: "proportional gain"}']);
  const disturbance = edit(pidDemo, setModelParameterValue(pidDemo, 'disturbance', '-3'));
  assert.deepEqual(disturbance.removed, ['    value: -2']);
  assert.deepEqual(disturbance.added, ['    value: -3']);
  const matrix = edit(balbot, setModelParameterValue(balbot, 'kalman_R', '[[1, 0], [0, 0.001]]'));
  assert.deepEqual(matrix.added, ['    value: [[1, 0], [0, 0.001]]']);
});

test('every other model of the repository takes an added block and a deletion cleanly', () => {
  for (const path of ['apps/block_tour/block_tour.yaml', 'apps/step_time/step_time.yaml', 'apps/thermostat/thermostat.yaml', 'apps/thermostat/heater.yaml', 'apps/transfer_test/transfer_test.yaml']) {
    const text = model(path);
    const before = parse(text);
    const added = edit(text, addBlock(text, '', { name: 'zz_new', type: 'Abs', parameters: [] }));
    assert.deepEqual(added.removed, [], path);
    assert.equal(added.added.length, 1, path);
    assert.deepEqual(added.model.blocks.slice(0, -1), before.blocks, path);
    const first = before.blocks[0].name;
    const deleted = edit(text, deleteBlock(text, first));
    assert.deepEqual(deleted.model.blocks, before.blocks.slice(1), path);
    assert.deepEqual(deleted.added, [], path);
  }
  assert.ok(blockTour.length > 0);
});

test('CRLF-free offsets: edits never touch a carriage return the text keeps elsewhere', () => {
  // The editor hands "\n" text; a stray "\r" inside a line is content and survives untouched.
  const text = 'blocks:\n  - {name: a, type: Abs}\n';
  assert.equal(applyChanges(text, addBlock(text, '', { name: 'b', type: 'Sign', parameters: [] })), 'blocks:\n  - {name: a, type: Abs}\n  - {name: b, type: Sign}\n');
});

test('names: free names, numbered block names, names in use per system', () => {
  assert.equal(uniqueName('gain_1_y', new Set()), 'gain_1_y');
  assert.equal(uniqueName('x', new Set(['x', 'x_2'])), 'x_3');
  assert.equal(newBlockName('DiscretePid', new Set()), 'discrete_pid_1');
  assert.equal(newBlockName('Gain', new Set(['gain_1'])), 'gain_2');
  const names = systemNames(pidDemo, 'monitor');
  assert.deepEqual([...names.blocks], ['magnitude', 'integrate']);
  assert.ok(names.signals.has('e') && names.signals.has('e_magnitude') && !names.signals.has('theta'));
});

test('typed values: numbers, names and lists plain; operators and text quoted', () => {
  assert.equal(yamlValue(' 2.5 '), '2.5');
  assert.equal(yamlValue('-1e-3'), '-1e-3');
  assert.equal(yamlValue('Kp'), 'Kp');
  assert.equal(yamlValue('[[1, 0], [0, 1]]'), '[[1, 0], [0, 1]]');
  assert.equal(yamlValue('>='), '">="');
  assert.equal(yamlValue('+-'), '"+-"');
  assert.equal(yamlValue('[1, 2'), '"[1, 2"');
  assert.equal(yamlValue('a b'), '"a b"');
});

test('edits refuse a text that does not read as YAML, and unknown blocks', () => {
  assert.throws(() => addBlock('blocks: [\n', '', { name: 'a', type: 'Abs', parameters: [] }), ModelEditError);
  assert.throws(() => deleteBlock(pidDemo, 'no_such_block'), ModelEditError);
  assert.throws(() => addBlock(pidDemo, 'no/such', { name: 'a', type: 'Abs', parameters: [] }), ModelEditError);
});
