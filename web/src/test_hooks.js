// window.duet: counters and a message hook for browser tests and benchmarks, nothing more.
// A test sets window.duet.onMessage = (message, arrivalMs) => {...} to see every message with
// its arrival time on the page's clock (performance.timeOrigin + performance.now()).
export function installTestHooks(connection) {
  const duet = {
    stats: { messages: 0, samples: 0, frames: 0, lastMessageTime: 0 },
    connection,
    onMessage: null,
  };
  window.duet = duet;
  return duet;
}

export function recordMessage(duet, message, arrivalMs) {
  duet.stats.messages += 1;
  duet.stats.lastMessageTime = arrivalMs;
  if (duet.onMessage) duet.onMessage(message, arrivalMs);
}
