// The target's arrays reach the page one element at a time: the A2L's measurement `gains` becomes
// the telemetry items `gains[0]`, `gains[1]`, ... and a simulation's column names do the same.
// The diagram knows a wire by the array's own name, so the page needs both directions.

const indexed_name = /^(.+?)((?:\[\d+\])+)$/;

// `gains[1]` -> {base: 'gains', indices: [1]}; `m[1][0]` -> {base: 'm', indices: [1, 0]};
// a plain name has no indices.
export function splitItemName(name) {
  const match = indexed_name.exec(name);
  if (!match) return { base: name, indices: [] };
  return { base: match[1], indices: [...match[2].matchAll(/\d+/g)].map((digits) => Number(digits[0])) };
}

export function baseName(name) {
  return splitItemName(name).base;
}

// The items of one name as the diagram calls it: the scalar itself, or every element of the
// array, in the order the description lists them.
export function itemsNamed(items, name) {
  return items.filter((item) => item.name === name || baseName(item.name) === name);
}

// Items grouped by base name, in first-seen order: [{name, vector, positions}], `positions` the
// items' places in `names`, ordered by their indices (row-major for a matrix) whatever order the
// description gave them in.
export function groupItems(names) {
  const groups = new Map();
  names.forEach((name, position) => {
    const { base, indices } = splitItemName(name);
    if (!groups.has(base)) groups.set(base, { name: base, vector: false, members: [] });
    const group = groups.get(base);
    group.members.push({ position, indices });
    if (indices.length > 0) group.vector = true;
  });
  return [...groups.values()].map(({ name, vector, members }) => ({
    name,
    vector,
    positions: members.sort((a, b) => compareIndices(a.indices, b.indices)).map((member) => member.position),
  }));
}

function compareIndices(a, b) {
  for (let i = 0; i < Math.min(a.length, b.length); i += 1) if (a[i] !== b[i]) return a[i] - b[i];
  return a.length - b.length;
}
