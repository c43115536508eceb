// The Problems tab: every diagnostic with its place (its file's name too when that is not the open
// one); a click jumps there in the text and selects the block it concerns in the diagram.
import { element, replaceChildren } from '../dom.js';
import { placeText } from './diagnostics.js';

export function createProblemsList(root, countNode, { onJump }) {
  return {
    show(diagnostics, openFile) {
      countNode.textContent = diagnostics.length ? String(diagnostics.length) : '';
      countNode.dataset.state = diagnostics.some((d) => d.severity === 'error') ? 'error' : 'warning';
      if (diagnostics.length === 0) {
        replaceChildren(root, element('p', { class: 'muted' }, 'No problems.'));
        return;
      }
      replaceChildren(root, element('ul', { class: 'problems' }, diagnostics.map((diagnostic) => element('li', {},
        element('button', { class: `problem ${diagnostic.severity}`, onclick: () => onJump(diagnostic) },
          element('span', { class: 'severity' }, diagnostic.severity),
          element('span', { class: 'place' }, placeText(diagnostic, openFile)),
          element('span', { class: 'message' }, diagnostic.message),
          diagnostic.hint ? element('span', { class: 'hint' }, diagnostic.hint) : null,
          diagnostic.block ? element('span', { class: 'block-name' }, diagnostic.block) : null)))));
    },
  };
}
