// Numbers for people: enough digits to tell values apart, no float noise like 0.05000000074505806.
export function formatNumber(value, significant = 6) {
  if (typeof value !== 'number') return '—';
  if (!Number.isFinite(value)) return String(value);
  if (Number.isInteger(value) && Math.abs(value) < 1e15) return String(value);
  return String(Number(value.toPrecision(significant)));
}

// Counters and durations in tables: integers grouped for reading, others to 4 significant digits.
export function formatCounter(value) {
  if (typeof value === 'boolean') return value ? 'yes' : 'no';
  if (typeof value !== 'number') return value === null || value === undefined ? '—' : String(value);
  if (Number.isInteger(value)) return value.toLocaleString('en-US');
  return formatNumber(value, 4);
}
