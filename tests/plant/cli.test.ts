// The machines on the command line (issue 26): `rungsmith test` runs the exercise's scenario as CI
// does, `rungsmith simulate --plant` traces the machine, `rungsmith plants` lists the machines.
import { describe, expect, test } from 'vitest';
import { tankReference, tankWrong } from '../../src/plant/exercises';
import { rungsmith } from '../cli/memoryIo';

describe('rungsmith and the machines', () => {
  test('test: the reference solution passes its scenario, the wrong one fails where the tank overflows', () => {
    const ok = rungsmith(['test', 'tank.json'], { 'tank.json': JSON.stringify(tankReference()) });
    expect(ok.code).toBe(0);
    expect(ok.out).toContain('PASS Tank held between the switches for 5 minutes (3000 scans)');
    const bad = rungsmith(['test', 'tank.json', '--junit', 'out.xml'], {
      'tank.json': JSON.stringify(tankWrong()),
    });
    expect(bad.code).toBe(1);
    expect(bad.out).toContain(
      'FAIL Tank held between the switches for 5 minutes: the tank overflowed at scan 576 (57.50 s)',
    );
    expect(bad.files.get('out.xml')).toContain('failure message="the tank overflowed at scan 576 (57.50 s)"');
  });

  test('simulate --plant: the machine in the trace, its faults and controls as stimulus columns, consequences on stderr', () => {
    const r = rungsmith(
      [
        'simulate',
        'tank.json',
        '--plant',
        'tank',
        '--inputs',
        's.csv',
        '--scans',
        '700',
        '--cycle',
        '100ms',
        '--watch',
        'HighLevel,tank.level,tank.overflowing',
      ],
      {
        'tank.json': JSON.stringify(tankReference()),
        's.csv': 'scan,tank.Start,fault high_stuck_off\n1,1,1\n3,0,\n',
      },
    );
    expect(r.code).toBe(0);
    const rows = r.out.trim().split('\n');
    expect(rows[0]).toBe('scan,time_ms,HighLevel,tank.level,tank.overflowing');
    expect(rows.at(-1)).toBe('700,69900,0,1000,1');
    expect(r.err).toMatch(/^error tank: the tank overflowed at scan \d+ \(\d+\.\d\d s\)\n$/);
  });

  test('simulate --plant names what does not exist', () => {
    const files = { 'tank.json': JSON.stringify(tankReference()) };
    expect(rungsmith(['simulate', 'tank.json', '--plant', 'boiler'], files).err).toContain(
      '--plant: there is no machine "boiler"; the machines are tank',
    );
    expect(
      rungsmith(['simulate', 'tank.json', '--plant', 'tank', '--watch', 'tank.volume'], files).err,
    ).toContain('--watch: tank has no quantity or point "volume"');
  });

  test('plants lists each machine with its I/O map, faults and quantities', () => {
    const all = rungsmith(['plants']);
    expect(all.code).toBe(0);
    expect(all.out).toMatch(
      /^tank: Tank level control\n {2}I\/O:\n {4}%IX0\.0 {2}Start {7}BOOL {2}operator \(button\) {2}Start push button \(NO\)\n/,
    );
    expect(all.out).toContain(
      '    %IW0    Level       INT   sensor             Level transmitter, litres (0 to 1000)',
    );
    expect(all.out).toContain('    high_stuck_off      High level switch stuck OFF');
    expect(all.out).toContain('    tank.level          REAL  L    Water in the tank');
    expect(rungsmith(['plants', 'tank']).out).toContain('Keep the tank between its level switches');
    expect(rungsmith(['plants', 'boiler']).code).toBe(2);
  });
});
