// `rungsmith simulate` traces of the classic programs, checked scan by scan against values worked
// out by hand from the IEC definitions (timers time from the start of the scan on the virtual clock).
import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { EXAMPLES } from '../../src/model/examples';
import { saveProject } from '../../src/model/load';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { csv, rungsmith } from './memoryIo';

const example = (id: string) => saveProject(EXAMPLES.find((e) => e.id === id)!.build());

describe('rungsmith simulate', () => {
  it('motor seal-in: Start latches the motor, Stop drops it; default watch is every variable in order', () => {
    const stim = 'scan,Start,Stop\n2,1,\n3,0,\n6,,1\n7,,0\n';
    const r = rungsmith(['simulate', 'motor.json', '--inputs', 'stim.csv', '--scans', '8'], {
      'motor.json': example('motor-start-stop'),
      'stim.csv': stim,
    });
    expect(r.err).toBe('');
    expect(r.code).toBe(0);
    expect(csv(r.out)).toEqual([
      ['scan', 'time_ms', 'Start', 'Stop', 'Motor'],
      ['1', '0', '0', '0', '0'],
      ['2', '10', '1', '0', '1'],
      ['3', '20', '0', '0', '1'],
      ['4', '30', '0', '0', '1'],
      ['5', '40', '0', '0', '1'],
      ['6', '50', '0', '1', '0'],
      ['7', '60', '0', '0', '0'],
      ['8', '70', '0', '0', '0'],
    ]);
  });

  it('traffic light on a 1 s cycle: each TON output rises at the first scan starting PT after its input rose', () => {
    const r = rungsmith(
      [
        'simulate',
        'tl.json',
        '--cycle',
        '1s',
        '--scans',
        '19',
        '--watch',
        'Red,Green,Yellow,RedTime.ET,GreenTime.Q',
      ],
      {
        'tl.json': example('traffic-light'),
      },
    );
    expect(r.code).toBe(0);
    const rows = csv(r.out);
    expect(rows[0]).toEqual(['scan', 'time_ms', 'Red', 'Green', 'Yellow', 'RedTime.ET', 'GreenTime.Q']);
    // prettier-ignore
    const expected = [
      // scan, time, Red, Green, Yellow, RedTime.ET, GreenTime.Q
      [1, 0, 1, 0, 0, 0, 0],          // red timer starts at 0 ms
      [2, 1000, 1, 0, 0, 1000, 0],
      [5, 4000, 1, 0, 0, 4000, 0],
      [6, 5000, 0, 1, 0, 5000, 0],    // 5 s: red over, green timer starts at 5000
      [9, 8000, 0, 1, 0, 5000, 0],
      [10, 9000, 0, 0, 1, 5000, 1],   // 4 s of green: yellow timer starts at 9000
      [11, 10000, 0, 0, 1, 5000, 1],  // yellow done, seen by the red network only next scan
      [12, 11000, 1, 0, 0, 0, 0],     // the chain resets
      [13, 12000, 1, 0, 0, 0, 0],     // red timer restarts at 12000
      [14, 13000, 1, 0, 0, 1000, 0],
      [17, 16000, 1, 0, 0, 4000, 0],
      [18, 17000, 0, 1, 0, 5000, 0],
      [19, 18000, 0, 1, 0, 5000, 0],
    ];
    for (const row of expected) expect(rows[row[0]!]).toEqual(row.map(String));
  });

  it('parts counter: counts rising edges of the sensor, Done at 10, Reset clears', () => {
    const lines = ['scan,PartSensor,Reset'];
    for (let k = 1; k <= 24; k++) lines.push(`${k},${k % 2},${k === 21 ? 1 : k === 22 ? 0 : ''}`);
    const r = rungsmith(
      ['simulate', 'pc.json', '--inputs', 'stim.csv', '--watch', 'PartCount,Done,Parts.Q'],
      {
        'pc.json': example('parts-counter'),
        'stim.csv': lines.join('\n'),
      },
    );
    expect(r.code).toBe(0);
    const rows = csv(r.out).slice(1);
    expect(rows).toHaveLength(24); // default: up to the last stimulus scan
    const count = rows.map((row) => Number(row[2]));
    expect(count.slice(0, 20)).toEqual([1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10]);
    expect(count.slice(20)).toEqual([0, 0, 1, 1]);
    const done = rows.map((row) => row[3]);
    expect(done.slice(17, 22)).toEqual(['0', '1', '1', '0', '0']);
    expect(rows.map((row) => row[4])).toEqual(done);
  });

  it('simulates a PLCopen file the same as the project it was exported from', () => {
    const project = EXAMPLES.find((e) => e.id === 'traffic-light')!.build();
    const args = ['--cycle', '250ms', '--scans', '60'];
    const fromJson = rungsmith(['simulate', 'p.json', ...args], { 'p.json': saveProject(project) });
    const fromXml = rungsmith(['simulate', 'p.xml', ...args], { 'p.xml': exportPlcopen(project) });
    expect(fromXml.code).toBe(0);
    expect(fromXml.out).toBe(fromJson.out);
  });

  it('TIME in ms, INT in decimal, --profile openplc stops CTU at PV', () => {
    const lines = ['scan,PartSensor'];
    for (let k = 1; k <= 30; k++) lines.push(`${k},${k % 2}`);
    const files = { 'pc.json': example('parts-counter'), 's.csv': lines.join('\n') };
    const iec = csv(
      rungsmith(['simulate', 'pc.json', '--inputs', 's.csv', '--watch', 'PartCount'], files).out,
    );
    const openplc = csv(
      rungsmith(
        ['simulate', 'pc.json', '--inputs', 's.csv', '--watch', 'PartCount', '--profile', 'openplc'],
        files,
      ).out,
    );
    expect(iec[30]![2]).toBe('15');
    expect(openplc[30]![2]).toBe('10');
  });

  it('refuses unknown variables, bad stimulus values and invalid programs on stderr with a non-zero exit', () => {
    const files = {
      'm.json': example('motor-start-stop'),
      'bad.csv': 'scan,Start\n1,maybe\n',
      'ghost.csv': 'scan,Ghost\n1,1\n',
    };
    const unknown = rungsmith(['simulate', 'm.json', '--watch', 'Motor,Nope'], files);
    expect(unknown.code).toBe(2);
    expect(unknown.err).toContain('unknown variable "Nope"');
    const bad = rungsmith(['simulate', 'm.json', '--inputs', 'bad.csv'], files);
    expect(bad.code).toBe(2);
    expect(bad.err).toContain('bad.csv line 2, column Start');
    expect(rungsmith(['simulate', 'm.json', '--inputs', 'ghost.csv'], files).err).toContain('column "Ghost"');
    const broken = JSON.parse(files['m.json']);
    broken.pous[0].networks[0].elements.push({
      id: 'x1',
      kind: 'coil',
      coil: 'COIL',
      variable: 'Undeclared',
      row: 1,
      col: 9,
    });
    const invalid = rungsmith(['simulate', 'b.json'], { 'b.json': JSON.stringify(broken) });
    expect(invalid.code).toBe(1);
    expect(invalid.err).toMatch(/^error LD-R\d+ Main\/network 1/m);
    expect(invalid.out).toBe('');
  });
});

describe('rungsmith simulate on a configuration of several program instances', () => {
  const xml = readFileSync(
    fileURLToPath(new URL('../fixtures/reference/c05-two-instances-bare-names.xml', import.meta.url)),
    'utf8',
  );

  it('a bare name is the first program instance of the first task; Inst.Var names any instance', () => {
    const r = rungsmith(
      ['simulate', 'p.xml', '--scans', '4', '--watch', 'Start,Run,PumpCtl.Run,FanCtl.Run', '--inputs', 's.csv'],
      { 'p.xml': xml, 's.csv': 'scan,Start,FanCtl.Start\n1,0,0\n3,1,1\n' },
    );
    expect(r.code).toBe(0);
    expect(csv(r.out)).toEqual([
      ['scan', 'time_ms', 'Start', 'Run', 'PumpCtl.Run', 'FanCtl.Run'],
      ['1', '0', '0', '0', '0', '1'],
      ['2', '10', '0', '0', '0', '1'],
      ['3', '20', '1', '1', '1', '0'],
      ['4', '30', '1', '0', '0', '0'],
    ]);
  });

  it('a name in no instance is still refused, naming it', () => {
    const r = rungsmith(['simulate', 'p.xml', '--scans', '1', '--watch', 'Nowhere'], { 'p.xml': xml });
    expect(r.code).toBe(2);
    expect(r.err).toContain('unknown variable "Nowhere"');
  });
});
