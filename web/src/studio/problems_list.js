// The Problems tab: every diagnostic with its place; a click jumps there in the text and selects
// the block it concerns in the diagram.
import { element, replaceChildren } from '../dom.js';

export function createProblemsList(root, countNode, { onJump }) {
  return {
    show(diagnostics) {
      countNode.textContent = diagnostics.length ? String(diagnostics.length) : '';
      countNode.dataset.state = diagnostics.some((d) => d.severity === 'error') ? 'error' : 'warning';
      if (diagnostics.length === 0) {
        replaceChildren(root, element('p', { class: 'muted' }, 'No problems.'));
        return;
      }
      replaceChildren(root, element('ul', { class: 'problems' }, diagnostics.map((diagnostic) => element('li', {},
        element('button', { class: `problem ${diagnostic.severity}`, onclick: () => onJump(diagnostic) },
          element('span', { class: 'severity' }, diagnostic.severity),
          element('span', { class: 'place' }, `${diagnostic.line}:${diagnostic.column}`),
          element('span', { class: 'message' }, diagnostic.message),
          diagnostic.hint ? element('span', { class: 'hint' }, diagnostic.hint) : null,
          diagnostic.block ? element('span', { class: 'block-name' }, diagnostic.block) : null)))));
    },
  };
}
