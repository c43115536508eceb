// Turns a `status` message into what the Status page shows: the link, the executive and one
// table of counters per other object member (application_channel, xcp, daq, ...).

export function linkText(link) {
  if (!link || typeof link !== 'object') return '';
  return [link.state, link.address].filter((part) => part !== undefined && part !== '').join(' — ');
}

// The executive's core load arrives as a share (0..1); shown in percent.
export function executiveSummary(executive) {
  if (!executive || typeof executive !== 'object') return [];
  const rows = [];
  if (typeof executive.core_load === 'number') rows.push(['core load', `${(executive.core_load * 100).toFixed(1)} %`]);
  if (executive.overruns !== undefined) rows.push(['overruns', executive.overruns]);
  if (typeof executive.time_s === 'number') rows.push(['time', `${executive.time_s.toFixed(3)} s`]);
  if (executive.ticks !== undefined) rows.push(['ticks', executive.ticks]);
  return rows;
}

export const task_columns = ['name', 'activations', 'overruns', 'min_us', 'mean_us', 'max_us'];

export function taskRows(executive) {
  if (!executive || !Array.isArray(executive.tasks)) return [];
  return executive.tasks.map((task) => task_columns.map((column) => task[column]));
}

// Every object member except the two above, as [title, [[counter, value], ...]]. Nested objects
// are flattened with dotted names so nothing is hidden.
export function counterTables(status) {
  const tables = [];
  for (const [title, member] of Object.entries(status)) {
    if (title === 'link' || title === 'executive' || title === 'type') continue;
    if (!member || typeof member !== 'object' || Array.isArray(member)) continue;
    tables.push([title, flatten(member, '')]);
  }
  return tables;
}

function flatten(object, prefix) {
  const rows = [];
  for (const [key, value] of Object.entries(object)) {
    const name = prefix ? `${prefix}.${key}` : key;
    if (value && typeof value === 'object' && !Array.isArray(value)) rows.push(...flatten(value, name));
    else rows.push([name, Array.isArray(value) ? value.join(', ') : value]);
  }
  return rows;
}
