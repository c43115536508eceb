import { formatNumber } from '../../number_format.js';

// The Generated panel's words for the server's numbers.

// A period in the unit that reads best: 1 ms, 250 µs, 1.5 s.
export function formatPeriod(periodUs) {
  if (typeof periodUs !== 'number') return '—';
  if (periodUs >= 1e6) return `${formatNumber(periodUs / 1e6)} s`;
  if (periodUs >= 1e3) return `${formatNumber(periodUs / 1e3)} ms`;
  return `${formatNumber(periodUs)} µs`;
}

// A file's size as it will be on disk (UTF-8), for the file list.
export function formatSize(text) {
  const bytes = new TextEncoder().encode(text ?? '').length;
  if (bytes < 1024) return `${bytes} B`;
  return `${formatNumber(bytes / 1024, 3)} KB`;
}

// One row of cells per task: name, kind, when it runs (its period, or its interrupt and
// priority), and how many blocks run in it.
export function taskRows(tasks) {
  return (tasks ?? []).map((task) => [
    task.name ?? `task ${task.index}`,
    task.kind ?? '',
    task.kind === 'interrupt' ? `${task.interrupt ?? '?'}, priority ${task.priority ?? '?'}` : formatPeriod(task.period_us),
    String(task.blocks ?? '—'),
  ]);
}
