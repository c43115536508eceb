import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Text } from '@codemirror/state';
import { CheckLoop } from '../src/studio/check_loop.js';
import { blockAtLine, findWire, textRangeOf, wireAtCursor, wireSelection } from '../src/studio/selection_sync.js';
import { blockMarkers, checkSummary, inOpenFile, lintDiagnostics, placeText, positionOf } from '../src/studio/diagnostics.js';
import { defaultValue, modelValueProblem, parameterProblem } from '../src/studio/parameter_rules.js';
import { lineSeparatorOf } from '../src/studio/editor.js';

function loopWithClock() {
  const sent = [];
  let now = 0;
  let connected = true;
  const loop = new CheckLoop((request) => connected && sent.push(request) > 0, () => now);
  return { loop, sent, tick: (ms) => (now += ms), disconnect: () => (connected = false) };
}

test('check loop: one check in flight; edits meanwhile coalesce into one send of the newest text', () => {
  const { loop, sent, tick } = loopWithClock();
  loop.loaded('a', { answerComing: true });
  assert.equal(sent.length, 0, 'the server answers the loaded text by itself (seq 0)');
  loop.edited('ab');
  assert.equal(sent.length, 0, 'nothing is sent while seq 0 is awaited');
  assert.deepEqual(loop.answered({ seq: 0 }), []);
  assert.deepEqual(sent, [{ type: 'check', text: 'ab', seq: 1 }]);
  tick(10);
  loop.edited('abc');
  tick(10);
  loop.edited('abcd');
  assert.equal(sent.length, 1, 'at most one in flight');
  tick(30);
  const times = loop.answered({ seq: 1 });
  assert.equal(times.length, 1, 'the answer covers the one edit it was sent for');
  assert.deepEqual(sent.at(-1), { type: 'check', text: 'abcd', seq: 2 });
  assert.deepEqual(loop.answered({ seq: 2 }), [10, 20], 'both coalesced edits are covered, with their own times');
  assert.equal(loop.pending, false);
});

test('check loop: answers with an old or unknown seq are ignored; an unchanged text is not re-sent', () => {
  const { loop, sent } = loopWithClock();
  loop.loaded('a', { answerComing: true });
  loop.answered({ seq: 0 });
  loop.edited('ab');
  assert.equal(loop.answered({ seq: 0 }), null, 'a late duplicate of an old answer');
  assert.equal(loop.answered({ seq: 7 }), null);
  assert.ok(loop.answered({ seq: 1 }));
  assert.equal(sent.length, 1, 'nothing changed since: no new check');
});

test('check loop: a reload sends its text at once; without a connection nothing counts as in flight', () => {
  const { loop, sent, disconnect } = loopWithClock();
  loop.loaded('x', { answerComing: false });
  assert.deepEqual(sent, [{ type: 'check', text: 'x', seq: 1 }]);
  loop.answered({ seq: 1 });
  disconnect();
  loop.edited('xy');
  assert.equal(loop.pending, false, 'the unsent edit waits for the next loaded text');
});

// A small diagram in the server's shape: a top level and one subsystem.
const diagram = {
  root: {
    path: '',
    blocks: [
      { id: 'gain', name: 'gain', type: 'Gain', line: 3, column: 5, end_line: 3, inputs: [{ port: 'u', signal: 'theta', line: 3, column: 39 }], outputs: [{ port: 'y', signal: 'scaled', line: 3, column: 60 }] },
      {
        id: 'sub', name: 'sub', type: 'Subsystem', line: 4, column: 5, end_line: 8,
        inputs: [{ port: 'e', signal: 'scaled', line: 6, column: 14 }], outputs: [],
        system: {
          path: 'sub',
          blocks: [{ id: 'sub/abs', name: 'abs', type: 'Abs', line: 8, column: 10, end_line: 8, inputs: [{ port: 'u', signal: 'e', line: 8, column: 41 }], outputs: [] }],
          wires: [{ id: 'sub:e', signal: 'e', resolved: 'sub.e', source: { system_input: 'e' }, targets: [{ block: 'sub/abs', port: 'u' }] }],
        },
      },
    ],
    wires: [
      { id: ':theta', signal: 'theta', resolved: 'theta', measurement: 'theta', line: 1, column: 11, targets: [{ block: 'gain', port: 'u' }] },
      { id: ':scaled', signal: 'scaled', resolved: 'scaled', line: 3, column: 60, source: { block: 'gain', port: 'y' }, targets: [{ block: 'sub', port: 'e' }] },
    ],
  },
};
const text = [
  'signals: {theta: {unit: deg}}',
  'blocks:',
  '  - {name: gain, type: Gain, inputs: {u: theta}, outputs: {y: scaled}}',
  '  - name: sub',
  '    type: Subsystem',
  '    inputs: {e: scaled}',
  '    blocks:',
  '      - {name: abs, type: Abs, inputs: {u: e}}',
].join('\n');
const doc = Text.of(text.split('\n'));

test('text -> diagram: the innermost block of a line, the wire under a signal name', () => {
  assert.equal(blockAtLine(diagram.root, 3).id, 'gain');
  assert.equal(blockAtLine(diagram.root, 5).id, 'sub');
  assert.equal(blockAtLine(diagram.root, 8).id, 'sub/abs');
  assert.equal(blockAtLine(diagram.root, 2), null);
  const lineText = (n) => doc.line(n).text;
  // On `theta` of `u: theta` (columns 42..46): the top-level wire.
  assert.equal(wireAtCursor(diagram, 3, 43, lineText(3)).wire.id, ':theta');
  // On the port key `u` itself: not a wire (the block is selected instead).
  assert.equal(wireAtCursor(diagram, 3, 39, lineText(3)), null);
  // Inside the subsystem: its own wire `e`, with the system to navigate to.
  const inner = wireAtCursor(diagram, 8, 44, lineText(8));
  assert.deepEqual(wireSelection(inner), { kind: 'wire', id: 'sub:e', system: 'sub', signal: 'e', resolved: 'sub.e', measurement: undefined });
  // On a declaration's key.
  assert.equal(wireAtCursor(diagram, 1, 13, lineText(1)).wire.id, ':theta');
});

test('diagram -> text: a block selects its whole lines; a wire its name at the declaration or the driver', () => {
  const slice = (range) => text.slice(range.from, range.to);
  assert.equal(slice(textRangeOf(diagram, { kind: 'block', id: 'sub' }, doc)), '  - name: sub\n    type: Subsystem\n    inputs: {e: scaled}\n    blocks:\n      - {name: abs, type: Abs, inputs: {u: e}}');
  const theta = textRangeOf(diagram, { kind: 'wire', id: ':theta' }, doc);
  assert.equal(slice(theta), 'theta');
  assert.equal(theta.from, text.indexOf('theta'));
  // The driver's place is the port key `y`: the name after it is selected.
  const scaled = textRangeOf(diagram, { kind: 'wire', id: ':scaled' }, doc);
  assert.equal(scaled.from, text.indexOf('scaled}}'));
  assert.equal(slice(scaled), 'scaled');
  assert.equal(textRangeOf(diagram, null, doc), null);
  assert.equal(findWire(diagram, 'sub:e').system, 'sub');
});

test('diagnostics: at their line and column, underlining the word; markers per block; the summary', () => {
  const diagnostics = [
    { severity: 'error', line: 3, column: 42, message: "reads signal 'theta'", hint: 'declare it', block: 'gain' },
    { severity: 'warning', line: 99, column: 1, message: 'past the end' },
    { severity: 'error', line: 8, column: 41, message: 'inner', block: 'sub/abs' },
  ];
  const lint = lintDiagnostics(doc, diagnostics);
  assert.equal(text.slice(lint[0].from, lint[0].to), 'theta');
  assert.equal(lint[0].message, "reads signal 'theta' (declare it)");
  assert.equal(lint[1].severity, 'warning');
  assert.ok(lint[1].from >= doc.line(doc.lines).from, 'a place past the end lands on the last line');
  assert.equal(positionOf(doc, 2, 1), doc.line(2).from);
  assert.deepEqual([...blockMarkers(diagnostics).keys()], ['gain', 'sub/abs']);
  assert.deepEqual(checkSummary([]), { text: 'checked', state: 'ok' });
  assert.deepEqual(checkSummary(diagnostics), { text: '2 errors, 1 warning', state: 'error' });
  assert.deepEqual(checkSummary([diagnostics[1]]), { text: 'checked, 1 warning', state: 'warning' });
});

// A model reference: the subsystem `c` takes its blocks from controller.yaml, whose places the
// server names with their file; line 3 of controller.yaml is not line 3 of this text.
const referencing = {
  root: {
    path: '',
    blocks: [
      {
        id: 'c', name: 'c', type: 'Subsystem', line: 3, column: 5, end_line: 6,
        inputs: [{ port: 'theta', signal: 'theta', line: 6, column: 14 }], outputs: [],
        system: {
          path: 'c',
          blocks: [{ id: 'c/k', name: 'k', type: 'Gain', file: 'controller.yaml', line: 3, column: 5, end_line: 3, inputs: [{ port: 'u', signal: 'theta', file: 'controller.yaml', line: 3, column: 42 }], outputs: [] }],
          wires: [{ id: 'c:theta', signal: 'theta', resolved: 'theta', file: 'controller.yaml', line: 3, column: 45, source: { system_input: 'theta' }, targets: [{ block: 'c/k', port: 'u' }] }],
        },
      },
    ],
    wires: [{ id: ':theta', signal: 'theta', resolved: 'theta', line: 1, column: 11, targets: [{ block: 'c', port: 'theta' }] }],
  },
};
const referencingText = [
  'signals: {theta: {unit: deg}}',
  'blocks:',
  '  - name: c',
  '    type: Subsystem',
  '    model: controller.yaml',
  '    inputs: {theta: theta}',
].join('\n');
const referencingDoc = Text.of(referencingText.split('\n'));

test('a referenced model\'s places: listed with their file, never looked for in the open text', () => {
  const diagnostics = [
    { severity: 'error', file: 'loop.yaml', line: 6, column: 21, message: 'own', block: 'c' },
    { severity: 'error', file: 'controller.yaml', line: 3, column: 42, message: 'inside', block: 'c/k' },
    { severity: 'warning', file: 'controller.yaml', line: 9, column: 3, message: 'unused', block: null },
  ];
  assert.deepEqual(diagnostics.map((d) => inOpenFile(d, 'loop.yaml')), [true, false, false]);
  assert.ok(inOpenFile({ line: 1, column: 1 }, 'loop.yaml'), 'a diagnostic without a file is the open text\'s');
  assert.deepEqual(diagnostics.map((d) => placeText(d, 'loop.yaml')), ['6:21', 'controller.yaml:3:42', 'controller.yaml:9:3']);
  const lint = lintDiagnostics(referencingDoc, diagnostics, 'loop.yaml');
  assert.equal(lint.length, 1, 'only the open text\'s own diagnostic is on the text');
  assert.equal(referencingText.slice(lint[0].from, lint[0].to), 'theta');
  assert.deepEqual([...blockMarkers(diagnostics).keys()], ['c', 'c/k'], 'both still mark their blocks');
  // Line 3 of the text is the reference itself, not the block on line 3 of controller.yaml.
  assert.equal(blockAtLine(referencing.root, 3).id, 'c');
  assert.equal(textRangeOf(referencing, { kind: 'block', id: 'c/k' }, referencingDoc), null);
  assert.equal(textRangeOf(referencing, { kind: 'wire', id: 'c:theta' }, referencingDoc), null);
  const lineText = (n) => referencingDoc.line(n).text;
  assert.equal(wireAtCursor(referencing, 3, 46, '  - {name: k, type: Gain, inputs: {u: theta}}'), null, 'a port of controller.yaml is not on this text');
  assert.equal(wireAtCursor(referencing, 6, 23, lineText(6)).wire.id, ':theta');
});

test('parameter rules: required, choices, numbers with limits, names, model parameter values', () => {
  assert.equal(parameterProblem({ name: 'k', kind: 'number', required: true }, ' '), 'k is required');
  assert.equal(parameterProblem({ name: 'n', kind: 'number', required: false }, ''), '');
  assert.equal(parameterProblem({ name: 'operator', kind: 'word', choices: ['<', '>'] }, '>'), '');
  assert.match(parameterProblem({ name: 'operator', kind: 'word', choices: ['<', '>'] }, '=>'), /one of/);
  assert.equal(parameterProblem({ name: 'limit', kind: 'number', integer: true, min: 0 }, '4999'), '');
  assert.equal(parameterProblem({ name: 'limit', kind: 'number', integer: true, min: 0 }, '2.5'), 'a whole number');
  assert.equal(parameterProblem({ name: 'limit', kind: 'number', integer: true, min: 0 }, '-1'), 'at least 0');
  assert.equal(parameterProblem({ name: 'k', kind: 'number', max: 1 }, '[0.5, 2]'), 'at most 1');
  assert.equal(parameterProblem({ name: 'k', kind: 'number' }, 'Kp'), '', 'a parameter name is for the server to check');
  assert.match(parameterProblem({ name: 'k', kind: 'number' }, '1,5'), /a number/);
  assert.equal(modelValueProblem({ type: 'single', min: 0, max: 1 }, '0.5'), '');
  assert.equal(modelValueProblem({ type: 'single', min: 0, max: 1 }, '2'), 'at most 1');
  assert.equal(modelValueProblem({ type: 'uint16' }, '1.5'), 'a whole number');
  assert.equal(modelValueProblem({ type: 'boolean' }, 'maybe'), 'true or false');
  assert.equal(modelValueProblem({ type: 'single' }, ''), 'a value is required');
});

test('defaults of required parameters: in range, the first choice, single for types', () => {
  assert.equal(defaultValue({ kind: 'number' }), '1');
  assert.equal(defaultValue({ kind: 'number', min: 2, max: 5 }), '2');
  assert.equal(defaultValue({ kind: 'number', max: -1 }), '-1');
  assert.equal(defaultValue({ kind: 'word', choices: ['AND', 'OR'] }), 'AND');
  assert.equal(defaultValue({ kind: 'data_type', choices: ['double', 'single'] }), 'single');
  assert.equal(defaultValue({ kind: 'word' }), '');
});

test('line separators: CRLF files keep CRLF', () => {
  assert.equal(lineSeparatorOf('a\r\nb\r\n'), '\r\n');
  assert.equal(lineSeparatorOf('a\nb\n'), '\n');
  assert.equal(lineSeparatorOf('a'), '\n');
});
