// The Block tab: the selected block's parameters as a form that knows their kinds and limits
// (from the library), the model parameter a block parameter names, and, in external mode, the
// value on the target; or, for a selected wire, its signal with a rename field.
// Every field is validated before anything is written; writing goes through diagram_edits.
import { element, replaceChildren } from '../dom.js';
import { formatNumber } from '../number_format.js';
import { modelValueProblem, parameterProblem } from './parameter_rules.js';
import { findBlock, findWire } from './selection_sync.js';

export function createBlockForm(root, { edits, getLivePanel }) {
  let diagram = null;
  let library = new Map();
  let selection = null;

  const field = ({ label, value, title, choices, required, validate, commit, id }) => {
    const message = element('span', { class: 'field-problem', role: 'status' });
    const input = choices
      ? element('select', { 'data-field': id }, required ? null : element('option', { value: '' }, '(default)'), choices.map((choice) => element('option', { value: choice, selected: choice === value }, choice)))
      : element('input', { type: 'text', value: value ?? '', 'data-field': id, spellcheck: 'false' });
    if (choices && value && !choices.includes(value)) input.prepend(element('option', { value, selected: true }, value));
    const submit = () => {
      const problem = validate(input.value);
      message.textContent = problem;
      input.classList.toggle('invalid', Boolean(problem));
      if (!problem && input.value.trim() !== (value ?? '')) commit(input.value);
    };
    input.addEventListener('change', submit);
    input.addEventListener('keydown', (event) => event.key === 'Enter' && submit());
    return element('label', { class: 'form-row', title: title ?? '' }, element('span', { class: 'form-label' }, label, required ? element('abbr', { title: 'required' }, '*') : null), input, message);
  };

  const limits = (owner) => [owner.min != null ? `min ${owner.min}` : '', owner.max != null ? `max ${owner.max}` : '', owner.integer ? 'whole' : ''].filter(Boolean).join(', ');

  const modelParameterRows = (argument) => {
    const parameter = diagram?.parameters?.find((candidate) => candidate.name === argument.reference);
    if (!parameter) return [];
    const rows = [field({
      id: `model:${parameter.name}`,
      label: `↳ ${parameter.name}`,
      value: parameter.value,
      title: [parameter.description, parameter.type, parameter.unit, limits(parameter)].filter(Boolean).join(' · '),
      validate: (typed) => modelValueProblem(parameter, typed),
      commit: (typed) => edits.setModelParameter(parameter.name, typed),
    })];
    const live = getLivePanel();
    if (live?.connected && argument.tunable) {
      const readBack = live.parameter(parameter.name);
      rows.push(field({
        id: `target:${parameter.name}`,
        label: targetLabel(readBack),
        value: readBack ? formatNumber(readBack.value) : '',
        title: 'written to the running target over XCP; the file is not changed',
        validate: (typed) => modelValueProblem(parameter, typed),
        commit: (typed) => live.write(parameter.name, Number(typed)),
      }));
    }
    return rows;
  };

  const blockPage = (block) => {
    const entry = library.get(block.type);
    const specs = entry && !entry.user_defined_ports ? entry.parameters : block.parameters.map((argument) => ({ name: argument.name, kind: 'number', required: false }));
    const rows = specs.flatMap((spec) => {
      const argument = block.parameters.find((candidate) => candidate.name === spec.name);
      return [
        field({
          id: `parameter:${spec.name}`,
          label: spec.name,
          value: argument?.text ?? '',
          title: [spec.description, spec.kind, limits(spec)].filter(Boolean).join(' · '),
          choices: spec.choices?.length ? spec.choices : undefined,
          required: spec.required,
          validate: (typed) => parameterProblem(spec, typed),
          commit: (typed) => edits.setParameter(block.id, spec.name, typed),
        }),
        ...(argument?.reference ? modelParameterRows(argument) : []),
      ];
    });
    const ports = (list, arrow) => list.map((port) => element('li', {}, `${port.port} ${arrow} ${port.signal ?? '(unconnected)'}`));
    return [
      element('div', { class: 'form-head' },
        element('strong', {}, block.id), element('span', { class: 'muted' }, ` ${block.type}`),
        element('button', { class: 'danger', 'data-action': 'delete', onclick: () => edits.deleteBlock(block.id) }, 'Delete block')),
      entry?.summary ? element('p', { class: 'muted' }, entry.summary) : null,
      rows.length ? element('div', { class: 'form-grid' }, rows) : element('p', { class: 'muted' }, 'No parameters.'),
      element('ul', { class: 'port-list' }, ports(block.inputs ?? [], '←'), ports(block.outputs ?? [], '→')),
    ];
  };

  const wirePage = ({ system, wire }) => {
    const name = element('input', { type: 'text', value: wire.signal, 'data-field': 'signal-name', spellcheck: 'false' });
    const rename = () => name.value.trim() && name.value.trim() !== wire.signal && edits.renameSignal(system, wire.signal, name.value.trim());
    name.addEventListener('keydown', (event) => event.key === 'Enter' && rename());
    const describe = (end) => (end.block ? `${end.block}.${end.port}` : end.system_input ? `input ${end.system_input}` : `output ${end.system_output}`);
    return [
      element('div', { class: 'form-head' }, element('strong', {}, `signal ${wire.signal}`), system ? element('span', { class: 'muted' }, ` in ${system}`) : null),
      element('div', { class: 'form-row rename' }, element('span', { class: 'form-label' }, 'name'), name, element('button', { 'data-action': 'rename', onclick: rename }, 'Rename')),
      element('p', { class: 'muted' }, [
        wire.type ? `type ${wire.type}` : '', wire.unit ? `unit ${wire.unit}` : '', wire.measurement ? `measurement ${wire.measurement}` : 'not measurable',
        wire.source ? `from ${describe(wire.source)}` : 'driven by nothing', wire.targets?.length ? `to ${wire.targets.map(describe).join(', ')}` : '',
      ].filter(Boolean).join(' · ')),
    ];
  };

  const render = () => {
    if (root.contains(document.activeElement) && document.activeElement.matches('input, select')) return; // not under the user's fingers
    const block = selection?.kind === 'block' ? findBlock(diagram, selection.id) : null;
    const wire = selection?.kind === 'wire' ? findWire(diagram, selection.id) : null;
    if (block) replaceChildren(root, blockPage(block));
    else if (wire) replaceChildren(root, wirePage(wire));
    else replaceChildren(root, element('p', { class: 'muted' }, 'Select a block or a wire in the diagram (or put the cursor in its text).'));
  };

  return {
    // A value read back from the target: shown on its row at once, even while the user is in the field.
    readBack(name, state) {
      const input = root.querySelector(`[data-field="target:${CSS.escape(name)}"]`);
      const label = input?.closest('.form-row')?.querySelector('.form-label');
      if (label) label.textContent = targetLabel(state);
    },
    setModel(nextDiagram, nextLibrary) {
      if (nextDiagram) diagram = nextDiagram;
      if (nextLibrary) library = new Map(nextLibrary.map((entry) => [entry.type, entry]));
      render();
    },
    select(next) {
      selection = next;
      if (root.contains(document.activeElement)) document.activeElement.blur();
      render();
    },
    refresh: render,
  };
}

function targetLabel(readBack) {
  return `on target${readBack ? ` (${formatNumber(readBack.value)}${readBack.status ? `, ${readBack.status}` : ''})` : ''}`;
}
