import { groupItems } from './vector_items.js';

// The newest value of every measurement, in the shape the diagram wants: the base name to a
// number, or to an array for a vector. The rings of the SignalStore already hold each item's
// latest sample; this only regroups them, so it costs nothing per incoming sample.
export class LiveValues {
  constructor(store) {
    this.store = store;
    this.groups = groupItems(store.signals.map((signal) => signal.name));
  }

  // A fresh Map (the view may keep it); measurements with no sample yet are left out.
  read() {
    const values = new Map();
    for (const group of this.groups) {
      const latest = group.positions.map((position) => this.store.values[position].last());
      if (latest.some((value) => value === undefined)) continue;
      values.set(group.name, group.vector ? latest : latest[0]);
    }
    return values;
  }
}
