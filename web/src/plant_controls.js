import { element, replaceChildren } from './dom.js';
import { actionLabel, argumentLabel, buildRequest, describePlantEvent, plantActions } from './plant_actions.js';

// The Disturb box: a simulated plant's actions (push, restart, ...) with their arguments, and the last event the
// plant applied with its model time. Shown only while the description has a `plant` (duet pil, duet plant serve);
// the board's page has none.
export function createPlantControls({ hub, connection, root }) {
  let actions = [];
  const last = element('p', { class: 'plant-last muted', id: 'plant-last', role: 'status' }, 'Nothing applied yet.');

  const say = (text, tone) => {
    last.textContent = text;
    last.className = `plant-last ${tone}`;
  };

  const actionRow = (action) => {
    const fields = new Map();
    const inputs = action.arguments.map((argument) => {
      const field = element('input', {
        type: 'number',
        min: argument.min,
        max: argument.max,
        step: 'any',
        value: String(argument.default),
        inputmode: 'decimal',
        'data-plant-argument': `${action.name}.${argument.name}`,
        'aria-label': `${action.name} ${argument.name}`,
      });
      fields.set(argument.name, field);
      return element('label', { class: 'plant-argument', title: `${argument.min} to ${argument.max} ${argument.unit}` }, argumentLabel(argument), field, argument.unit ? element('span', { class: 'unit' }, argument.unit) : null);
    });
    const send = () => {
      const texts = Object.fromEntries([...fields].map(([name, field]) => [name, field.value]));
      const { request, problem } = buildRequest(action, texts);
      if (problem) return say(problem, 'bad');
      connection.send(request);
      say(`${action.name}: asked for…`, 'muted');
    };
    const button = element('button', { class: 'primary', 'data-plant-action': action.name, title: action.summary, onclick: send }, actionLabel(action.name));
    return element('div', { class: 'plant-action' }, button, ...inputs);
  };

  hub.on('description', (description) => {
    actions = plantActions(description);
    root.hidden = actions.length === 0;
    if (actions.length === 0) return replaceChildren(root);
    replaceChildren(root, element('h2', {}, `Disturb ${description.plant.name ?? 'the plant'}`), ...actions.map(actionRow), last);
  });

  hub.on('plant', (message) => {
    if (typeof message.error === 'string') return say(describePlantEvent(message, actions), 'bad');
    say(`Last: ${describePlantEvent(message, actions)}`, 'good');
    last.dataset.timeS = String(message.time_s);
    last.dataset.action = String(message.action);
  });

  return root;
}
