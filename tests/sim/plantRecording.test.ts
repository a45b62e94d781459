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

/** The tank's reference solution run against the tank, Start pressed on the drawing; `then` runs on before the pause (ms of PLC time). */
function startedTank(then: (s: Sim, advance: (ms: number) => void) => void = () => {}) {
  const { s, scheduler } = setup();
  const project = tankReference();
  s().setPlant({ id: 'tank' });
  s().run(project);
  scheduler.advance(300);
  s().plantOperator('Start', true);
  scheduler.advance(300);
  s().plantOperator('Start', false);
  then(s, (ms) => scheduler.advance(ms));
  s().pause();
  return { s, project };
}
type Sim = ReturnType<typeof setup>['s'];

const inputsOf = (s: ReturnType<Sim>) => s.layout!.variables.filter((v) => v.role === 'input').map((v) => v.name);
const outputsOf = (s: ReturnType<Sim>) => s.layout!.variables.filter((v) => v.role === 'output').map((v) => v.name);

describe('a scenario recorded against a machine', () => {
  test('names the machine, has its controls and faults as columns, not its sensors, and replays as it ran', async () => {
    // The operator starts the system; later a valve goes slow, and is repaired.
    const { s, project } = startedTank((sim, advance) => {
      advance(20_000);
      sim().plantFault('inlet_slow', true);
      advance(20_000);
      sim().plantFault('inlet_slow', false);
      advance(10_000);
    });
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

  test('an exported trace has the machine\'s quantities beside the program\'s variables, scan by scan as rungsmith simulate writes them', async () => {
    const { s, project } = startedTank((_, advance) => advance(30_000));
    const rows = (await s().exportHistory({ format: 'trace' })).trim().split('\n').map((l) => l.split(','));
    const header = rows[0]!;
    expect(header).toEqual(expect.arrayContaining(['Pump', 'Running', 'tank.level', 'tank.inflow', 'tank.overflows']));
    const scans = rows.slice(1);
    expect(scans.length).toBe(s().history!.last);
    // The same columns as the command line's trace of the same run (its Start pressed at the same scans).
    const pressed = scans.findIndex((r) => r[header.indexOf('Start')] === '1') + 1;
    const released = scans.findIndex((r, i) => i >= pressed && r[header.indexOf('Start')] === '0') + 1;
    // At the simulation's cycle (its trace's time step).
    const cycle = Number(scans[1]![header.indexOf('time_ms')]) - Number(scans[0]![header.indexOf('time_ms')]);
    const cli = rungsmith(['simulate', 'tank.json', '--plant', 'tank', '--cycle', `${cycle}ms`, '--scans', String(scans.length), '--watch', 'Pump,tank.level,tank.inflow', '--inputs', 'stim.csv'], {
      'tank.json': JSON.stringify(project),
      'stim.csv': `scan,tank.Start\n${pressed},1\n${released},0\n`,
    });
    expect(cli.err).toBe('');
    const cliRows = cli.out.trim().split('\n').map((l) => l.split(','));
    const at = (row: string[], h: string[], name: string) => row[h.indexOf(name)];
    for (const k of [1, pressed, pressed + 1, 500, 1000, scans.length]) {
      const mine = scans[k - 1]!;
      const theirs = cliRows.find((r) => r[0] === String(k))!;
      for (const name of ['Pump', 'tank.level', 'tank.inflow']) expect(at(mine, header, name), `${name} at scan ${k}`).toBe(at(theirs, cliRows[0]!, name));
    }
    // The tank did fill: its level moved.
    expect(new Set(scans.map((r) => at(r, header, 'tank.level'))).size).toBeGreaterThan(100);
  });

  test('History Find reads the machine\'s names: the first recorded scan where the tank holds more than 500 L', async () => {
    const { s } = startedTank((_, advance) => advance(60_000));
    const trace = (await s().exportHistory({ format: 'trace', names: ['tank.level'] })).trim().split('\n').slice(1).map((l) => l.split(','));
    const expected = trace.findIndex((r) => Number(r[2]) > 500) + 1;
    expect(expected).toBeGreaterThan(1);
    s().seekHistory(1);
    await expect.poll(() => s().historyScan).toBe(1);
    s().findCondition('TANK.LEVEL > 500 AND Pump', 1);
    await expect.poll(() => s().historyScan).toBe(expected);
    expect(s().historyMessage).toBeUndefined();
    // And back: the last scan before it where the tank was still at or under 500 L.
    s().findCondition('tank.level <= 500', -1);
    await expect.poll(() => s().historyScan).toBe(expected - 1);
  });

  test('History Find on a machine name skips the scans before the machine was chosen (nothing of it is recorded there)', async () => {
    const { s, scheduler } = setup();
    s().run(tankReference());
    scheduler.advance(1000);
    s().setPlant({ id: 'tank' });
    const chosenAt = s().scan;
    scheduler.advance(1000);
    s().pause();
    s().seekHistory(1);
    await expect.poll(() => s().historyScan).toBe(1);
    // The tank holds 100 L from its first step: the first scan where it is below 150 L is one it ran in.
    s().findCondition('tank.level < 150', 1);
    await expect.poll(() => s().historyScan).toBeGreaterThan(chosenAt);
    expect(s().historyScan).toBeLessThanOrEqual(chosenAt + 2);
  });
});

