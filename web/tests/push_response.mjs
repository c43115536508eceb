// The tilt's answer to a push, from samples [time_s, theta_deg] as a page receives them: how far it tilted from
// where it stood (peak), when it was back within 0.5 degrees for good (settling), and how often it crossed its
// resting tilt (the oscillation).
export function responseToPush(samples, pushedAt, windowS) {
  const before = samples.filter(([time]) => time >= pushedAt - 1 && time < pushedAt);
  const rest = before.length ? before.reduce((sum, [, value]) => sum + value, 0) / before.length : 0;
  const after = samples.filter(([time]) => time >= pushedAt && time <= pushedAt + windowS);
  let peak = 0;
  let settled = pushedAt;
  let crossings = 0;
  let side = 0; // the side of the rest the tilt was last clearly on (beyond 0.05 degrees: noise does not count)
  for (const [time, value] of after) {
    const offset = value - rest;
    peak = Math.max(peak, Math.abs(offset));
    if (Math.abs(offset) > 0.5) settled = time;
    if (Math.abs(offset) <= 0.05) continue;
    if (side !== 0 && Math.sign(offset) !== side) crossings += 1;
    side = Math.sign(offset);
  }
  return { samples: after.length, rest_deg: rest, peak_deg: peak, settling_s: settled - pushedAt, crossings };
}
