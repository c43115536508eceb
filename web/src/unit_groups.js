// Signals sharing a unit share a chart and its y axis; different units get their own chart, so
// a battery voltage does not flatten an angle in degrees.
export function groupByUnit(signals) {
  const groups = new Map();
  for (const signal of signals) {
    const unit = signal.unit ?? '';
    if (!groups.has(unit)) groups.set(unit, { unit, signals: [] });
    groups.get(unit).signals.push(signal);
  }
  return [...groups.values()];
}
