import { element, replaceChildren } from '../../dom.js';
import { systemTrail } from './model_index.js';

// Where in the hierarchy the view is, each level a link back up.
export function createBreadcrumb(onOpen) {
  const root = element('nav', { class: 'breadcrumb', 'aria-label': 'system' });
  root.addEventListener('click', (event) => {
    const link = event.target.closest('a[data-path]');
    if (!link) return;
    event.preventDefault();
    onOpen(link.dataset.path);
  });
  return {
    root,
    update(diagram, path) {
      const trail = systemTrail(diagram, path);
      replaceChildren(root, ...trail.map((level, depth) => [
        depth > 0 ? element('span', { class: 'breadcrumb-separator' }, '›') : null,
        element('a', { href: '#', 'data-path': level.path, class: depth === trail.length - 1 ? 'current' : undefined }, level.name),
      ]));
    },
  };
}
