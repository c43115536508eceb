import { SignalStore } from './signal_store.js';

// Feeds `telemetry` messages and `samples` blocks into the SignalStore of the current
// description, then tells the pages ('store' when a new store replaced the old, 'data' after new
// samples).
export function connectSignalFeed(hub, stats) {
  let store = null;
  let signature = '';

  hub.on('description', (description) => {
    // The same signals again (the target came back, someone asked `describe`) keep the history.
    const next = JSON.stringify([description.telemetry_period_us, description.telemetry]);
    if (store && next === signature) return;
    signature = next;
    store = new SignalStore({ telemetry_period_us: description.telemetry_period_us, telemetry: description.telemetry ?? [] });
    hub.emit('store', store);
  });
  hub.on('telemetry', (message) => {
    if (!store) return; // samples before a description cannot be named
    stats.samples += store.addTelemetry(message);
    hub.emit('data', store);
  });
  hub.on('samples', (message) => {
    if (!store) return;
    stats.samples += store.addSamples(message);
    hub.emit('data', store);
  });
}
