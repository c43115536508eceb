import { reconnectDelay } from './reconnect_delay.js';

// The WebSocket to the back end, reopened with a growing delay whenever it closes.
// `onMessage(message, arrivalMs)` gets every parsed JSON object; `onState(state)` gets
// {name: 'connecting' | 'connected' | 'waiting', url, retryInMs}.
export class Connection {
  #socket = null;
  #failedAttempts = 0;
  #retryTimer = 0;

  constructor(url, { onMessage, onState, onOpen }) {
    this.url = url;
    this.onMessage = onMessage;
    this.onState = onState;
    this.onOpen = onOpen;
    this.state = { name: 'connecting', url };
    this.received = 0;
    this.malformed = 0;
  }

  open() {
    clearTimeout(this.#retryTimer);
    this.#setState({ name: 'connecting', url: this.url });
    let socket;
    try {
      socket = new WebSocket(this.url);
    } catch (error) {
      // A malformed ?ws= address throws here; say so and keep retrying in case it is fixed.
      console.error(error);
      this.#scheduleRetry();
      return;
    }
    this.#socket = socket;
    socket.addEventListener('open', () => {
      this.#failedAttempts = 0;
      this.#setState({ name: 'connected', url: this.url });
      this.onOpen?.();
    });
    socket.addEventListener('message', (event) => this.#receive(event.data));
    socket.addEventListener('close', () => {
      if (this.#socket !== socket) return;
      this.#socket = null;
      this.#scheduleRetry();
    });
  }

  // Sends one request; false when there is no open socket to take it.
  send(request) {
    if (!this.#socket || this.#socket.readyState !== WebSocket.OPEN) return false;
    this.#socket.send(JSON.stringify(request));
    return true;
  }

  get connected() {
    return this.state.name === 'connected';
  }

  #receive(text) {
    const arrivalMs = performance.timeOrigin + performance.now();
    let message;
    try {
      message = JSON.parse(text);
    } catch {
      this.malformed += 1;
      return;
    }
    if (!message || typeof message.type !== 'string') {
      this.malformed += 1;
      return;
    }
    this.received += 1;
    this.onMessage(message, arrivalMs);
  }

  #scheduleRetry() {
    const delay = reconnectDelay(this.#failedAttempts);
    this.#failedAttempts += 1;
    this.#setState({ name: 'waiting', url: this.url, retryInMs: delay });
    this.#retryTimer = setTimeout(() => this.open(), delay);
  }

  #setState(state) {
    this.state = state;
    this.onState?.(state);
  }
}
