// The line a triggered or enabled subsystem's box carries: what starts it.
const edge_arrows = { rising: '↑', falling: '↓', either: '↕', both: '↕' };

export function subsystemMarking(block, tasks) {
  if (block.type !== 'Subsystem') return '';
  const trigger = block.trigger;
  if (trigger?.kind === 'edge' || (trigger && trigger.signal && !trigger.interrupt)) {
    const edge = trigger.edge || 'rising';
    return `${edge_arrows[edge] ?? '↑'} ${edge}: ${trigger.signal}`;
  }
  // An interrupt's name and priority: the block's own, else the task table's.
  const task = typeof block.task === 'number' ? (tasks ?? []).find((candidate) => candidate.index === block.task) : null;
  const interrupt = trigger?.interrupt ?? (task?.kind === 'interrupt' ? task.interrupt : undefined);
  if (interrupt) {
    const priority = trigger?.priority ?? task?.priority;
    return priority === undefined ? interrupt : `${interrupt} · priority ${priority}`;
  }
  if (block.enable) return `enable: ${block.enable}`;
  return '';
}
