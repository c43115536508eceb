// Waits between reconnection attempts: doubling from half a second to ten, so a restarting back
// end is found quickly and a missing one is not hammered.
export const first_delay_ms = 500;
export const longest_delay_ms = 10000;

export function reconnectDelay(failedAttempts) {
  return Math.min(longest_delay_ms, first_delay_ms * 2 ** Math.max(0, failedAttempts));
}
