// Determinism with faults and operator actions (issue 26): for every machine, an operator working
// its controls and faults set and cleared mid-run give, in the worker's session (what the browser
// records and exports) and in `rungsmith simulate --plant`, the same trace scan by scan, at the
// exercise's cycle and at an odd one.
import { describe, expect, test } from 'vitest';
import { requirePlant } from '../../src/plant/machines';
import { SimHarness } from '../sim/harness';
import { cliTrace, workerTrace } from './traces';
import { actionStimulus, MACHINES } from './operatorRuns';

const SCANS = 2000;

describe.each([
  ['its exercise cycle', undefined],
  ['a 37 ms cycle', 37],
] as const)('at %s', (_what, odd) => {
  test.each(MACHINES)('$id: operator actions and faults give the same trace in the worker and the CLI', ({ id, project, cycleMs, actions }) => {
    const cycle = odd ?? cycleMs;
    const model = requirePlant(id);
    const names = model.points.map((p) => p.name);
    const h = new SimHarness().send({ type: 'setCycle', cycleMs: cycle }, { type: 'setPlant', plant: { id } }, { type: 'load', project: project() });
    let done = 0;
    for (const [scan, kind, name, on] of actions) {
      if (scan - 1 > done) {
        h.send({ type: 'step', scans: scan - 1 - done });
        while (h.frame.scan < scan - 1) h.settle();
        done = scan - 1;
      }
      h.send(kind === 'op' ? { type: 'plantOperator', name, value: on } : { type: 'plantFault', id: name, active: on });
    }
    h.send({ type: 'step', scans: SCANS - done });
    while (h.frame.scan < SCANS) h.settle();
    const worker = workerTrace(h, names);

    const cli = cliTrace({ project: project(), plant: id, stimulus: actionStimulus(id, actions), scans: SCANS, cycle: `${cycle}ms`, watch: names });
    expect(cli.code).toBe(0);
    const rows = cli.out.trim().split('\n');
    expect(rows).toHaveLength(SCANS + 1);
    expect(rows).toEqual(worker);
    // The faults acted: without them the same operator actions give another trace.
    const noFaults = cliTrace({ project: project(), plant: id, stimulus: actionStimulus(id, actions, 'op'), scans: SCANS, cycle: `${cycle}ms`, watch: names });
    expect(noFaults.code).toBe(0);
    expect(noFaults.out.trim().split('\n')).not.toEqual(rows);
  });
});
