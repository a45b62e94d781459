// The two traces a machine's determinism test compares (issue 26): the worker session's recorded
// scans and `rungsmith simulate --plant`, the same program, stimulus and cycle.
import type { Project } from '../../src/model/project';
import { rungsmith } from '../cli/memoryIo';
import { SimulatedDevice } from '../../src/gateway/simulatedDevice';
import { SimHarness } from '../sim/harness';
import { tankReference } from '../../src/plant/exercises';

/** The session's recorded scans of `names` as the History's Export writes them, one line a scan (header first). */
export function workerTrace(h: SimHarness, names: readonly string[]): string[] {
  h.send({ type: 'historyExport', id: 1, format: 'trace', names: [...names] });
  const texts = h.of('historyText');
  return texts[texts.length - 1]!.text.trim().split('\n');
}

/** `rungsmith simulate FILE --plant ID --inputs stim.csv --scans N --cycle C --watch …` on `project`. */
export function cliTrace(o: {
  project: Project;
  plant: string;
  stimulus: string;
  scans: number;
  cycle: string;
  watch: readonly string[];
}): ReturnType<typeof rungsmith> {
  const file = `${o.plant}.json`;
  return rungsmith(
    [
      'simulate',
      file,
      '--plant',
      o.plant,
      '--inputs',
      'stim.csv',
      '--scans',
      String(o.scans),
      '--cycle',
      o.cycle,
      '--watch',
      o.watch.join(','),
    ],
    { [file]: JSON.stringify(o.project), 'stim.csv': o.stimulus },
  );
}

/** The gateway's simulated device as `npm start -- --plant ID` makes it, started with no gateway listening (no Modbus port). */
export async function startedPlantDevice(plant: string): Promise<SimulatedDevice> {
  const device = new SimulatedDevice(null, plant);
  await device.start({ inputs: () => undefined, written: () => undefined, status: () => undefined } as never);
  return device;
}

/**
 * A simulation session (100 ms cycle) running the tank's reference solution against the tank,
 * Start pressed for two scans, then 300 scans on: at scan 302 the tank has filled from 100 L past
 * its low switch (200 L).
 */
export function tankFilledInSession(): SimHarness {
  const h = new SimHarness().send(
    { type: 'setCycle', cycleMs: 100 },
    { type: 'setPlant', plant: { id: 'tank' } },
    { type: 'load', project: tankReference() },
  );
  h.send({ type: 'plantOperator', name: 'Start', value: true }, { type: 'step', scans: 2 }).settle();
  h.send({ type: 'plantOperator', name: 'Start', value: false }, { type: 'step', scans: 300 });
  while (h.frame.scan < 302) h.settle();
  return h;
}

