import { textWidth } from './text_width.js';
import { subsystemMarking } from './subsystem_marking.js';

// A block's box and where its ports sit on it, decided before layout so ELK places the ports
// exactly where the drawing puts them (and the drawing needs no second opinion).
export const name_font = 12;
export const type_font = 11;
export const port_font = 10;
export const port_pitch = 18;
const line_height = 14;
const padding = 8;
const minimum_width = 86;
const open_button_width = 18;

export function portKey(direction, port) {
  return `${direction}:${port}`;
}

export function blockGeometry(block, tasks) {
  const marking = subsystemMarking(block, tasks);
  const isSubsystem = block.type === 'Subsystem';
  const dataInputs = (block.inputs ?? []).filter((port) => port.kind !== 'trigger' && port.kind !== 'enable');
  const controlInputs = (block.inputs ?? []).filter((port) => port.kind === 'trigger' || port.kind === 'enable');
  const outputs = block.outputs ?? [];
  const textLines = marking ? 3 : 2;
  const header = padding + textLines * line_height;
  const widest = (ports) => Math.max(0, ...ports.map((port) => textWidth(port.port, port_font)));
  const width = Math.max(
    minimum_width,
    // Name and marking are bold: measured a size up.
    textWidth(block.name, name_font + 1) + 2 * padding + (isSubsystem ? open_button_width : 0),
    textWidth(block.type, type_font) + 2 * padding,
    marking ? textWidth(marking, type_font + 1) + 2 * padding : 0,
    widest(dataInputs) + widest(outputs) + 3 * padding,
  );
  const rows = Math.max(dataInputs.length, outputs.length);
  const height = header + (rows > 0 ? rows * port_pitch + padding / 2 : padding / 2);
  const rowY = (row) => header + (row + 0.5) * port_pitch;
  const ports = [
    ...dataInputs.map((port, row) => ({ key: portKey('in', port.port), port: port.port, kind: 'data', side: 'WEST', x: 0, y: rowY(row) })),
    ...controlInputs.map((port, column) => ({
      key: portKey('in', port.port), port: port.port, kind: port.kind, side: 'NORTH',
      x: (width * (column + 1)) / (controlInputs.length + 1), y: 0,
    })),
    ...outputs.map((port, row) => ({ key: portKey('out', port.port), port: port.port, kind: 'data', side: 'EAST', x: width, y: rowY(row) })),
  ];
  return { width, height, header, marking, ports, isSubsystem };
}

// The small markers for a system's own inputs and outputs (left and right edge of the drawing).
export function systemPortGeometry(direction, port) {
  const width = Math.max(40, textWidth(port, port_font) + 24);
  return {
    width, height: 20, marking: '', header: 0, isSubsystem: false,
    ports: [{ key: portKey(direction === 'input' ? 'out' : 'in', port), port, kind: 'data', side: direction === 'input' ? 'EAST' : 'WEST', x: direction === 'input' ? width : 0, y: 10 }],
  };
}

// The "?" a wire nobody drives starts from.
export function undrivenStubGeometry() {
  return { width: 18, height: 18, marking: '', header: 0, isSubsystem: false, ports: [{ key: 'out:?', port: '?', kind: 'data', side: 'EAST', x: 18, y: 9 }] };
}
