// Profile `openplc`: the blocks no coil needs run after every coil of the POU body, as units of
// their own that the body's last network calls (codegen.ts lateUnits). These cases check what the
// user sees of them: stepping into a late user FB, forcing a variable a late block writes, and late
// blocks at two depths (a late user FB whose own body has a late TON), on the dispatch loops and
// on straight-line code.
import { describe, expect, test } from 'vitest';
import type { Plc } from '../../src/engine/api';
import { compileProgram } from '../../src/engine/plc';
import { ScanPlc } from '../../src/engine/runtime/scanner';
import { DEFAULT_TIERING } from '../../src/engine/runtime/tiering';
import type { Profile } from '../../src/model/project';
import { io, multiProject, pou } from './userBlocksHelpers';
import { ladder, vars } from './ladder';

const dispatchOnly = { ...DEFAULT_TIERING, startAfterEvals: Infinity };
const switchAtOnce = { ...DEFAULT_TIERING, startAfterEvals: 0, minScans: 1, msPerNetwork: 0, batch: 1 };

// Blinker: its TON reaches only the rail (a late block of its body), its coil reads T1.Q.
const blinker = pou('Blinker', 'FUNCTION_BLOCK', [...io('input', 'Go BOOL'), ...io('output', 'Lamp BOOL'), ...vars('T1 TON')], [
  ladder(['[Go] # # -', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T1', inputs: { PT: 'T#20ms' } }] }),
  ladder(['[T1.Q] (Lamp)']),
]);
// Main: the Blinker's output reaches only the rail too (a late block of Main), a coil reads it.
const main = pou('Main', 'PROGRAM', vars('Go BOOL %IX0.0', 'Lamp BOOL %QX0.0', 'B1 Blinker'), [
  ladder(['[Go] # # -', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'Blinker', instance: 'B1' }] }),
  ladder(['[B1.Lamp] (Lamp)']),
]);

function plcs(profile: Profile): ScanPlc[] {
  const { program, diagnostics } = compileProgram({ ...multiProject([main, blinker]), profile });
  if (!program) throw new Error(diagnostics.map((d) => d.message).join('\n'));
  return [new ScanPlc(program, { cycleMs: 10 }, dispatchOnly), new ScanPlc(program, { cycleMs: 10 }, switchAtOnce)];
}

const read = (plc: Plc) => ['B1.T1.Q', 'B1.Lamp', 'Lamp'].map((n) => (plc.read(n) ? 1 : 0));
const where = (plc: Plc) => plc.position().map((f) => `${f.instance ? `${f.instance} (${f.pou})` : f.pou}/${f.network + 1}`).join(' → ');

describe('openplc: late blocks at two depths', () => {
  test('the late FB runs after Main\'s coils and its late TON after its own coils: the lamp follows T1.Q two scans late', () => {
    for (const plc of plcs('openplc')) {
      plc.write('Go', true);
      const rows = Array.from({ length: 6 }, () => (plc.scan(), read(plc)));
      expect(rows).toEqual([[0, 0, 0], [0, 0, 0], [1, 0, 0], [1, 1, 0], [1, 1, 1], [1, 1, 1]]);
    }
    for (const plc of plcs('iec')) {
      plc.write('Go', true);
      const rows = Array.from({ length: 4 }, () => (plc.scan(), read(plc)));
      expect(rows).toEqual([[0, 0, 0], [0, 0, 0], [1, 1, 1], [1, 1, 1]]);
    }
  });

  test('the late blocks write their nets back for the power display: the late FB box shows its powered input', () => {
    for (const plc of plcs('openplc')) {
      plc.write('Go', true);
      plc.scans(3);
      const contact = main.networks[0]!.elements.findIndex((e) => e.kind === 'contact');
      expect(plc.snapshot().networks[0]!.elements[contact]! & 2).toBe(2);
    }
  });
});

describe('openplc: stepping into a late user FB', () => {
  test('a step into stops before each network of the late FB, after the last network of Main, and ends with the same values', () => {
    const [stepped, scanned] = plcs('openplc');
    for (const plc of [stepped!, scanned!]) plc.write('Go', true);
    scanned!.scans(3);
    stepped!.scans(2);
    const stops: string[] = [];
    for (let k = 0; k < 10; k++) {
      const r = stepped!.stepNetwork({ into: true });
      stops.push(r.scanDone ? 'scan done' : where(stepped!));
      if (r.scanDone) break;
    }
    expect(stops).toEqual(['Main/2', 'Main/2 → B1 (Blinker)/1', 'Main/2 → B1 (Blinker)/2', 'scan done']);
    expect(read(stepped!)).toEqual(read(scanned!));
    expect(read(stepped!)).toEqual([1, 0, 0]);
  });
});

describe('openplc: forcing a variable a late block writes', () => {
  test('the late FB does not overwrite its forced output, and writes it again once unforced', () => {
    for (const plc of plcs('openplc')) {
      plc.scans(2);
      plc.force('B1.Lamp', true);
      plc.scans(3);
      expect(read(plc)).toEqual([0, 1, 1]);
      plc.unforce('B1.Lamp');
      plc.scans(2);
      expect(read(plc)).toEqual([0, 0, 0]);
    }
  });
});
