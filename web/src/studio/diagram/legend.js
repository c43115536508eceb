import { element, replaceChildren } from '../../dom.js';
import { legendEntries } from './task_colours.js';

// The colour key: each task's name and rate (period, or interrupt and priority) beside its colour. It folds to
// its title, so that it covers no blocks when the user wants them all.
export function createLegend() {
  const root = element('div', { class: 'diagram-legend' });
  const toggle = element('button', {
    type: 'button', class: 'legend-toggle', 'aria-expanded': 'true', title: 'Show or hide the task colours',
    onclick: () => {
      const folded = root.classList.toggle('folded');
      toggle.setAttribute('aria-expanded', String(!folded));
    },
  }, 'tasks');
  return {
    root,
    update(tasks, blockTasks) {
      const rows = legendEntries(tasks, blockTasks);
      replaceChildren(root, [toggle, ...rows.map((row) => element('div', { class: 'legend-row', 'data-task': String(row.key) },
        element('span', { class: 'legend-swatch', style: `background:${row.colour}` }),
        element('span', { class: 'legend-name' }, row.name),
        row.rate ? element('span', { class: 'legend-rate' }, row.rate) : null))]);
      root.hidden = rows.length === 0;
    },
  };
}
