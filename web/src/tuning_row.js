import { element } from './dom.js';
import { formatNumber } from './number_format.js';
import { asStored, digitsFor, hasUsableLimits, isIntegerType, problemWith, sameValue, stepFor } from './parameter_rules.js';
import { nameOf } from './value_names.js';

// One parameter on the Tuning page: the value being edited (slider and number field in step),
// the target's value, Write, and Undo through the values this page replaced.
export class TuningRow {
  constructor(parameter, { write }) {
    this.parameter = parameter;
    this.write = write; // (name, value) => bool: sends a set
    this.target = undefined; // the target's value, from `parameter` messages
    this.edited = undefined; // the value in the fields
    this.history = []; // target values before each write from this page, newest last
    this.awaitingAnswer = false;
    this.#build();
  }

  get name() {
    return this.parameter.name;
  }

  // Differs from the target (at the target's precision) and could be written.
  get changed() {
    return typeof this.edited === 'number' && !sameValue(this.parameter, this.edited, this.target);
  }

  // A `parameter` message for this row.
  received(message) {
    const previousTarget = this.target;
    if (typeof message.value === 'number') this.target = message.value;
    // The fields follow the target unless the user has an edit of their own going; the answer to
    // this page's own write always resets them (it may have been clamped).
    const userEditing = this.edited !== undefined && !sameValue(this.parameter, this.edited, previousTarget);
    if (this.target !== undefined && (!userEditing || this.awaitingAnswer || this.edited === undefined)) this.#setEdited(this.target);
    if (message.status !== 'reported') this.awaitingAnswer = false;
    this.#showStatus(message);
    this.#refresh();
  }

  // Puts a value in the fields without writing it (presets, undo).
  propose(value) {
    this.#setEdited(value);
    this.#refresh();
  }

  writeEdited() {
    if (!this.changed) return false;
    const problem = problemWith(this.parameter, this.edited);
    if (problem) {
      this.#say(`not written: ${problem}`, 'bad');
      return false;
    }
    if (!this.write(this.name, this.edited)) {
      this.#say('not written: not connected', 'bad');
      return false;
    }
    if (this.target !== undefined) this.history.push(this.target);
    this.awaitingAnswer = true;
    this.#say('writing…', 'muted');
    this.#refresh();
    return true;
  }

  undo() {
    if (this.history.length === 0) return;
    const previous = this.history[this.history.length - 1];
    if (!this.write(this.name, previous)) {
      this.#say('not undone: not connected', 'bad');
      return;
    }
    this.history.pop();
    this.awaitingAnswer = true;
    this.#setEdited(previous);
    this.#say(`undoing to ${formatNumber(previous)}…`, 'muted');
    this.#refresh();
  }

  #setEdited(value) {
    this.edited = value;
    if (typeof value !== 'number') return;
    if (this.slider) this.slider.value = String(value);
    if (this.choice) this.choice.value = String(value);
    // Show what the target will hold, to the digits that matter (no float32 noise).
    this.numberField.value = String(Number(asStored(this.parameter, value).toPrecision(digitsFor(this.parameter))));
  }

  #refresh() {
    this.targetValue.textContent =
      this.target === undefined ? '—' : (nameOf(this.parameter, this.target) ?? formatNumber(this.target, digitsFor(this.parameter)));
    if (this.target !== undefined) this.targetValue.dataset.value = String(this.target);
    this.writeButton.disabled = !this.changed;
    this.undoButton.disabled = this.history.length === 0;
    this.node.classList.toggle('changed', this.changed);
  }

  #showStatus(message) {
    switch (message.status) {
      case 'applied':
        return this.#say(`applied ${formatNumber(this.target)}`, 'good');
      case 'clamped':
        return this.#say(`clamped to ${formatNumber(this.target)}`, 'warn');
      case 'failed':
        return this.#say(`failed${message.message ? `: ${message.message}` : ''}`, 'bad');
      case 'unknown parameter':
      case 'malformed':
        return this.#say(message.status, 'bad');
      default:
        return undefined; // `reported` needs no words: the target value shows it
    }
  }

  #say(text, tone) {
    this.statusLine.textContent = text;
    this.statusLine.className = `row-status ${tone}`;
  }

  #fromField(field) {
    const value = field === this.choice ? Number(field.value) : field.valueAsNumber;
    this.edited = Number.isNaN(value) ? undefined : value;
    if (field !== this.numberField && this.edited !== undefined) this.#setEdited(this.edited);
    if (field !== this.slider && this.slider && this.edited !== undefined) this.slider.value = String(this.edited);
    if (field === this.choice && this.edited !== undefined) this.numberField.value = String(this.edited);
    const problem = this.edited === undefined ? 'not a number' : problemWith(this.parameter, this.edited);
    this.#say(problem, problem ? 'bad' : 'muted');
    this.#refresh();
  }

  #build() {
    const { name, unit, type, min, max } = this.parameter;
    const step = stepFor(this.parameter);
    const usable = hasUsableLimits(this.parameter);
    // A parameter whose values have names (a choice: the controller) is chosen by name.
    const labels = this.parameter.labels ?? [];
    this.choice = labels.length
      ? element(
          'select',
          { 'data-parameter': name, 'data-choice': name, 'aria-label': `${name} choice`, onchange: () => this.#fromField(this.choice) },
          labels.map((label) => element('option', { value: String(label.value) }, label.text)),
        )
      : null;
    this.slider = usable && !this.choice
      ? element('input', { type: 'range', min, max, step, 'data-parameter': name, 'aria-label': `${name} slider`, oninput: () => this.#fromField(this.slider) })
      : null;
    this.numberField = element('input', {
      type: 'number',
      step: isIntegerType(type) ? 1 : 'any',
      min: Number.isFinite(min) ? min : undefined,
      max: Number.isFinite(max) ? max : undefined,
      inputmode: isIntegerType(type) ? 'numeric' : 'decimal',
      'data-parameter': name,
      'aria-label': `${name} value`,
      hidden: this.choice !== null,
      oninput: () => this.#fromField(this.numberField),
      onkeydown: (event) => {
        if (event.key === 'Enter') this.writeEdited();
      },
    });
    this.targetValue = element('span', { class: 'target-value', 'data-target-value': name }, '—');
    this.writeButton = element('button', { class: 'primary', 'data-write': name, disabled: true, onclick: () => this.writeEdited() }, 'Write');
    this.undoButton = element('button', { 'data-undo': name, disabled: true, onclick: () => this.undo() }, 'Undo');
    this.statusLine = element('div', { class: 'row-status muted', role: 'status' });
    this.node = element(
      'div',
      { class: 'parameter', 'data-row': name },
      element('div', { class: 'parameter-head' }, element('span', { class: 'parameter-name' }, name), unit ? element('span', { class: 'unit' }, unit) : null, element('span', { class: 'type' }, type), element('span', { class: 'target' }, 'target ', this.targetValue)),
      this.slider,
      this.choice,
      this.choice ? null : element('div', { class: 'limits' }, element('span', {}, `min ${formatNumber(min)}`), element('span', {}, `max ${formatNumber(max)}`)),
      element('div', { class: 'parameter-edit' }, this.numberField, this.writeButton, this.undoButton),
      this.statusLine,
    );
  }
}
