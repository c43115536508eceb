// CSV of sampled signals: a time column then one column per signal, headed "name [unit]".
export function signalsCsv(time, columns) {
  const header = ['time_s', ...columns.map(({ name, unit }) => (unit ? `${name} [${unit}]` : name))];
  const lines = [header.map(quoteIfNeeded).join(',')];
  const row = new Array(columns.length + 1);
  for (let i = 0; i < time.length; i += 1) {
    row[0] = time[i];
    for (let c = 0; c < columns.length; c += 1) {
      const value = columns[c].values[i];
      row[c + 1] = Number.isNaN(value) ? '' : value;
    }
    lines.push(row.join(','));
  }
  return `${lines.join('\n')}\n`;
}

function quoteIfNeeded(text) {
  return /[",\n]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text;
}
