// The model's text: CodeMirror 6 with YAML highlighting and lint markers.
//
// The text must round-trip byte for byte (load, save unedited, same file). CodeMirror joins lines
// with "\n" unless told otherwise, so the editor is created with the file's own line separator
// ("\r\n" when the file has it); getText() then gives back exactly what was loaded. Edits
// computed on "\n" text (editText()) have the same positions, since a separator counts as one
// character in both.
import { basicSetup } from 'codemirror';
import { ChangeSet, EditorSelection, EditorState, Prec } from '@codemirror/state';
import { EditorView, keymap } from '@codemirror/view';
import { yaml } from '@codemirror/lang-yaml';
import { lintGutter, setDiagnostics } from '@codemirror/lint';

export function lineSeparatorOf(text) {
  return text.includes('\r\n') ? '\r\n' : '\n';
}

// `onEdit(text)`: the document changed (typing, undo, a diagram edit); `onCursor(position)`:
// the selection moved or changed while the editor has focus; `onSave()`: Ctrl/Cmd+S.
export function createEditor(parent, { onEdit, onCursor, onSave }) {
  let separator = '\n';

  const extensions = () => [
    basicSetup,
    yaml(),
    lintGutter(),
    EditorView.lineWrapping, // flow-style blocks are long lines; wrapped, the text fits beside the diagram
    Prec.highest(keymap.of([{ key: 'Mod-s', preventDefault: true, run: () => (onSave(), true) }])),
    EditorState.lineSeparator.of(separator),
    EditorView.updateListener.of((update) => {
      if (update.docChanged) onEdit(update.state.sliceDoc());
      if (update.selectionSet && update.transactions.some((t) => t.isUserEvent('select') || t.isUserEvent('input') || t.isUserEvent('delete'))) {
        onCursor(update.state.selection.main);
      }
    }),
  ];

  const view = new EditorView({ parent, state: EditorState.create({ doc: '', extensions: extensions() }) });

  return {
    view,
    // As saved: the file's own line separators.
    getText: () => view.state.sliceDoc(), // joined with the state's separator (doc.toString() would use "\n")
    // With "\n" between lines, for yaml_edit (same positions as the editor's).
    editText: () => view.state.doc.sliceString(0, view.state.doc.length, '\n'),
    get doc() {
      return view.state.doc;
    },

    // A text from the server (the studio message, a reload): not an edit, so no check is sent
    // for it (the server sends its verdict) and undo does not go back past it.
    load(text) {
      separator = lineSeparatorOf(text);
      view.setState(EditorState.create({ doc: text, extensions: extensions() }));
    },

    // The whole text replaced as a user edit (undoable, re-checked): test hooks, pastes of files.
    setText(text) {
      view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: view.state.toText(text) }, userEvent: 'input' });
    },

    // Changes from yaml_edit, applied one after the other, as one undoable transaction.
    applyEdits(changes, userEvent = 'input.diagram') {
      let combined = ChangeSet.empty(view.state.doc.length);
      for (const change of changes) {
        const insert = change.insert.replaceAll('\n', separator);
        combined = combined.compose(ChangeSet.of({ from: change.from, to: change.to, insert }, combined.newLength, separator));
      }
      view.dispatch({ changes: combined, userEvent, scrollIntoView: true });
    },

    select(from, to = from, { focus = false } = {}) {
      const length = view.state.doc.length;
      const clamp = (position) => Math.min(Math.max(position, 0), length);
      view.dispatch({ selection: EditorSelection.single(clamp(from), clamp(to)), effects: EditorView.scrollIntoView(clamp(from), { y: 'center' }) });
      if (focus) view.focus();
    },

    selection: () => ({ from: view.state.selection.main.from, to: view.state.selection.main.to }),

    // Between positions (a line break counts 1) and offsets into getText() (a "\r\n" counts 2).
    offsetOf: (position) => position + (view.state.doc.lineAt(position).number - 1) * (separator.length - 1),
    positionOf(offset) {
      const breaks = separator.length === 1 ? 0 : view.state.sliceDoc().slice(0, offset).split(separator).length - 1;
      return offset - breaks * (separator.length - 1);
    },

    setDiagnostics(diagnostics) {
      view.dispatch(setDiagnostics(view.state, diagnostics));
    },
  };
}
