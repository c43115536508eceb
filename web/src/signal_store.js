import { RingBuffer } from './ring_buffer.js';

// How much history the scope and the CSV export can see. Twenty seconds at the signal's rate, but
// never fewer than 20000 points (a slow 100 Hz signal then keeps 200 s) and never so many that a
// badly described period (1 us) would eat the memory of a small board.
const history_seconds = 20;
const minimum_capacity = 20000;
const maximum_capacity = 400000;

export function capacityFor(periodUs) {
  const wanted = periodUs > 0 ? Math.ceil((history_seconds * 1e6) / periodUs) : minimum_capacity;
  return Math.min(maximum_capacity, Math.max(minimum_capacity, wanted));
}

// Every telemetry signal's recent samples, all sharing one time axis: `telemetry` messages and
// `samples` blocks both carry every signal for every sample, so one time ring serves them all.
export class SignalStore {
  constructor(description) {
    this.periodUs = description.telemetry_period_us;
    this.signals = description.telemetry.map((item, index) => ({ ...item, index }));
    const capacity = capacityFor(this.periodUs);
    this.time = new RingBuffer(capacity);
    this.values = this.signals.map(() => new RingBuffer(capacity));
  }

  indexOf(name) {
    return this.signals.findIndex((signal) => signal.name === name);
  }

  clear() {
    this.time.clear();
    for (const ring of this.values) ring.clear();
  }

  // One `telemetry` message; its time is the sample number times the telemetry period.
  // Returns the number of samples taken in.
  addTelemetry(message) {
    if (!Array.isArray(message.values)) return 0;
    this.#startTime(message.sample * this.periodUs * 1e-6);
    for (let s = 0; s < this.values.length; s += 1) this.values[s].push(numberOrNaN(message.values[s]));
    return 1;
  }

  // One `samples` block: `time_s` and one array per signal, each as long as `time_s`.
  addSamples(message) {
    const times = message.time_s;
    const columns = message.values;
    if (!Array.isArray(times) || !Array.isArray(columns)) return 0;
    for (let i = 0; i < times.length; i += 1) {
      this.#startTime(times[i]);
      for (let s = 0; s < this.values.length; s += 1) this.values[s].push(numberOrNaN(columns[s]?.[i]));
    }
    return times.length;
  }

  #startTime(timeS) {
    // Time going back means the target restarted: old and new samples cannot share an axis (and
    // the plots' binary searches need it sorted), so start afresh.
    const last = this.time.last();
    if (last !== undefined && timeS < last) this.clear();
    this.time.push(timeS);
  }
}

// A missing or non-numeric value (JSON has no NaN) becomes a gap rather than a zero.
function numberOrNaN(value) {
  return typeof value === 'number' ? value : NaN;
}
