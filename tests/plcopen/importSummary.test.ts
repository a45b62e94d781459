// Issue 22, section 2 item 13: after an import the editor opens the program the configuration's
// resource runs (first_steps opened its ST function), and the report counts POUs by their body
// language ("7 LD POUs" for 3).
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, test } from 'vitest';
import { newPou, newProject } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { pouCountText, pouToOpen } from '../../src/plcopen/importSummary';

function imported(file: string): Project {
  const r = importPlcopen(readFileSync(join(__dirname, '../fixtures/plcopen', file), 'utf8'));
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return r.project;
}

const nameOf = (p: Project) => p.pous.find((x) => x.id === pouToOpen(p))?.name;

describe('the POU an import opens', () => {
  test('the program the resource runs, not the ST function first in the file nor a program no task runs', () => {
    const p = imported('open-resource-program.xml');
    expect(p.pous.map((x) => `${x.name}:${x.language}`)).toEqual(['Halve:ST', 'Latch:LD', 'Spare:LD', 'Plant:LD']);
    expect(nameOf(p)).toBe('Plant');
  });

  test('files whose first POU is an SFC function block open their program (legacy v1.0 and v2.01)', () => {
    expect(nameOf(imported('legacy-sfc-v10.xml'))).toBe('Main');
    expect(nameOf(imported('sfc-ld-actions.xml'))).toBe('Main');
  });

  test('without tasks: the first PROGRAM, else the first LD POU', () => {
    const fn = { ...newPou('Calc'), kind: 'FUNCTION' as const, language: 'ST' as const };
    const fb = { ...newPou('Motor'), kind: 'FUNCTION_BLOCK' as const };
    const prog = newPou('Line');
    expect(nameOf(newProject('a', { pous: [fn, fb, prog], tasks: [] }))).toBe('Line');
    expect(nameOf(newProject('b', { pous: [fn, fb], tasks: [] }))).toBe('Motor');
  });
});

describe('the POU count of the import report', () => {
  test('counts POUs by their body language', () => {
    expect(pouCountText(imported('open-resource-program.xml'))).toBe('4 POUs (3 LD, 1 ST)');
    expect(pouCountText(imported('names-globals.xml'))).toBe('2 POUs (LD)');
    expect(pouCountText(imported('timer-chain-openplc.xml'))).toBe('1 POU (LD)');
  });
});
