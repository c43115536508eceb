// The palette: every block type of the library by category; a click adds one to the system the
// diagram shows. The filter matches type names and summaries.
import { element, replaceChildren } from '../dom.js';

export function createPalette({ root, list, filter, toggle }, { onAdd }) {
  let library = [];

  const render = () => {
    const wanted = filter.value.trim().toLowerCase();
    const matching = library.filter((entry) => !wanted || entry.type.toLowerCase().includes(wanted) || (entry.summary ?? '').toLowerCase().includes(wanted));
    const categories = new Map();
    for (const entry of matching) {
      const category = entry.category || 'other';
      if (!categories.has(category)) categories.set(category, []);
      categories.get(category).push(entry);
    }
    replaceChildren(list, [...categories].map(([category, entries]) => element('section', { class: 'palette-category' },
      element('h3', {}, category),
      entries.map((entry) => element('button', {
        class: 'palette-entry', 'data-type': entry.type, title: entry.summary ?? entry.type,
        onclick: () => onAdd(entry),
      }, entry.type)))));
  };

  filter.addEventListener('input', render);
  toggle.addEventListener('click', () => {
    const collapsed = root.classList.toggle('collapsed');
    toggle.setAttribute('aria-expanded', String(!collapsed));
    toggle.textContent = collapsed ? '▶' : '◀';
  });

  return {
    setLibrary(next) {
      library = [...next].sort((a, b) => (a.category ?? '').localeCompare(b.category ?? '') || a.type.localeCompare(b.type));
      render();
    },
  };
}
