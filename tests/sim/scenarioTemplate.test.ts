// A new scenario starts with the program's inputs and outputs as columns and runs as it is.
import { expect, test } from 'vitest';
import { EXAMPLES } from '../../src/model/examples';
import { parseScenario, runScenario } from '../../src/sim/scenario';
import { newScenarioCsv, newScenarioName, scenarioColumns } from '../../src/sim/scenarioTemplate';

const example = (id: string) => EXAMPLES.find((e) => e.id === id)!.build();

test("a new scenario has a column per input and an expect column per output of the program that runs", () => {
  const project = example('motor-start-stop');
  const { inputs, outputs } = scenarioColumns(project);
  expect(inputs.length).toBeGreaterThan(0);
  expect(outputs.length).toBeGreaterThan(0);
  const csv = newScenarioCsv(project);
  const parsed = parseScenario(csv, 'new');
  expect(parsed.columns).toEqual([
    ...inputs.map((name) => ({ name, kind: 'input' })),
    ...outputs.map((name) => ({ name, kind: 'expect' })),
  ]);
  expect(parsed.rows.map((r) => [r.scan, r.cells.size])).toEqual([[1, 0]]);
  // Ready to run: nothing expected yet, so it passes.
  expect(runScenario(project, { name: 'new', csv }).result).toMatchObject({ ok: true, divergences: [] });
});

test('every input and output is a column: the motor example', () => {
  const project = example('motor-start-stop');
  const located = (area: string) =>
    [...project.globals, ...project.pous.flatMap((p) => p.variables)]
      .filter((v) => v.location?.toUpperCase().startsWith(`%${area}`))
      .map((v) => v.name.toUpperCase());
  const { inputs, outputs } = scenarioColumns(project);
  const bare = (names: string[]) => names.map((n) => n.split('.').pop()!.toUpperCase()).sort();
  expect(bare(inputs)).toEqual(located('I').sort());
  expect(bare(outputs)).toEqual(located('Q').sort());
});

test('a new scenario takes the first free name', () => {
  expect(newScenarioName([{ name: 'Scenario 2' }])).toBe('Scenario 3');
  expect(newScenarioName([{ name: 'Scenario 1' }, { name: 'x' }])).toBe('Scenario 3');
  expect(newScenarioName([])).toBe('Scenario 1');
});
