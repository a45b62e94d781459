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
    expect(parseLocation('%IX0.8')).toBeUndefined();
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
