import { formatNumber } from './number_format.js';

// A value's name, when its item names its values (`labels`: the application channel's named
// items, the A2L's verbal conversions); undefined otherwise, or for a value without a name.
export function nameOf(item, value) {
  return item?.labels?.find((label) => label.value === value)?.text;
}

// A value for people: its name when it has one, else the number with the item's unit.
export function describeValue(item, value) {
  const name = nameOf(item, value);
  if (name !== undefined) return name;
  if (typeof value !== 'number' || Number.isNaN(value)) return '—';
  return item?.unit ? `${formatNumber(value)} ${item.unit}` : formatNumber(value);
}

// Named items first (what the target is doing), then the rest in the description's order.
export function namedFirst(items) {
  return [...items.filter((item) => item.labels?.length), ...items.filter((item) => !item.labels?.length)];
}
