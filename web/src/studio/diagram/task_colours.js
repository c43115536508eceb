// Colours by the task that runs a block, after Simulink's sample-time colours: periodic rates
// fastest first red, green, blue, ...; each interrupt task its own colour from a second set, so
// a rate is never mistaken for an interrupt; constants magenta; not known grey.
const periodic_colours = ['#d62728', '#2ca02c', '#1f77b4', '#17becf', '#8c564b', '#bcbd22', '#6b6ecf', '#637939'];
const interrupt_colours = ['#ff7f0e', '#9467bd', '#e7298a', '#a6761d', '#1b9e77', '#7570b3', '#b15928', '#e6ab02', '#66a61e', '#d95f02'];
export const constant_colour = '#c000c0';
export const unknown_colour = '#8a8f98';

// Map from a Block.task value (an index into `tasks`, "constant", or none) to its colour.
export function taskColours(tasks) {
  const byIndex = new Map();
  let periodic = 0;
  let interrupt = 0;
  for (const task of tasks ?? []) {
    const colour = task.kind === 'interrupt'
      ? interrupt_colours[interrupt++ % interrupt_colours.length]
      : periodic_colours[periodic++ % periodic_colours.length];
    byIndex.set(task.index, colour);
  }
  return (task) => {
    if (task === 'constant') return constant_colour;
    if (typeof task === 'number' && byIndex.has(task)) return byIndex.get(task);
    return unknown_colour;
  };
}

function periodText(periodUs) {
  return `${Number((periodUs / 1000).toPrecision(6))} ms`;
}

// What a task runs on, in words: "1 ms" or "EXTI8 · priority 5" ("priority 5" when the task is
// named after its interrupt already).
export function taskRateText(task) {
  if (task.kind === 'interrupt') return task.name === task.interrupt ? `priority ${task.priority}` : `${task.interrupt} · priority ${task.priority}`;
  return periodText(task.period_us);
}

// The legend's rows: every task, then constant and not known when some block is so.
export function legendEntries(tasks, blockTasks) {
  const colourOf = taskColours(tasks);
  const rows = (tasks ?? []).map((task) => ({ key: task.index, colour: colourOf(task.index), name: task.name, rate: taskRateText(task) }));
  const used = new Set(blockTasks);
  if (used.has('constant')) rows.push({ key: 'constant', colour: constant_colour, name: 'constant', rate: 'at initialisation' });
  const known = new Set((tasks ?? []).map((task) => task.index));
  if ([...used].some((task) => task !== 'constant' && !known.has(task))) rows.push({ key: 'unknown', colour: unknown_colour, name: 'not known', rate: '' });
  return rows;
}
