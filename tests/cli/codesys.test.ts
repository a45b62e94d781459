// `rungsmith simulate` on a CODESYS V3 export (issue 23 class 8): the task runs a CFC PLC_PRG and
// an LD program; the LD one runs (the CFC one is named and left out), with CODESYS Util's BLINK
// and LIMITALARM and a structure of BIT members.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { csv, rungsmith } from './memoryIo';

const xml = readFileSync(fileURLToPath(new URL('../fixtures/plcopen/codesys-v3-application.xml', import.meta.url)), 'utf8');

describe('rungsmith simulate on a CODESYS V3 export', () => {
  it('runs the LD program of the task, says the CFC one is left out, and traces BLINK, LIMITALARM and BIT members', () => {
    const r = rungsmith(
      [
        'simulate',
        'app.xml',
        '--inputs',
        'stim.csv',
        '--scans',
        '8',
        '--cycle',
        '10ms',
        '--watch',
        'LampLogic.Lamp,LampLogic.Status.Blinking,LampLogic.HighAlarm,LampLogic.InRange,LampLogic.Status.Alarm',
      ],
      { 'app.xml': xml, 'stim.csv': 'scan,Enable,Level\n1,1,50\n5,0,90\n7,1,90\n' },
    );
    expect(r.code).toBe(0);
    expect(r.err).toContain('warning LD-W51');
    expect(r.err).toContain('the program instance PLC_PRG runs PLC_PRG, written in CFC, which the simulator does not run');
    expect(r.err).toMatch(/POU "PLC_PRG" is written in CFC \(CODESYS\)/);
    expect(r.err).toMatch(/block type RAMP_INT is a block of CODESYS's Util library that Rungsmith does not run/);
    expect(r.err).not.toContain('has no PROGRAM');
    expect(csv(r.out)).toEqual([
      ['scan', 'time_ms', 'LampLogic.Lamp', 'LampLogic.Status.Blinking', 'LampLogic.HighAlarm', 'LampLogic.InRange', 'LampLogic.Status.Alarm'],
      // TIMEHIGH 30 ms: TRUE for three scans, then TIMELOW 20 ms FALSE.
      ['1', '0', '1', '1', '0', '1', '0'],
      ['2', '10', '1', '1', '0', '1', '0'],
      ['3', '20', '1', '1', '0', '1', '0'],
      ['4', '30', '0', '0', '0', '1', '0'],
      // ENABLE FALSE: OUT keeps FALSE; Level 90 > HIGH 80.
      ['5', '40', '0', '0', '1', '0', '0'],
      ['6', '50', '0', '0', '1', '0', '0'],
      // ENABLE again: a new TIMEHIGH phase; the packed Alarm bit follows HighAlarm AND Enable.
      ['7', '60', '1', '1', '1', '0', '1'],
      ['8', '70', '1', '1', '1', '0', '1'],
    ]);
  });

  it('check names the CFC body as the one thing that cannot run (no type errors from BIT)', () => {
    const r = rungsmith(['check', 'app.xml'], { 'app.xml': xml });
    const errors = r.out.split('\n').concat(r.err.split('\n')).filter((l) => /^error /.test(l));
    expect(errors).toEqual([expect.stringMatching(/^error LD-E51 PLC_PRG.*written in CFC/)]);
  });
});
