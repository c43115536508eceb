// The mock's triggered recorder: keeps a history of every sample, watches the armed signal for
// its edge through the level, and after the post-trigger time cuts the capture out of the history.
export class MockRecorder {
  constructor(signalNames, historySamples) {
    this.names = signalNames;
    this.capacity = historySamples;
    this.time = [];
    this.values = signalNames.map(() => []);
    this.armed = null; // the request, while armed or triggered
    this.triggerAt = -1; // the trigger sample's time, once triggered
    this.previous = undefined; // the armed signal's previous value
  }

  // A record request; returns an error message or '' when armed.
  arm(request) {
    const index = this.names.indexOf(request.signal);
    if (index < 0) return `record: no signal named '${request.signal}'`;
    if (!['rising', 'falling', 'either'].includes(request.edge)) return 'record: edge is rising, falling or either';
    for (const key of ['level', 'pre_s', 'post_s']) {
      if (typeof request[key] !== 'number' || !Number.isFinite(request[key])) return `record: ${key} must be a number`;
    }
    if (request.pre_s < 0 || request.post_s < 0 || request.pre_s + request.post_s > 20) return 'record: pre_s and post_s are 0..20 s together';
    this.armed = { signal: request.signal, level: request.level, edge: request.edge, pre_s: request.pre_s, post_s: request.post_s, index };
    this.triggerAt = -1;
    this.previous = undefined;
    return '';
  }

  cancel() {
    this.armed = null;
  }

  // One sample; returns 'triggered', a capture message, or nothing.
  add(timeS, row) {
    this.time.push(timeS);
    row.forEach((value, s) => this.values[s].push(value));
    // Trimmed in batches: removing from the front of an array moves all of it.
    if (this.time.length > 1.5 * this.capacity) {
      const excess = this.time.length - this.capacity;
      this.time.splice(0, excess);
      for (const column of this.values) column.splice(0, excess);
    }
    if (!this.armed) return undefined;
    if (this.triggerAt < 0) {
      const value = row[this.armed.index];
      const crossed = this.#crossed(this.previous, value);
      this.previous = value;
      if (!crossed) return undefined;
      this.triggerAt = timeS;
      return 'triggered';
    }
    if (timeS < this.triggerAt + this.armed.post_s) return undefined;
    const capture = this.#capture();
    this.armed = null;
    return capture;
  }

  #crossed(before, now) {
    if (before === undefined) return false;
    const { level, edge } = this.armed;
    const rising = before < level && now >= level;
    const falling = before > level && now <= level;
    return edge === 'rising' ? rising : edge === 'falling' ? falling : rising || falling;
  }

  #capture() {
    const { signal, level, edge, pre_s: pre, post_s: post } = this.armed;
    const first = this.time.findIndex((t) => t >= this.triggerAt - pre);
    const last = this.time.length;
    return {
      type: 'capture',
      signal,
      level,
      edge,
      trigger_time_s: this.triggerAt,
      pre_s: pre,
      post_s: post,
      time_s: this.time.slice(first, last),
      values: this.values.map((column) => column.slice(first, last)),
    };
  }
}
