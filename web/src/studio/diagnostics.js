// The server's diagnostics as CodeMirror lint diagnostics (positions in the text) and as the
// diagram's markers (per block). Pure: `doc` is CodeMirror's Text.

// Whether a diagnostic's place is in the open text: a referenced model's are in their own file.
export function inOpenFile(diagnostic, openFile) {
  return !diagnostic.file || diagnostic.file === openFile;
}

// Where the Problems list says a diagnostic is: `12:5` in the open text, `controller.yaml:12:5` elsewhere.
export function placeText(diagnostic, openFile) {
  const place = `${diagnostic.line}:${diagnostic.column}`;
  return inOpenFile(diagnostic, openFile) ? place : `${diagnostic.file}:${place}`;
}

export function positionOf(doc, line, column) {
  if (doc.lines === 0) return 0;
  const target = doc.line(Math.min(Math.max(line, 1), doc.lines));
  return target.from + Math.min(Math.max(column - 1, 0), target.length);
}

// Each diagnostic of the open text underlines the word at its place (at least one character, so
// it is visible); those of other files are not on this text.
export function lintDiagnostics(doc, diagnostics, openFile) {
  return diagnostics.filter((diagnostic) => inOpenFile(diagnostic, openFile)).map((diagnostic) => {
    const from = positionOf(doc, diagnostic.line ?? 1, diagnostic.column ?? 1);
    const line = doc.lineAt(from);
    const word = /^[^\s,{}[\]:]*/.exec(line.text.slice(from - line.from))[0].length;
    const to = Math.min(from + Math.max(word, 1), line.to);
    return {
      from,
      to: Math.max(to, from),
      severity: diagnostic.severity === 'warning' ? 'warning' : 'error',
      message: diagnostic.hint ? `${diagnostic.message} (${diagnostic.hint})` : diagnostic.message,
    };
  });
}

export function blockMarkers(diagnostics) {
  const markers = new Map();
  for (const diagnostic of diagnostics) {
    if (!diagnostic.block) continue;
    if (!markers.has(diagnostic.block)) markers.set(diagnostic.block, []);
    markers.get(diagnostic.block).push({ severity: diagnostic.severity, message: diagnostic.message });
  }
  return markers;
}

// The top bar's verdict: "checked", "2 errors", "1 error, 3 warnings".
export function checkSummary(diagnostics) {
  const errors = diagnostics.filter((d) => d.severity === 'error').length;
  const warnings = diagnostics.length - errors;
  const plural = (n, word) => `${n} ${word}${n === 1 ? '' : 's'}`;
  if (errors === 0 && warnings === 0) return { text: 'checked', state: 'ok' };
  if (errors === 0) return { text: `checked, ${plural(warnings, 'warning')}`, state: 'warning' };
  return { text: warnings ? `${plural(errors, 'error')}, ${plural(warnings, 'warning')}` : plural(errors, 'error'), state: 'error' };
}
