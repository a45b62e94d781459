// Recording the scan history as a scenario while the program runs against a machine (issue 26): the
// scenario names the machine, operates its controls and sets its faults as the user did, and does
// not set the inputs the machine drives (its sensors); replayed, it runs as the recorded scans ran.
import { describe, expect, test } from 'vitest';
import { tankReference } from '../../src/plant/exercises';
import { createSimStore } from '../../src/store/simStore';
import { loopback } from './loopback';
import { rungsmith } from '../cli/memoryIo';

function setup() {
  const { transport, scheduler } = loopback();
  const store = createSimStore(transport);
  return { scheduler, s: () => store.getState() };
}

const inputsOf = (s: ReturnType<ReturnType<typeof setup>['s']>) => s.layout!.variables.filter((v) => v.role === 'input').map((v) => v.name);
const outputsOf = (s: ReturnType<ReturnType<typeof setup>['s']>) => s.layout!.variables.filter((v) => v.role === 'output').map((v) => v.name);

describe('a scenario recorded against a machine', () => {
  test('names the machine, has its controls and faults as columns, not its sensors, and replays as it ran', async () => {
    const { s, scheduler } = setup();
    const project = tankReference();
    s().setPlant({ id: 'tank' });
    s().run(project);
    scheduler.advance(300);
    // The operator starts the system; later a valve goes slow, and is repaired.
    s().plantOperator('Start', true);
    scheduler.advance(300);
    s().plantOperator('Start', false);
    scheduler.advance(20_000);
    s().plantFault('inlet_slow', true);
    scheduler.advance(20_000);
    s().plantFault('inlet_slow', false);
    scheduler.advance(10_000);
    s().pause();
    const csv = await s().exportHistory({ format: 'scenario', inputs: inputsOf(s()), outputs: outputsOf(s()) });
    const lines = csv.trim().split('\n');
    expect(lines).toContain('# plant: tank');
    const header = lines.find((l) => l.startsWith('scan,'))!.split(',');
    expect(header).toEqual(expect.arrayContaining(['tank.Start', 'tank.Stop', 'fault inlet_slow', 'expect Pump', 'expect DrainValve']));
    // The machine drives its sensors and controls' inputs: the scenario does not set them.
    for (const sensor of ['LowLevel', 'HighLevel', 'Level', 'Start', 'Stop']) expect(header).not.toContain(sensor);
    // Start pressed at one scan and released at a later one; the fault set and cleared.
    const col = (name: string) => header.indexOf(name);
    const cells = lines.filter((l) => /^\d/.test(l)).map((l) => l.split(','));
    expect(cells.filter((c) => c[col('tank.Start')] === '1')).toHaveLength(1);
    expect(cells.filter((c) => c[col('fault inlet_slow')] === '1')).toHaveLength(1);
    expect(cells.filter((c) => c[col('fault inlet_slow')] === '0').length).toBeGreaterThanOrEqual(1);
    // The tank filled and drained meanwhile: the pump went on and off.
    expect(new Set(cells.map((c) => c[col('expect Pump')]))).toEqual(new Set(['1', '0']));

    const replayed = await s().replayScenario(project, { name: 'Recorded', csv });
    expect(replayed.error).toBeUndefined();
    expect(replayed.divergences).toEqual([]);
    expect(replayed.ok).toBe(true);
    // And as CI runs it: `rungsmith test` with the scenario in the project.
    const ci = rungsmith(['test', 'tank.json'], { 'tank.json': JSON.stringify({ ...project, scenarios: [{ name: 'Recorded', csv }] }) });
    expect(ci.out).toMatch(/PASS\s+Recorded/);
    expect(ci.code).toBe(0);
  });

  test('is refused, with why, when the machine was chosen after the cold start', async () => {
    const { s, scheduler } = setup();
    s().run(tankReference());
    scheduler.advance(500);
    s().setPlant({ id: 'tank' });
    scheduler.advance(500);
    s().pause();
    await expect(s().exportHistory({ format: 'scenario', inputs: inputsOf(s()), outputs: outputsOf(s()) })).rejects.toThrow(
      /machine tank .* record starts later .* Press Reset/,
    );
  });
});
