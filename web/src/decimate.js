// Reduces a window of samples to about one horizontal pixel's worth of points per column.
//
// For each pixel column the first and last sample times are kept, carrying the column's minimum
// and maximum of every signal (in the order they occurred), so a one-sample spike still reaches
// its full height on screen. All signals of one chart share the x array, as uPlot wants, which
// works because every signal has a value at every sample time.

// The first index in sorted `array` whose value is >= `value` (> `value` when `after`).
export function lowerBound(array, value, after = false) {
  let low = 0;
  let high = array.length;
  while (low < high) {
    const middle = (low + high) >>> 1;
    if (array[middle] < value || (after && array[middle] === value)) low = middle + 1;
    else high = middle;
  }
  return low;
}

export class Decimator {
  constructor() {
    this.x = new Float64Array(0);
    this.ys = [];
  }

  // `time`: sorted sample times; `signals`: value arrays as long as `time`; the window is
  // [from, to] seconds drawn over `columns` pixels. Returns [x, ...ys] views into buffers this
  // decimator reuses on the next call (uPlot reads them until then).
  decimate(time, signals, from, to, columns) {
    columns = Math.max(1, Math.floor(columns));
    // One sample either side of the window, so lines run to the plot's edges.
    const start = Math.max(0, lowerBound(time, from) - 1);
    const end = Math.min(time.length, lowerBound(time, to, true) + 1);
    this.#reserve(2 * (columns + 2) + 1, signals.length);
    const count = end - start;
    if (count <= 2 * columns) return this.#copy(time, signals, start, end);

    const x = this.x;
    const ys = this.ys;
    const width = (to - from) / columns;
    let points = 0;
    let first = start;
    // The newest sample is kept as itself after the columns, so the line ends on the true value.
    const last = end - 1;
    while (first < last) {
      // Columns sit on a grid fixed in time, not to the window's moving edge, so a scrolling
      // picture keeps its shape instead of shimmering as samples change columns.
      const columnEnd = (Math.floor(time[first] / width) + 1) * width;
      let past = first + 1;
      while (past < last && time[past] < columnEnd) past += 1;
      if (past - first === 1) {
        x[points] = time[first];
        for (let s = 0; s < signals.length; s += 1) ys[s][points] = signals[s][first];
        points += 1;
      } else {
        x[points] = time[first];
        x[points + 1] = time[past - 1];
        for (let s = 0; s < signals.length; s += 1) {
          const values = signals[s];
          let minimum = Infinity;
          let maximum = -Infinity;
          let minimumAt = first;
          let maximumAt = first;
          for (let i = first; i < past; i += 1) {
            const value = values[i];
            if (value < minimum) {
              minimum = value;
              minimumAt = i;
            }
            if (value > maximum) {
              maximum = value;
              maximumAt = i;
            }
          }
          if (minimum === Infinity) minimum = maximum = NaN; // only gaps in this column
          const out = ys[s];
          if (minimumAt <= maximumAt) {
            out[points] = minimum;
            out[points + 1] = maximum;
          } else {
            out[points] = maximum;
            out[points + 1] = minimum;
          }
        }
        points += 2;
      }
      first = past;
    }
    x[points] = time[last];
    for (let s = 0; s < signals.length; s += 1) ys[s][points] = signals[s][last];
    points += 1;
    return this.#views(points, signals.length);
  }

  #copy(time, signals, start, end) {
    this.x.set(time.subarray(start, end));
    for (let s = 0; s < signals.length; s += 1) this.ys[s].set(signals[s].subarray(start, end));
    return this.#views(end - start, signals.length);
  }

  #views(points, signalCount) {
    const data = [this.x.subarray(0, points)];
    for (let s = 0; s < signalCount; s += 1) data.push(this.ys[s].subarray(0, points));
    return data;
  }

  #reserve(points, signalCount) {
    if (this.x.length < points) this.x = new Float64Array(points);
    if (this.ys.length !== signalCount || (signalCount > 0 && this.ys[0].length < this.x.length)) {
      this.ys = Array.from({ length: signalCount }, () => new Float64Array(this.x.length));
    }
  }
}
