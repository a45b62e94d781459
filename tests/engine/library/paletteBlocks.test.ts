// The blocks added from OpenPLC Editor's palette, as a user meets them: found by the palette's
// block search, drawn in a ladder program that compiles and runs scan by scan, and carried through
// a PLCopen export (schema-valid) and import unchanged.
import { describe, expect, it } from 'vitest';
import { checkProject } from '../../../src/engine/check';
import { ALL_BLOCKS, searchBlocks } from '../../../src/editor/palette/paletteItems';
import { exportPlcopen } from '../../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../../src/plcopen/importPlcopen';
import { blockSignature } from '../../../src/model/blocks';
import { ladder, plcOf, project, vars } from '../ladder';
import { connections, trace } from '../../plcopen/behaviour';
import { schemaErrors } from '../../plcopen/xsd';

const ADDED = [
  ...['SQRT', 'LN', 'LOG', 'EXP', 'SIN', 'COS', 'TAN', 'ASIN', 'ACOS', 'ATAN', 'EXPT', 'TRUNC'],
  ...['BCD_TO_USINT', 'BCD_TO_UINT', 'BCD_TO_UDINT', 'BCD_TO_ULINT', 'USINT_TO_BCD', 'UINT_TO_BCD', 'UDINT_TO_BCD', 'ULINT_TO_BCD'],
  ...['ADD_TIME', 'SUB_TIME', 'MULTIME', 'DIVTIME'],
  ...['SEMA', 'INTEGRAL', 'DERIVATIVE', 'PID', 'RAMP', 'HYSTERESIS'],
];

/** `rows` grid rows: the first given, the rest empty under the box. */
const tall = (first: string, rows: number) => [first, ...Array.from({ length: rows - 1 }, () => '. # # .')];

function controlProject() {
  return project(
    vars(
      'Auto BOOL',
      'Start BOOL',
      'Level REAL := 8.0',
      'Sp REAL := 10.0',
      'Out REAL',
      'Pid1 PID',
      'Ramp1 RAMP',
      'Sema1 SEMA',
      'Hyst1 HYSTERESIS',
      'R REAL',
      'Busy BOOL',
      'Held BOOL',
      'Hi BOOL',
      'Root REAL',
      'Whole INT',
      'Pw LREAL',
      'Digits USINT := 42',
      'Bcd BYTE',
      'Back USINT',
      'Tm TIME',
      'Ok BOOL',
    ),
    [
      ladder(tall('[Auto] # # .', 8), {
        boxes: [
          {
            row: 0,
            col: 1,
            type: 'PID',
            instance: 'Pid1',
            inputs: { PV: 'Level', SP: 'Sp', X0: '3.0', KP: '2.0', TR: '4.0', TD: '0.5', CYCLE: 'T#1s' },
            outputs: { XOUT: 'Out' },
          },
        ],
      }),
      ladder(tall('[Start] # # (Busy)', 5), {
        boxes: [
          {
            row: 0,
            col: 1,
            type: 'RAMP',
            instance: 'Ramp1',
            inputs: { X0: '0.0', X1: '8.0', TR: 'T#400ms', CYCLE: 'T#100ms' },
            outputs: { XOUT: 'R' },
          },
        ],
      }),
      ladder(tall('[Start] # # (Held)', 2), {
        boxes: [{ row: 0, col: 1, type: 'SEMA', instance: 'Sema1', inputs: { RELEASE: 'Auto' } }],
      }),
      ladder(tall('. # # (Hi)', 4), {
        boxes: [{ row: 0, col: 1, type: 'HYSTERESIS', instance: 'Hyst1', inputs: { XIN1: 'R', XIN2: '4.0', EPS: '1.0' } }],
      }),
      ladder(tall('[Start] # # (Ok)', 2), {
        boxes: [{ row: 0, col: 1, type: 'SQRT', inputs: { IN: 'Level' }, outputs: { OUT: 'Root' } }],
      }),
      ladder(tall('[Start] # # .', 2), {
        boxes: [{ row: 0, col: 1, type: 'TRUNC', inputs: { IN: 'R' }, outputs: { OUT: 'Whole' } }],
      }),
      ladder(tall('[Start] # # .', 3), {
        boxes: [{ row: 0, col: 1, type: 'EXPT', inputs: { IN1: 'Level', IN2: '0.5' }, outputs: { OUT: 'Pw' } }],
      }),
      ladder(tall('[Start] # # .', 2), {
        boxes: [{ row: 0, col: 1, type: 'USINT_TO_BCD', inputs: { IN: 'Digits' }, outputs: { OUT: 'Bcd' } }],
      }),
      ladder(tall('[Start] # # .', 2), {
        boxes: [{ row: 0, col: 1, type: 'BCD_TO_USINT', inputs: { IN: 'Bcd' }, outputs: { OUT: 'Back' } }],
      }),
      ladder(tall('[Start] # # .', 3), {
        boxes: [{ row: 0, col: 1, type: 'MULTIME', inputs: { IN1: 'T#1s', IN2: '1.5' }, outputs: { OUT: 'Tm' } }],
      }),
    ],
    'openplc',
  );
}

describe('palette', () => {
  it('lists every added block, found by name and by category', () => {
    for (const name of ADDED) {
      expect(ALL_BLOCKS, name).toContain(blockSignature(name));
      expect(searchBlocks(name)[0]?.name, name).toBe(name);
    }
    expect(searchBlocks('numerical').map((s) => s.name)).toEqual(expect.arrayContaining(['SQRT', 'ATAN']));
    expect(searchBlocks('control').map((s) => s.name)).toEqual(expect.arrayContaining(['PID', 'RAMP', 'HYSTERESIS']));
    expect(searchBlocks('BCD').map((s) => s.name)).toEqual(expect.arrayContaining(['BCD_TO_UINT', 'UINT_TO_BCD']));
  });
});

describe('in a ladder program (openplc profile)', () => {
  it('compiles with no diagnostics and runs the blocks scan by scan', () => {
    const p = controlProject();
    expect(checkProject(p).map((d) => `${d.rule} ${d.message}`)).toEqual([]);
    const plc = plcOf(p, 100, 'openplc');
    // Scan 1: manual PID gives KP * X0 = 6; Start off: RAMP tracks X0 = 0, nothing else runs.
    plc.scan();
    expect([plc.read('Out'), plc.read('R'), plc.read('Busy'), plc.read('Root')]).toEqual([6, 0, false, 0]);
    // Automatic, PV 8, SP 10: ERROR -2, ITERM 20 - 2 = 18, XOUT = 2 * (-2 + 18/4) = 5. Start: ramp 0 -> 8 in 400 ms.
    plc.write('Auto', true);
    plc.write('Start', true);
    plc.scan();
    expect([plc.read('Out'), plc.read('R'), plc.read('Busy'), plc.read('Held')]).toEqual([5, 0, true, true]);
    expect([plc.read('Root'), plc.read('Ok')]).toEqual([Math.fround(Math.sqrt(8)), true]);
    expect(plc.read('Pw')).toBe(Math.fround(Math.sqrt(8))); // REAL 8 ** 0.5, widened to LREAL
    expect([plc.read('Bcd'), plc.read('Back')]).toEqual([0x42, 42]);
    expect(plc.read('Tm')).toBe(1500);
    plc.scan();
    plc.scan();
    // Ramp at T = 200 ms: 8 * 200/400 = 4; TRUNC(4.0) = 4; HYSTERESIS: 4 is not above 4 + 1.
    expect([plc.read('R'), plc.read('Whole'), plc.read('Hi')]).toEqual([4, 4, false]);
    plc.scan();
    // T = 300 ms: 6 > 5: Q ON.
    expect([plc.read('R'), plc.read('Whole'), plc.read('Hi')]).toEqual([6, 6, true]);
    plc.scan();
    plc.scan();
    expect([plc.read('R'), plc.read('Busy')]).toEqual([8, false]);
  });

  it('MUL and DIV boxes take a TIME and a number (the palette’s Time section)', () => {
    const p = project(vars('A BOOL', 'Base TIME := T#250ms', 'Long TIME', 'Short TIME'), [
      ladder(tall('[A] # # .', 3), { boxes: [{ row: 0, col: 1, type: 'MUL', inputs: { IN1: 'Base', IN2: '4' }, outputs: { OUT: 'Long' } }] }),
      ladder(tall('[A] # # .', 3), { boxes: [{ row: 0, col: 1, type: 'DIV', inputs: { IN1: 'Base', IN2: '2.5' }, outputs: { OUT: 'Short' } }] }),
    ]);
    const plc = plcOf(p);
    plc.write('A', true);
    plc.scan();
    expect([plc.read('Long'), plc.read('Short')]).toEqual([1000, 100]);
  });

  it('refuses wrong types on the pins, naming the block', () => {
    const p = project(vars('A BOOL', 'N INT', 'Y REAL'), [
      ladder(tall('[A] # # .', 2), { boxes: [{ row: 0, col: 1, type: 'SQRT', inputs: { IN: 'N' }, outputs: { OUT: 'Y' } }] }),
    ]);
    const errors = checkProject(p).filter((d) => d.severity === 'error');
    expect(errors.map((d) => d.rule)).toEqual(['LD-R11']);
    expect(errors[0]!.message).toContain('SQRT');
    expect(errors[0]!.message).toContain('INT');
  });
});

describe('PLCopen', () => {
  it('exports schema-valid XML and imports the same program, which runs the same', async () => {
    const original = controlProject();
    const xml = exportPlcopen(original);
    expect(await schemaErrors(xml)).toEqual([]);
    for (const name of ['PID', 'RAMP', 'SEMA', 'HYSTERESIS', 'SQRT', 'TRUNC', 'EXPT', 'USINT_TO_BCD', 'BCD_TO_USINT', 'MULTIME'])
      expect(xml).toContain(`typeName="${name}"`);
    const back = importPlcopen(xml);
    if (!back.ok) throw new Error(JSON.stringify(back.errors));
    expect(back.report.warnings).toEqual([]);
    // PLCopen has no place for Rungsmith's profile: the import says iec; run both as openplc.
    const p = { ...back.project, profile: original.profile };
    expect(p.pous.map((x) => x.variables)).toEqual(original.pous.map((x) => x.variables));
    expect(connections(p)).toEqual(connections(original));
    expect(checkProject(p).filter((d) => d.severity === 'error')).toEqual([]);
    expect(trace(p, 'Main')).toEqual(trace(original, 'Main'));
  });
});
