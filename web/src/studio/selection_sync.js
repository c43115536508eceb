// Where the diagram's selection is in the text, and what in the diagram the text's cursor is on.
// Pure: the diagram is the server's `diagram`, places are its 1-based lines and columns, and a
// document is anything with line(n) -> {from, to, text} and lines (CodeMirror's Text). A place
// with a `file` is in a referenced model's file, not in the text: it is never looked for there.

export function systemOfBlock(blockId) {
  return blockId.split('/').slice(0, -1).join('/');
}

// The innermost block whose lines hold `line`, searching inside subsystems.
export function blockAtLine(system, line) {
  for (const block of system?.blocks ?? []) {
    if (block.file || line < block.line || line > (block.end_line ?? block.line)) continue;
    return blockAtLine(block.system, line) ?? block;
  }
  return null;
}

function* systemsOf(system) {
  yield system;
  for (const block of system.blocks ?? []) if (block.system) yield* systemsOf(block.system);
}

// The span of the identifier starting at `column` (1-based) in `text`, as 1-based columns.
function identifierAt(text, column) {
  const match = /^[A-Za-z_][A-Za-z0-9_]*/.exec(text.slice(column - 1));
  return match ? { start: column, end: column + match[0].length, name: match[0] } : null;
}

// The signal a port's key names: `u: theta` or a Code block's `duty: {signal: duty, ...}`.
function portValueSpan(lineText, keyColumn) {
  const rest = lineText.slice(keyColumn - 1);
  const match = /^[A-Za-z_][A-Za-z0-9_]*\s*:\s*(\{\s*signal\s*:\s*)?/.exec(rest);
  if (!match) return null;
  return identifierAt(lineText, keyColumn + match[0].length);
}

// The wire the cursor is on: a port's signal name, or a wire's declaration (or driver) place.
export function wireAtCursor(diagram, line, column, lineText) {
  if (!diagram) return null;
  for (const system of systemsOf(diagram.root)) {
    for (const block of system.blocks ?? []) {
      for (const port of [...(block.inputs ?? []), ...(block.outputs ?? [])]) {
        if (port.file || port.line !== line || !port.signal) continue;
        const span = portValueSpan(lineText, port.column);
        if (span && span.name === port.signal && column >= span.start && column <= span.end) {
          const wire = system.wires?.find((candidate) => candidate.signal === port.signal);
          if (wire) return { system: system.path, wire };
        }
      }
    }
    for (const wire of system.wires ?? []) {
      if (wire.file || wire.line !== line) continue;
      const span = identifierAt(lineText, wire.column);
      if (span && span.name === wire.signal && column >= span.start && column <= span.end) return { system: system.path, wire };
    }
  }
  return null;
}

// The diagram's selection for a wire found in the text (the shape view.onSelect reports).
export function wireSelection({ system, wire }) {
  return { kind: 'wire', id: wire.id, system, signal: wire.signal, resolved: wire.resolved, measurement: wire.measurement };
}

export function findBlock(diagram, id) {
  for (const system of diagram ? systemsOf(diagram.root) : []) {
    const block = system.blocks?.find((candidate) => candidate.id === id);
    if (block) return block;
  }
  return null;
}

export function findWire(diagram, id) {
  for (const system of diagram ? systemsOf(diagram.root) : []) {
    const wire = system.wires?.find((candidate) => candidate.id === id);
    if (wire) return { system: system.path, wire };
  }
  return null;
}

export function findSystem(diagram, path) {
  for (const system of diagram ? systemsOf(diagram.root) : []) if (system.path === path) return system;
  return null;
}

// The text range to select for a diagram selection: a block's whole lines; a wire's name at its
// declaration or driver place. Null when the place is unknown or not in this document.
export function textRangeOf(diagram, selection, doc) {
  if (!selection || !diagram) return null;
  if (selection.kind === 'block') {
    const block = findBlock(diagram, selection.id);
    if (!block?.line || block.file || block.line > doc.lines) return null;
    const last = Math.min(block.end_line ?? block.line, doc.lines);
    return { from: doc.line(block.line).from, to: doc.line(last).to };
  }
  const found = findWire(diagram, selection.id);
  const wire = found?.wire;
  if (!wire?.line || wire.file || wire.line > doc.lines) return null;
  const line = doc.line(wire.line);
  // The place may be a port's key (the driver's `y: signal`): select the name that follows.
  let column = wire.column ?? 1;
  const direct = identifierAt(line.text, column);
  if (!direct || direct.name !== wire.signal) column = portValueSpan(line.text, column)?.start ?? column;
  const span = identifierAt(line.text, column);
  if (!span || span.name !== wire.signal) {
    const index = line.text.indexOf(wire.signal);
    if (index < 0) return { from: line.from, to: line.from };
    return { from: line.from + index, to: line.from + index + wire.signal.length };
  }
  return { from: line.from + span.start - 1, to: line.from + span.end - 1 };
}
