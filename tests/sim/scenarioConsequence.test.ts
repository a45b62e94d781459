// A scenario that fails on a machine's consequence names the quantity counting it, what the Tests
// tab's "Why it failed" explains at that scan (issue 26).
import { expect, test } from 'vitest';
import { runScenario } from '../../src/sim/scenario';
import { tankReference, tankWrong } from '../../src/plant/tankExercise';

const csv = '# plant: tank\n# cycle: 100ms\nscan,tank.Start,expect Running\n1,1,\n3,0,1\n3000,,1\n';

test("a run failed on the tank's overflow names tank.overflows; a divergence or a pass names none", () => {
  const failed = runScenario(tankWrong(), { name: 'no overflow', csv }).result;
  expect(failed).toMatchObject({ ok: false, consequence: 'tank.overflows' });
  expect(failed.error).toMatch(
    new RegExp(`^the tank overflowed at scan ${failed.scans.toLocaleString('en-US')} \\(`),
  );
  expect(runScenario(tankReference(), { name: 'holds', csv }).result.consequence).toBeUndefined();
  const diverged = runScenario(tankReference(), {
    name: 'wrong expectation',
    csv: csv.replace('3,0,1', '3,0,0'),
  }).result;
  expect(diverged).toMatchObject({ ok: false, scans: 3 });
  expect(diverged.consequence).toBeUndefined();
});
