// A fixed-capacity ring of numbers that can always be read as one contiguous typed array.
//
// Every value is written twice, at i and at i + capacity, so the newest `length` values are
// always a plain subarray: the decimator and CSV export then loop over ordinary indices
// instead of wrapping, at the price of one extra store per value.
export class RingBuffer {
  constructor(capacity) {
    if (!(capacity > 0)) throw new RangeError(`ring capacity must be positive, not ${capacity}`);
    this.capacity = capacity;
    this.data = new Float64Array(2 * capacity);
    this.next = 0; // where the next value goes, in [0, capacity)
    this.length = 0;
  }

  push(value) {
    this.data[this.next] = value;
    this.data[this.next + this.capacity] = value;
    this.next = this.next + 1 === this.capacity ? 0 : this.next + 1;
    if (this.length < this.capacity) this.length += 1;
  }

  clear() {
    this.next = 0;
    this.length = 0;
  }

  // The held values, oldest first; a view that later pushes overwrite, so copy it to keep it.
  view() {
    const oldest = (this.next - this.length + this.capacity) % this.capacity;
    return this.data.subarray(oldest, oldest + this.length);
  }

  last() {
    return this.length === 0 ? undefined : this.data[this.next - 1 + this.capacity];
  }
}
