import { parentPath, systemOfBlock } from './model_index.js';

// Markers per block as shown in one system: a block's own, and for a subsystem box every marker
// inside it (a problem inside a closed box must still show). Errors outrank warnings.
export function markersInSystem(markers, systemPath) {
  const shown = new Map();
  for (const [blockId, list] of markers ?? []) {
    // Walk up from the block to the child of `systemPath` that holds it, if any.
    let holder = blockId;
    while (holder !== '' && systemOfBlock(holder) !== systemPath) holder = parentPath(holder);
    if (holder === '' || systemOfBlock(holder) !== systemPath) continue;
    shown.set(holder, [...(shown.get(holder) ?? []), ...list.map((marker) => (holder === blockId ? marker : { ...marker, message: `${blockId.slice(holder.length + 1)}: ${marker.message}` }))]);
  }
  return shown;
}

export function worstSeverity(list) {
  return list.some((marker) => marker.severity === 'error') ? 'error' : 'warning';
}
