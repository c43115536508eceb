import { element, replaceChildren } from '../../dom.js';
import { colourFor } from '../../palette.js';

// Which signals a plot shows: a chip per plotted signal (in its line's colour, × removes it) and
// a list to add any other. `signals` are [{name, unit, index}], `index` choosing the colour as in
// the plots; `onChange(chosenSignals)` follows every change, the user's or the program's.
export class SignalChooser {
  constructor(container, { onChange, placeholder = 'add a signal…' }) {
    this.container = container;
    this.onChange = onChange;
    this.placeholder = placeholder;
    this.signals = [];
    this.chosen = []; // names, in the order they were added
    container.classList.add('signal-chooser');
  }

  // New signals to choose from; chosen names that still exist stay chosen.
  setSignals(signals, chosen = this.chosen) {
    this.signals = signals;
    this.#set(chosen);
  }

  add(names) {
    this.#set([...this.chosen, ...names.filter((name) => !this.chosen.includes(name))]);
  }

  remove(name) {
    this.#set(this.chosen.filter((chosen) => chosen !== name));
  }

  get chosenSignals() {
    return this.chosen.map((name) => this.signals.find((signal) => signal.name === name));
  }

  #set(names) {
    const known = new Set(this.signals.map((signal) => signal.name));
    this.chosen = names.filter((name) => known.has(name));
    this.#render();
    this.onChange(this.chosenSignals);
  }

  #render() {
    const chips = this.chosenSignals.map((signal) =>
      element(
        'span',
        { class: 'plotted-chip', style: `--signal-colour: ${colourFor(signal.index)}`, 'data-signal': signal.name },
        element('span', { class: 'swatch' }),
        labelOf(signal),
        element('button', { type: 'button', class: 'remove', title: `stop plotting ${signal.name}`, 'aria-label': `remove ${signal.name}`, onclick: () => this.remove(signal.name) }, '×'),
      ),
    );
    const others = this.signals.filter((signal) => !this.chosen.includes(signal.name));
    const adder = element(
      'select',
      {
        class: 'add-signal',
        disabled: others.length === 0,
        onchange: (event) => {
          if (event.target.value) this.add([event.target.value]);
        },
      },
      element('option', { value: '' }, others.length === 0 && this.signals.length === 0 ? 'no signals' : this.placeholder),
      others.map((signal) => element('option', { value: signal.name }, labelOf(signal))),
    );
    replaceChildren(this.container, chips, adder);
  }
}

function labelOf(signal) {
  return signal.unit ? `${signal.name} [${signal.unit}]` : signal.name;
}
