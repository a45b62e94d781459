// The palette's block list and the block search (B) offer the project's own FBs and functions
// with their pins, never the POU being edited, and no FBs inside a FUNCTION.
import { expect, test } from 'vitest';
import { newPou, newProject, variable } from '../../src/model/factory';
import { blockLibrary } from '../../src/model/library';
import { boxTemplate, pinSummary, searchBlocks } from '../../src/editor/palette/paletteItems';

const motor = newPou('Motor', {
  kind: 'FUNCTION_BLOCK',
  variables: [
    variable('Start', 'BOOL', { varClass: 'input' }),
    variable('Stop', 'BOOL', { varClass: 'input' }),
    variable('Run', 'BOOL', { varClass: 'output' }),
  ],
});
const scale = newPou('Scale', {
  kind: 'FUNCTION',
  returnType: 'REAL',
  variables: [variable('Raw', 'INT', { varClass: 'input' })],
});
const project = newProject('P', { pous: [newPou('Main'), motor, scale] });
const lib = blockLibrary(project);

test("the project's blocks come first, found by name in any case, with their pins", () => {
  expect(
    searchBlocks('', lib)
      .slice(0, 2)
      .map((s) => s.name),
  ).toEqual(['Motor', 'Scale']);
  expect(searchBlocks('mot', lib)[0]!.name).toBe('Motor');
  expect(pinSummary(lib.signature('Motor')!)).toBe('Start : BOOL, Stop : BOOL → Run : BOOL');
  expect(pinSummary(lib.signature('Scale')!)).toBe('Raw : INT → OUT : REAL');
  expect(boxTemplate(lib.signature('Motor')!, lib)).toEqual({
    kind: 'box',
    blockType: 'Motor',
    instance: '',
    inputs: {},
    outputs: {},
  });
  expect(boxTemplate(lib.signature('Scale')!, lib)).not.toHaveProperty('instance');
});

test('inside a POU the POU itself is not offered; inside a FUNCTION no function block is', () => {
  expect(searchBlocks('', lib, motor).map((s) => s.name)).not.toContain('Motor');
  const inFunction = searchBlocks('', lib, scale);
  expect(inFunction.map((s) => s.name)).not.toContain('Scale');
  expect(inFunction.some((s) => s.kind === 'fb')).toBe(false);
  expect(inFunction.map((s) => s.name)).toContain('ADD');
});
