// A new scenario in a project with a machine (issue 26) runs against the machine: its operator
// controls are columns, the inputs the machine writes are not, and it runs as it is.
import { expect, test } from 'vitest';
import { tankReference } from '../../src/plant/tankExercise';
import { parseScenario, runScenario } from '../../src/sim/scenario';
import { newScenarioCsv } from '../../src/sim/scenarioTemplate';

test("the tank exercise's new scenario: # plant: tank, tank.Start and tank.Stop to operate, the outputs to expect, no sensor column", () => {
  const project = tankReference();
  const csv = newScenarioCsv(project);
  const parsed = parseScenario(csv, 'new');
  expect(parsed.plant).toBe('tank');
  expect(csv.split('\n').find((l) => l.startsWith('scan,'))).toBe(
    'scan,tank.Start,tank.Stop,expect Pump,expect InletValve,expect DrainValve,expect RunLamp',
  );
  expect(runScenario(project, { name: 'new', csv }).result).toMatchObject({ ok: true, divergences: [] });
  // Filled in as its comment says: Start pressed at scan 1, let go at 3; the pump runs (below the low switch).
  const filled = csv.replace(/\n1,.*\n$/, '\n1,1,,*,*,*,*\n3,0,,1,1,0,1\n');
  expect(runScenario(project, { name: 'filled', csv: filled }).result).toMatchObject({ ok: true, scans: 3 });
});

test("a point rewired in the project's map: the variable at the machine's new address is the machine's, a program input elsewhere stays a column", () => {
  const project = tankReference();
  const main = project.pous[0]!;
  const withOwn = {
    ...project,
    plant: { id: 'tank', map: { Stop: '%IX1.0' } },
    pous: [
      {
        ...main,
        variables: [
          ...main.variables.map((v) => (v.name === 'Stop' ? { ...v, location: '%IX1.0' } : v)),
          {
            name: 'Jog',
            type: 'BOOL',
            varClass: 'local' as const,
            retain: false,
            comment: '',
            location: '%IX2.0',
          },
        ],
      },
    ],
  };
  const header = newScenarioCsv(withOwn)
    .split('\n')
    .find((l) => l.startsWith('scan,'));
  expect(header).toBe(
    'scan,tank.Start,tank.Stop,Jog,expect Pump,expect InletValve,expect DrainValve,expect RunLamp',
  );
});
