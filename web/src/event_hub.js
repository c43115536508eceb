// The one place messages fan out from: the connection emits each message under its `type`, the
// pages listen to the types they show. Keeps pages ignorant of each other and of the socket.
export class EventHub {
  #listeners = new Map();

  on(type, listener) {
    if (!this.#listeners.has(type)) this.#listeners.set(type, []);
    this.#listeners.get(type).push(listener);
  }

  emit(type, payload) {
    for (const listener of this.#listeners.get(type) ?? []) {
      try {
        listener(payload);
      } catch (error) {
        // One page's bug must not starve the others of messages.
        console.error(`handling "${type}":`, error);
      }
    }
  }
}
