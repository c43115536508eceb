// Live values as wire labels: short enough to sit on a wire, precise enough to see change.
const shown_elements = 3;

export function formatScalar(value) {
  if (typeof value === 'boolean') return value ? '1' : '0';
  if (typeof value !== 'number') return '—';
  if (!Number.isFinite(value)) return String(value);
  // Counters and integer signals read best whole, up to where they stop fitting on a wire.
  if (Number.isInteger(value) && Math.abs(value) < 1e7) return String(value);
  const magnitude = Math.abs(value);
  if (magnitude !== 0 && (magnitude < 1e-3 || magnitude >= 1e7)) return trimExponent(value.toExponential(3));
  return String(Number(value.toPrecision(4)));
}

function trimExponent(text) {
  // 1.200e-5 -> 1.2e-5: trailing zeros of the mantissa carry nothing.
  return text.replace(/\.?0+e/, 'e').replace('e+', 'e');
}

export function formatLiveValue(value) {
  if (!Array.isArray(value) && !ArrayBuffer.isView(value)) return formatScalar(value);
  const elements = Array.from(value);
  const shown = elements.slice(0, shown_elements).map(formatScalar).join(', ');
  if (elements.length <= shown_elements) return `[${shown}]`;
  return `[${shown}, …] (${elements.length})`;
}
