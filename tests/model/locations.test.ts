// IEC addresses, including hierarchical ones (IEC 61131-3 table 15; MATIEC reads `%IW0.0` and
// CANopen's `%IB0.0.32.24576.1` as locations of their own, as OpenPLC Editor files write them).
import { describe, expect, test } from 'vitest';
import { locationText, parseLocation } from '../../src/model/iecTypes';
import { openPlcRegister } from '../../src/gateway/pointMap';
import { checkProject } from '../../src/engine/check';
import { ladder, plcOf, project, trace, vars } from '../engine/ladder';

describe('IEC addresses', () => {
  test('flat addresses read as before', () => {
    expect(parseLocation('%ix0.3')).toEqual({ area: 'I', size: 'X', index: 0, bit: 3 });
    expect(parseLocation('%QW7')).toEqual({ area: 'Q', size: 'W', index: 7 });
    // No bound on the bit: %IX0.12 is a location of its own (MATIEC compiles it), with no OpenPLC register.
    expect(parseLocation('%IX0.12')).toEqual({ area: 'I', size: 'X', index: 0, bit: 12 });
    expect(openPlcRegister('%IX0.12')).toBeUndefined();
    expect(parseLocation('%I3')).toBeUndefined();
  });

  test('hierarchical addresses are locations of their own, written back as read', () => {
    expect(parseLocation('%IW0.0')).toEqual({ area: 'I', size: 'W', index: 0, levels: [0] });
    expect(parseLocation('%IB0.0.32.24576.1')).toEqual({ area: 'I', size: 'B', index: 0, levels: [0, 32, 24576, 1] });
    expect(locationText(parseLocation('%iw0.1')!)).toBe('%IW0.1');
    expect(locationText(parseLocation('%IX1.2.3')!)).toBe('%IX1.2.3');
    // No OpenPLC Modbus register is assumed for them: the gateway does not bind them.
    expect(openPlcRegister('%IW0.0')).toBeUndefined();
    expect(openPlcRegister('%IW0')).toEqual({ table: 'inputRegisters', register: 0 });
  });

  test('a program with %IW0.0 and %IW0.1 inputs compiles and runs; the two are different inputs', () => {
    const p = project(
      [...vars('Flag BOOL'), { ...vars('T1 INT')[0]!, location: '%IW0.0' }, { ...vars('T2 INT')[0]!, location: '%IW0.1' }],
      [ladder(['- # # .', '. # # .', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'GT', inputs: { IN1: 'T1', IN2: 'T2' }, outputs: { OUT: 'Flag' } }] })],
    );
    expect(checkProject(p).filter((d) => d.severity === 'error')).toEqual([]);
    expect(trace(plcOf(p), [{ T1: 5, T2: 3 }, { T1: 1, T2: 3 }], ['Flag'])).toEqual([[1], [0]]);
  });
});

describe('bits beyond 7', () => {
  test('%IX0.12 and %IX1.4 are two inputs; LD-W04 says that no device drives %IX0.12', () => {
    const p = project(
      [{ ...vars('A BOOL')[0]!, location: '%IX0.12' }, { ...vars('B BOOL')[0]!, location: '%IX1.4' }, ...vars('Q BOOL')],
      [ladder(['[A] - (Q)'])],
    );
    const d = checkProject(p);
    expect(d.filter((x) => x.severity === 'error')).toEqual([]);
    expect(d.find((x) => x.rule === 'LD-W04')?.message).toContain('"A" is at bit 12 of byte 0 (%IX0.12)');
    const plc = plcOf(p);
    plc.write('A', true);
    plc.scan();
    expect(plc.read('Q')).toBe(true);
    expect(plc.read('B')).toBe(false);
  });
});
