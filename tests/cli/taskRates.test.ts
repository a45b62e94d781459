// `rungsmith simulate` of a project whose tasks run at 10 ms and 30 ms: a scan is one common tick,
// the slow task's program runs in every third scan, and --cycle cannot change the tick.
import { describe, expect, it } from 'vitest';
import { saveProject } from '../../src/model/load';
import { ratesProject } from '../engine/taskRatesProject';
import { csv, rungsmith } from './memoryIo';

const files = (opts: Parameters<typeof ratesProject>[0] = {}) => ({ 'rates.json': saveProject(ratesProject(opts)) });

describe('rungsmith simulate with tasks at different intervals', () => {
  it('traces one row per 10 ms tick: F every row, S (and its timer) every third', () => {
    const r = rungsmith(['simulate', 'rates.json', '--scans', '7', '--watch', 'F.N,S.N,S.Et,Trace'], files());
    expect(r.code).toBe(0);
    expect(r.err).toBe('one scan = one tick of 10 ms: Fast runs every tick (10 ms); Slow every 3rd tick (30 ms)\n');
    expect(csv(r.out)).toEqual([
      ['scan', 'time_ms', 'F.N', 'S.N', 'S.Et', 'Trace'],
      ['1', '0', '1', '1', '0', '12'],
      ['2', '10', '2', '1', '0', '121'],
      ['3', '20', '3', '1', '0', '1211'],
      ['4', '30', '4', '2', '30', '121112'],
      ['5', '40', '5', '2', '30', '1211121'],
      ['6', '50', '6', '2', '30', '12111211'],
      ['7', '60', '7', '3', '60', '1211121112'],
    ]);
  });

  it('on a tick of the gcd: 20 ms and 30 ms tasks on a 10 ms tick, some ticks run nothing', () => {
    const r = rungsmith(['simulate', 'rates.json', '--scans', '4', '--watch', 'F.N,S.N'], files({ fastMs: 20 }));
    expect(r.code).toBe(0);
    expect(r.out).toBe('scan,time_ms,F.N,S.N\n1,0,1,1\n2,10,1,1\n3,20,2,1\n4,30,2,2\n');
  });

  it('--cycle other than the common tick is refused, naming the tick and the tasks', () => {
    const r = rungsmith(['simulate', 'rates.json', '--cycle', '30ms'], files());
    expect(r.code).not.toBe(0);
    expect(r.err).toMatch(/--cycle 30ms: the tasks run at different intervals \(Fast runs every tick \(10 ms\); Slow every 3rd tick \(30 ms\)\), so a scan is their common tick of 10 ms/);
    const same = rungsmith(['simulate', 'rates.json', '--cycle', '10ms', '--scans', '1', '--watch', 'F.N'], files());
    expect(same.code).toBe(0);
    expect(same.out).toBe('scan,time_ms,F.N\n1,0,1\n');
  });
});
