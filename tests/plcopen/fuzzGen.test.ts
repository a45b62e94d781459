// The differential fuzzer's generator (scripts/fuzzGen.ts, docs/fuzz.md): the same seed gives the
// same program, and every program it writes imports, checks clean and simulates in Rungsmith (the
// comparison with the MATIEC reference is scripts/fuzz.ts, outside `npm test`: it needs the oracle).
import { describe, expect, it } from 'vitest';
import { generate } from '../../scripts/fuzzGen';
import { rungsmith } from '../cli/memoryIo';

describe('fuzz program generator', () => {
  it('is deterministic in (seed, index) and varies with them', () => {
    expect(generate(7, 3)).toEqual(generate(7, 3));
    expect(generate(7, 3).xml).not.toBe(generate(7, 4).xml);
    expect(generate(8, 3).xml).not.toBe(generate(7, 3).xml);
  });

  it('covers the kinds of network it promises over a few dozen programs', () => {
    const seen = new Set(Array.from({ length: 60 }, (_, i) => generate(1, i).features).flat());
    for (const f of [
      'logic',
      'TON',
      'CTU',
      'fb-chain',
      'fn-chain',
      'en-open',
      'en-wired',
      'user-fn-st',
      'user-fn-ld',
      'user-fb-st',
      'user-fb-ld',
      'connector-bool',
      'connector-int',
      'CONCAT',
    ])
      expect(seen, f).toContain(f);
  });

  it('writes programs that import, check clean and simulate with every watched variable', () => {
    for (let i = 0; i < 12; i++) {
      const c = generate(3, i);
      const files = { 'case.xml': c.xml, 'stim.csv': c.stim };
      const check = rungsmith(['check', 'case.xml'], files);
      expect(
        check.out.split('\n').filter((l) => /error/.test(l)),
        c.name,
      ).toEqual([]);
      expect(check.code, c.name).toBe(0);
      const sim = rungsmith(
        [
          'simulate',
          'case.xml',
          '--inputs',
          'stim.csv',
          '--scans',
          String(c.scans),
          '--cycle',
          '10ms',
          '--watch',
          c.watch.join(','),
          '--profile',
          'openplc',
        ],
        files,
      );
      expect(sim.code, `${c.name}: ${sim.err}`).toBe(0);
      const lines = sim.out.trim().split('\n');
      expect(lines[0]).toBe(`scan,time_ms,${c.watch.join(',')}`);
      expect(lines).toHaveLength(c.scans + 1);
    }
  });
});
