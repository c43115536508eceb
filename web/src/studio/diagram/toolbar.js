import { element } from '../../dom.js';

// The view's controls: find a block or signal, zoom, fit, lay out anew.
export function createToolbar({ onFind, onZoom, onFit, onRelayout }) {
  const input = element('input', { type: 'search', class: 'diagram-find', placeholder: 'find block or signal', 'aria-label': 'find block or signal' });
  const status = element('span', { class: 'diagram-find-status', 'aria-live': 'polite' });
  const form = element('form', {
    class: 'diagram-find-form',
    onsubmit: (event) => {
      event.preventDefault();
      status.textContent = onFind(input.value) ? '' : 'not found';
    },
  }, input, status);
  input.addEventListener('input', () => { status.textContent = ''; });
  const button = (label, title, action) => element('button', { type: 'button', title, 'aria-label': title, onclick: action }, label);
  const root = element('div', { class: 'diagram-toolbar' },
    form,
    button('−', 'zoom out', () => onZoom(1 / 1.25)),
    button('+', 'zoom in', () => onZoom(1.25)),
    button('fit', 'fit the drawing into view', onFit),
    button('lay out', 'lay the system out anew', onRelayout));
  return { root };
}
