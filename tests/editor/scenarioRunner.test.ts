// The Tests panel's batch run (runScenariosOffPage): results in the scenarios' order, each from a
// cold restart, a scenario that cannot run failing with its reason while the others still run.
// In the browser it runs in its own worker (tests/e2e/testsRunAll.e2e.test.ts); Node has no Worker,
// so here the same batch runs in place.
import { expect, test } from 'vitest';
import { runScenariosOffPage } from '../../src/editor/scenarios/scenarioRunner';
import { EXAMPLES } from '../../src/model/examples';

const motor = EXAMPLES.find((e) => e.id === 'motor-start-stop')!.build();
const own = motor.scenarios![0]!;

test('each scenario runs from a cold restart, in order; a broken one fails with its reason and the next still runs', async () => {
  const wrong = { name: 'Motor off after Start', csv: 'scan,Start,Stop,expect Motor\n1,0,0,0\n2,1,0,0\n' };
  const broken = { name: 'Unknown column', csv: 'scan,Pump,expect Motor\n1,1,0\n' };
  const results = await runScenariosOffPage(motor, [own, wrong, broken, own]);
  expect(results.map((r) => [r.name, r.ok])).toEqual([
    [own.name, true],
    ['Motor off after Start', false],
    ['Unknown column', false],
    [own.name, true],
  ]);
  expect(results[1]!.divergences).toEqual([{ scan: 2, line: 3, name: 'Motor', expected: '0', actual: '1' }]);
  expect(results[2]!.error).toMatch(/unknown variable "Pump"/);
});
