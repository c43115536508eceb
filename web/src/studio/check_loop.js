// Keeps the server's verdict close behind the typing without a fixed debounce: at most one
// `check` is in flight; when its answer comes, the newest text is sent if it changed meanwhile.
// So a fast server answers every keystroke and a slow one sees only the latest text.
// Answers to anything but the request in flight (an old seq, a lost connection's) are dropped.
export class CheckLoop {
  #send;
  #now;
  #nextSeq = 1;
  #inFlight = null; // {seq, text, editTimes}
  #latestText = '';
  #unsentEditTimes = [];

  // `send(request)` returns false when there is no connection to take it.
  // `now()` stamps edits (performance.now() in the page; a fake clock in tests).
  constructor(send, now = () => performance.now()) {
    this.#send = send;
    this.#now = now;
  }

  // A newly loaded text (the studio message, a reload): the server's seq 0 answer describes it.
  loaded(text, { answerComing }) {
    this.#latestText = text;
    this.#unsentEditTimes = [];
    this.#inFlight = answerComing ? { seq: 0, text, editTimes: [] } : null;
    if (!answerComing) this.#sendLatest(true);
  }

  edited(text) {
    this.#latestText = text;
    this.#unsentEditTimes.push(this.#now());
    if (!this.#inFlight) this.#sendLatest(false);
  }

  // When the answer is the one awaited and should be shown: the times of the edits it covers
  // (for the edit-to-shown latency, measured once it is shown); null when it is stale.
  answered(model) {
    if (!this.#inFlight || model.seq !== this.#inFlight.seq) return null;
    const { text, editTimes } = this.#inFlight;
    this.#inFlight = null;
    if (this.#latestText !== text) this.#sendLatest(true);
    return editTimes;
  }

  get pending() {
    return this.#inFlight !== null;
  }

  #sendLatest(force) {
    if (!force && this.#unsentEditTimes.length === 0) return;
    const request = { type: 'check', text: this.#latestText, seq: this.#nextSeq };
    if (!this.#send(request)) return; // the reconnection sends it
    this.#inFlight = { seq: this.#nextSeq, text: this.#latestText, editTimes: this.#unsentEditTimes };
    this.#unsentEditTimes = [];
    this.#nextSeq += 1;
  }
}
