// The file on disk versus the text in the editor: the version the text was edited from (`base`),
// the dirty mark, Save and Reload. A save names its base so the server refuses it when the file
// changed on disk meanwhile; then, as when the server says the file changed, a banner offers
// Reload — the page never overwrites someone else's change.
export function createFileState({ connection, editor, nodes, say }) {
  let base = null;
  let savedText = null;
  let saving = false;
  let pendingText = null; // the text of the save in flight: what is on disk once it is `saved`

  const dirty = () => savedText !== null && editor.getText() !== savedText;
  const showDirty = () => {
    nodes.dirty.hidden = !dirty();
    document.title = `${dirty() ? '● ' : ''}${nodes.fileName.textContent} — duet studio`;
  };
  const banner = (text) => {
    nodes.bannerText.textContent = text;
    nodes.banner.hidden = !text;
  };

  const save = () => {
    if (saving || base === null) return;
    const text = editor.getText();
    if (!connection.send({ type: 'save', text, base })) return say('not connected: not saved', 'bad');
    saving = true;
    pendingText = text;
    say('saving…');
  };

  const reload = () => {
    if (!connection.send({ type: 'reload' })) say('not connected: cannot reload', 'bad');
  };

  nodes.save.addEventListener('click', save);
  nodes.reload.addEventListener('click', () => {
    if (dirty() && !confirm('Discard your changes and read the file from disk?')) return;
    reload();
  });
  nodes.bannerReload.addEventListener('click', () => {
    banner('');
    reload();
  });
  nodes.bannerDismiss.addEventListener('click', () => banner(''));
  window.addEventListener('beforeunload', (event) => {
    if (dirty()) event.preventDefault();
  });

  return {
    save,
    dirty,
    // A text as it is on disk (the studio message, a `file` answer), now in the editor.
    loaded({ text, version }) {
      base = version;
      savedText = text;
      banner('');
      showDirty();
    },
    edited: showDirty,
    saved({ version }) {
      saving = false;
      base = version;
      savedText = pendingText;
      pendingText = null;
      say('saved', 'good');
      showDirty();
    },
    refused({ reason }) {
      saving = false;
      pendingText = null;
      banner(`Not saved: ${reason || 'the file changed on disk'}. Reload it (your edits are lost), or keep your text and save again after reloading elsewhere.`);
    },
    changedOnDisk({ version }) {
      if (version === base) return;
      banner('The file changed on disk.');
    },
    failed() {
      saving = false;
      pendingText = null;
    },
  };
}
