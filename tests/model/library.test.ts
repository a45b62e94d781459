// The project's own FBs and functions as blocks: pins from the interface, layout like a standard block.
import { describe, expect, test } from 'vitest';
import { boxLayout } from '../../src/model/boxLayout';
import { newPou, newProject, variable } from '../../src/model/factory';
import { blockLibrary, isInOutPin, STANDARD_LIBRARY } from '../../src/model/library';

const motor = newPou('Motor', {
  kind: 'FUNCTION_BLOCK',
  variables: [
    variable('Start', 'BOOL', { varClass: 'input' }),
    variable('Run', 'BOOL', { varClass: 'output' }),
    variable('Count', 'INT', { varClass: 'inOut' }),
    variable('Stop', 'BOOL', { varClass: 'input' }),
    variable('Seal', 'BOOL'),
  ],
});
const scale = newPou('Scale', {
  kind: 'FUNCTION',
  returnType: 'REAL',
  variables: [variable('Raw', 'INT', { varClass: 'input' })],
});
const project = newProject('P', { pous: [newPou('Main'), motor, scale] });

describe('block library', () => {
  test('user FBs and functions get pins from their interfaces; programs are not blocks', () => {
    const lib = blockLibrary(project);
    const m = lib.signature('motor')!;
    expect(m.kind).toBe('fb');
    expect(m.inputs.map((p) => p.name)).toEqual(['Start', 'Count', 'Stop']);
    expect(m.outputs.map((p) => p.name)).toEqual(['Run', 'Count']);
    expect(m.outputs.filter(isInOutPin).map((p) => p.name)).toEqual(['Count']);
    const s = lib.signature('SCALE')!;
    expect(s.kind).toBe('function');
    expect(s.outputs[0]).toMatchObject({ name: 'OUT', type: 'REAL' });
    expect(lib.signature('Main')).toBeUndefined();
    expect(lib.isFbType('Motor')).toBe(true);
    expect(lib.isFbType('TON')).toBe(true);
    expect(lib.isFbType('Scale')).toBe(false);
    expect(lib.userBlocks.map((b) => b.name)).toEqual(['Motor', 'Scale']);
    expect(STANDARD_LIBRARY.signature('Motor')).toBeUndefined();
  });

  test('the library follows the project: memoised per POU list, new after an edit', () => {
    expect(blockLibrary(project)).toBe(blockLibrary({ pous: project.pous }));
    const edited = { ...project, pous: project.pous.map((p) => (p === scale ? { ...p, returnType: 'INT' } : p)) };
    expect(blockLibrary(edited).signature('Scale')!.outputs[0]!.type).toBe('INT');
  });

  test('a box of a user block is laid out from its interface; EN/ENO for functions and on request for FBs', () => {
    const lib = blockLibrary(project);
    const fb = boxLayout({ blockType: 'Motor' }, lib)!;
    expect(fb.inputs.map((p) => `${p.name}@${p.rowOffset}`)).toEqual(['Start@0', 'Count@1', 'Stop@2']);
    expect(fb.rows).toBe(3);
    const fbEn = boxLayout({ blockType: 'Motor', executionControl: true }, lib)!;
    expect(fbEn.inputs.map((p) => p.name)).toEqual(['EN', 'Start', 'Count', 'Stop']);
    expect(fbEn.outputs.map((p) => p.name)).toEqual(['ENO', 'Run', 'Count']);
    const fn = boxLayout({ blockType: 'Scale' }, lib)!;
    expect(fn.outputs.map((p) => p.name)).toEqual(['ENO', 'OUT']);
    expect(boxLayout({ blockType: 'Motor' })).toBeUndefined();
    const ton = boxLayout({ blockType: 'TON', executionControl: true })!;
    expect(ton.inputs.map((p) => p.name)).toEqual(['EN', 'IN', 'PT']);
  });
});
