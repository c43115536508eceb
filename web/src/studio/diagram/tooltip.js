import { element, replaceChildren } from '../../dom.js';

// The floating box by the pointer: a block's description, or a wire's name and type.
export function createTooltip(container) {
  const root = element('div', { class: 'diagram-tooltip', role: 'tooltip', hidden: true });
  container.append(root);
  const place = (clientX, clientY) => {
    const box = container.getBoundingClientRect();
    const left = Math.min(clientX - box.left + 14, Math.max(0, box.width - root.offsetWidth - 4));
    const top = clientY - box.top + 16 + root.offsetHeight > box.height ? clientY - box.top - root.offsetHeight - 8 : clientY - box.top + 16;
    root.style.left = `${left}px`;
    root.style.top = `${Math.max(0, top)}px`;
  };
  return {
    showBlock(description, markers, clientX, clientY) {
      replaceChildren(root,
        element('div', { class: 'tooltip-title' }, description.title, element('span', { class: 'tooltip-type' }, ` ${description.type}`)),
        description.summary ? element('div', { class: 'tooltip-summary' }, description.summary) : null,
        description.code ? element('div', { class: 'tooltip-summary' }, description.code) : null,
        markers.map((marker) => element('div', { class: `tooltip-marker ${marker.severity}` }, marker.message)),
        description.parameters.length + description.unset.length > 0 ? element('table', {},
          description.parameters.map((parameter) => element('tr', {},
            element('th', {}, parameter.name),
            element('td', {},
              element('code', {}, parameter.text),
              parameter.model ? element('div', { class: 'tooltip-model' }, parameter.model) : null,
              parameter.documentation ? element('div', { class: 'tooltip-doc' }, parameter.documentation) : null))),
          description.unset.map((parameter) => element('tr', { class: 'unset' },
            element('th', {}, parameter.name),
            element('td', {}, element('div', { class: 'tooltip-doc' }, parameter.documentation))))) : null);
      root.hidden = false;
      place(clientX, clientY);
    },
    showWire(wire, clientX, clientY) {
      replaceChildren(root,
        element('div', { class: 'tooltip-title' }, wire.signal, element('span', { class: 'tooltip-type' }, ` ${[wire.type, wire.unit].filter(Boolean).join(' ')}`)),
        wire.resolved && wire.resolved !== wire.signal ? element('div', { class: 'tooltip-summary' }, `model-wide: ${wire.resolved}`) : null,
        wire.measurement ? element('div', { class: 'tooltip-doc' }, `measurement ${wire.measurement}`) : null,
        !wire.source ? element('div', { class: 'tooltip-marker warning' }, 'nothing drives this signal') : null);
      root.hidden = false;
      place(clientX, clientY);
    },
    hide() {
      root.hidden = true;
    },
  };
}
