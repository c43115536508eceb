// Edits made on the diagram (palette, drags, the Block form), each turned into a splice of the
// text by yaml_edit and applied as one undoable editor transaction; the check loop then sends
// the new text like any typing. Problems (a text that does not read, a taken name) are said,
// never half-applied.
import {
  addBlock, connectPorts, deleteBlock, newBlockName, removeBlockParameter, renameSignal, setBlockParameter,
  setModelParameterValue, systemNames, yamlValue,
} from './yaml_edit.js';
import { defaultValue } from './parameter_rules.js';
import { findBlock, findSystem } from './selection_sync.js';

export function createDiagramEdits({ editor, getDiagram, currentSystem, say }) {
  // A model reference's blocks, and the parameters its model brings, are in that model's file, not in this text.
  const fileOfBlock = (id) => findBlock(getDiagram(), id)?.file;
  const fileOfSystem = (path) => findSystem(getDiagram(), path)?.blocks?.find((block) => block.file)?.file;
  const fileOfParameter = (name) => getDiagram()?.parameters?.find((parameter) => parameter.name === name)?.file;

  // Runs one edit; returns its result, or undefined when it could not be made (and says why). `elsewhere`: the
  // file of what it would change when that is not this text.
  const attempt = (what, edit, elsewhere) => {
    if (elsewhere) {
      say(`${what}: that is in ${elsewhere}, not in this text: edit it there`, 'bad');
      return undefined;
    }
    try {
      const result = edit(editor.editText());
      editor.applyEdits(result.changes);
      say(result.message ?? what, 'good');
      return result;
    } catch (error) {
      say(`${what}: ${error.message}`, 'bad');
      return undefined;
    }
  };

  return {
    addBlock(entry) {
      const system = currentSystem();
      return attempt(`add ${entry.type}`, (text) => {
        const name = newBlockName(entry.type, systemNames(text, system).blocks);
        const parameters = (entry.parameters ?? []).filter((spec) => spec.required).map((spec) => [spec.name, yamlValue(defaultValue(spec))]);
        const id = system ? `${system}/${name}` : name;
        return { changes: addBlock(text, system, { name, type: entry.type, parameters }), id, message: `added ${id}` };
      }, fileOfSystem(system))?.id;
    },

    connect({ from, to }) {
      const source = findBlock(getDiagram(), from.block);
      const signal = source?.outputs?.find((port) => port.port === from.port)?.signal;
      return attempt(`connect ${from.block}.${from.port} to ${to.block}.${to.port}`, (text) => {
        const result = connectPorts(text, { ...from, signal }, to);
        return { ...result, message: `${to.block}.${to.port} reads ${result.signal}` };
      }, fileOfSystem(currentSystem()));
    },

    renameSignal(system, oldName, newName) {
      return attempt(`rename ${oldName}`, (text) => ({ changes: renameSignal(text, system, oldName, newName), message: `renamed ${oldName} to ${newName}` }), fileOfSystem(system));
    },

    // `typed` as the user wrote it; empty removes an optional parameter.
    setParameter(blockId, name, typed) {
      return attempt(`set ${name}`, (text) => ({
        changes: typed.trim() === '' ? removeBlockParameter(text, blockId, name) : setBlockParameter(text, blockId, name, yamlValue(typed)),
        message: typed.trim() === '' ? `removed ${name} of ${blockId}` : `${name} of ${blockId} = ${typed.trim()}`,
      }), fileOfBlock(blockId));
    },

    setModelParameter(name, typed) {
      return attempt(`set ${name}`, (text) => ({ changes: setModelParameterValue(text, name, yamlValue(typed)), message: `${name} = ${typed.trim()}` }), fileOfParameter(name));
    },

    deleteBlock(blockId) {
      return attempt(`delete ${blockId}`, (text) => ({ changes: deleteBlock(text, blockId), message: `deleted ${blockId}` }), fileOfBlock(blockId));
    },
  };
}
