// A `simulation` message as the ScopeView reads a SignalStore: signals described by name, unit
// and column index, and `time` and `values` offering view() over typed arrays. The scope's
// drawing, decimation, zoom and legends then serve a finished result as they serve live data.
export function resultStore(simulation) {
  const time = Float64Array.from(simulation.time_s ?? [], numberOrNaN);
  const names = simulation.names ?? [];
  return {
    signals: names.map((name, index) => ({ name, unit: simulation.units?.[index] ?? '', index })),
    time: fixed(time),
    values: names.map((_, index) => {
      const column = simulation.columns?.[index] ?? [];
      // A short column (a cancelled run's last row) is padded with gaps: every signal must have
      // a value at every time for the decimator.
      return fixed(Float64Array.from({ length: time.length }, (_, row) => numberOrNaN(column[row])));
    }),
  };
}

// The simulated span in seconds (0 for fewer than two samples).
export function spanOf(store) {
  const time = store.time.view();
  return time.length < 2 ? 0 : time[time.length - 1] - time[0];
}

function fixed(array) {
  return { view: () => array };
}

// JSON has no NaN: the server's null is a gap.
function numberOrNaN(value) {
  return typeof value === 'number' ? value : NaN;
}
