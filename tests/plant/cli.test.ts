// The machines on the command line (issue 26): `rungsmith test` runs the exercise's scenario as CI
// does, `rungsmith simulate --plant` traces the machine, `rungsmith plants` lists the machines.
import { describe, expect, test } from 'vitest';
import type { Project } from '../../src/model/project';
import { boxesReference, boxesWrong } from '../../src/plant/boxesExercise';
import { tankReference, tankWrong } from '../../src/plant/exercises';
import { garageReference, garageWrong } from '../../src/plant/garageExercise';
import { intersectionReference, intersectionWrong } from '../../src/plant/intersectionExercise';
import { liftReference, liftWrong } from '../../src/plant/liftExercise';
import { mixerReference, mixerWrong } from '../../src/plant/mixerExercise';
import { coil, contact, network, rung } from '../../src/model/examples';
import { newPou, newProject } from '../../src/model/factory';
import { plantVariables } from '../../src/plant/exerciseKit';
import { tank } from '../../src/plant/tank';
import { rungsmith } from '../cli/memoryIo';

/** Each machine's exercise as CI runs it: its scenario, the scans it takes, where the wrong solution fails. */
const EXERCISES: {
  id: string;
  reference: () => Project;
  wrong: () => Project;
  scenario: string;
  scans: number;
  failure: string;
}[] = [
  {
    id: 'tank',
    reference: tankReference,
    wrong: tankWrong,
    scenario: 'Tank held between the switches for 5 minutes',
    scans: 3000,
    failure: 'the tank overflowed at scan 576 (57.50 s)',
  },
  {
    id: 'boxes',
    reference: boxesReference,
    wrong: boxesWrong,
    scenario: 'Ten boxes sorted by size',
    scans: 570,
    failure: 'box 2 (large) ran into the small-box bin at scan 122 (12.10 s)',
  },
  {
    id: 'intersection',
    reference: intersectionReference,
    wrong: intersectionWrong,
    scenario: 'Side road and pedestrians served for 5 minutes, no conflict',
    scans: 3000,
    failure: 'conflicting signals: main road yellow with side road green at scan 201 (20.00 s)',
  },
  {
    id: 'garage',
    reference: garageReference,
    wrong: garageWrong,
    scenario: 'Garage door: three cycles on the key, reversing for a car',
    scans: 1200,
    failure: 'the door came down on the car in the doorway at scan 499 (49.80 s)',
  },
  {
    id: 'mixer',
    reference: mixerReference,
    wrong: mixerWrong,
    scenario: 'Three good batches',
    scans: 3600,
    failure: 'a batch overheated above 80 °C and is spoiled at scan 819 (81.80 s)',
  },
  {
    id: 'lift',
    reference: liftReference,
    wrong: liftWrong,
    scenario: 'Six calls answered, level with the floors',
    scans: 5000,
    failure: 'the car moved with the door 100 % open at scan 528 (10.54 s)',
  },
];

describe('rungsmith and the machines', () => {
  test.each(EXERCISES)(
    'test ($id): the reference solution passes its scenario, the wrong one fails where it goes wrong, in the JUnit file too',
    ({ id, reference, wrong, scenario, scans, failure }) => {
      const ok = rungsmith(['test', `${id}.json`], { [`${id}.json`]: JSON.stringify(reference()) });
      expect(ok.code).toBe(0);
      expect(ok.out).toContain(`PASS ${scenario} (${scans} scans)`);
      const bad = rungsmith(['test', `${id}.json`, '--junit', 'out.xml'], {
        [`${id}.json`]: JSON.stringify(wrong()),
      });
      expect(bad.code).toBe(1);
      expect(bad.out).toContain(`FAIL ${scenario}: ${failure}`);
      expect(bad.files.get('out.xml')).toContain(`failure message="${failure}"`);
    },
  );

  test('simulate --plant: the machine in the trace, its faults and controls as stimulus columns, consequences on stderr', () => {
    const r = rungsmith(
      [
        'simulate',
        'tank.json',
        '--plant',
        'tank',
        '--inputs',
        's.csv',
        '--scans',
        '700',
        '--cycle',
        '100ms',
        '--watch',
        'HighLevel,tank.level,tank.overflowing',
      ],
      {
        'tank.json': JSON.stringify(tankReference()),
        's.csv': 'scan,tank.Start,fault high_stuck_off\n1,1,1\n3,0,\n',
      },
    );
    expect(r.code).toBe(0);
    const rows = r.out.trim().split('\n');
    expect(rows[0]).toBe('scan,time_ms,HighLevel,tank.level,tank.overflowing');
    expect(rows.at(-1)).toBe('700,69900,0,1000,1');
    expect(r.err).toMatch(/^error tank: the tank overflowed at scan \d+ \(\d+\.\d\d s\)\n$/);
  });

  test('simulate --plant writes the machine REAL quantities as REALs: 60, not 60.00000000000001', () => {
    const r = rungsmith(
      ['simulate', 'tank.json', '--plant', 'tank', '--inputs', 's.csv', '--scans', '12', '--cycle', '100ms', '--watch', 'tank.pump,tank.inlet,tank.inflow'],
      { 'tank.json': JSON.stringify(tankReference()), 's.csv': 'scan,tank.Start\n1,1\n3,0\n' },
    );
    expect(r.code).toBe(0);
    const rows = r.out.trim().split('\n');
    // The pump ramps up 20 % per 100 ms scan, the inlet valve 10 %: round figures, as a REAL holds them.
    expect(rows.slice(1, 6).map((row) => row.split(',').slice(2, 4).join(','))).toEqual(['20,10', '40,20', '60,30', '80,40', '100,50']);
    for (const row of rows.slice(1)) for (const cell of row.split(',').slice(2)) expect(cell.replace(/^-|\./g, '').length).toBeLessThanOrEqual(9);
  });

  test('simulate --plant names what does not exist', () => {
    const files = { 'tank.json': JSON.stringify(tankReference()) };
    expect(rungsmith(['simulate', 'tank.json', '--plant', 'boiler'], files).err).toContain(
      '--plant: there is no machine "boiler"; the machines are tank',
    );
    expect(
      rungsmith(['simulate', 'tank.json', '--plant', 'tank', '--watch', 'tank.volume'], files).err,
    ).toContain('--watch: tank has no quantity or point "volume"');
  });

  test('simulate --plant refuses a stimulus column that sets the machine\'s state, or a fault it lacks, before the first scan', () => {
    const files = { 'tank.json': JSON.stringify(tankReference()) };
    const run = (header: string, row: string) =>
      rungsmith(['simulate', 'tank.json', '--plant', 'tank', '--inputs', 's.csv', '--watch', 'tank.level'], {
        ...files,
        's.csv': `scan,${header}\n1,1\n2000,${row}\n`,
      });
    // A quantity or a sensor cannot be set: the machine works them out (was "500 is an integer, not a BOOL").
    const level = run('tank.level', '500');
    expect(level.code).toBe(2);
    expect(level.out).toBe('');
    expect(level.err).toBe(
      'rungsmith: s.csv: column "tank.level": only the machine\'s operator controls can be set (tank.Start, tank.Stop); watch its state with --watch tank.level\n',
    );
    expect(run('tank.LowLevel', '0').err).toContain('column "tank.LowLevel": only the machine\'s operator controls can be set');
    expect(run('tank.Nope', '0').err).toBe('rungsmith: s.csv: column "tank.Nope": tank has no operator control "Nope"; it has Start, Stop\n');
    expect(run('fault pump_daed', '0').err).toBe(
      'rungsmith: s.csv: column "fault pump_daed": tank has no fault "pump_daed"; it has low_stuck_off, low_stuck_on, high_stuck_off, high_stuck_on, pump_dead, inlet_slow, drain_stuck\n',
    );
  });

  test("a machine's name, fault or control without its machine says what to add (--plant / # plant:), not only that the variable is undeclared", () => {
    const files = { 'tank.json': JSON.stringify(tankReference()) };
    const watch = rungsmith(['simulate', 'tank.json', '--scans', '3', '--watch', 'Pump,tank.level'], files);
    expect(watch.code).toBe(2);
    expect(watch.err).toBe(
      'rungsmith: unknown variable "tank.level": "tank" is not declared; tank.level is the machine tank\'s: add --plant tank\n',
    );
    expect(rungsmith(['simulate', 'tank.json', '--plant', 'mixer', '--scans', '3', '--watch', 'tank.level'], files).err).toContain(
      'tank.level is the machine tank\'s, and this runs mixer',
    );
    // Was: "fault pump_dead" is a constant, not a variable.
    const fault = rungsmith(['simulate', 'tank.json', '--inputs', 's.csv'], { ...files, 's.csv': 'scan,fault pump_dead\n1,1\n' });
    expect(fault.code).toBe(2);
    expect(fault.err).toBe(
      'rungsmith: s.csv: column "fault pump_dead": "fault pump_dead" sets a machine\'s fault: run the program with its machine (--plant NAME)\n',
    );
    const project = { ...tankReference(), scenarios: [{ name: 'No machine', csv: 'scan,tank.Start,expect tank.level\n1,1,100\n' }] };
    const test = rungsmith(['test', 'tank.json'], { 'tank.json': JSON.stringify(project) });
    expect(test.code).toBe(1);
    expect(test.out).toContain(
      'FAIL No machine: line 1: unknown variable "tank.Start": "tank" is not declared; tank.Start is the machine tank\'s: add "# plant: tank" before the header',
    );
  });

  test('"# plant:" naming no machine, or a second one, fails the scenario at its line (it was ignored, or the last one won)', () => {
    const run = (csv: string) =>
      rungsmith(['test', 'tank.json'], { 'tank.json': JSON.stringify({ ...tankReference(), scenarios: [{ name: 'S', csv }] }) });
    const empty = run('# plant:\nscan,expect Pump\n1,0\n');
    expect(empty.code).toBe(1);
    expect(empty.out).toContain('FAIL S: line 1: there is no machine ""; the machines are tank, lift, garage, mixer, boxes, intersection');
    const two = run('# plant: tank\n# plant: mixer\nscan,tank.Start\n1,1\n');
    expect(two.code).toBe(1);
    expect(two.out).toContain('FAIL S: line 2: a scenario runs against one machine: line 1 already names tank, this line mixer');
    expect(run('# plant: tank\n# plant: Tank\nscan,tank.Start,expect tank.level ~ 1\n1,1,100\n').code).toBe(0);
  });

  test("a project's I/O map naming no point of the machine (a typo) is warned about on stderr by test and simulate, not silently ignored", () => {
    const project = { ...tankReference(), plant: { id: 'tank', map: { Pmp: '%QX0.5' } } };
    const warning =
      'warning tank: the project\'s I/O map names "Pmp", not a point of the machine (Start, Stop, LowLevel, HighLevel, Level, Pump, InletValve, DrainValve, RunLamp): it changes nothing\n';
    const test = rungsmith(['test', 'tank.json'], { 'tank.json': JSON.stringify(project) });
    expect(test.code).toBe(0);
    expect(test.err).toBe(warning);
    const sim = rungsmith(['simulate', 'tank.json', '--plant', 'tank', '--scans', '1', '--watch', 'Pump'], { 'tank.json': JSON.stringify(project) });
    expect(sim.code).toBe(0);
    expect(sim.err).toBe(warning);
    expect(rungsmith(['test', 'tank.json'], { 'tank.json': JSON.stringify(tankReference()) }).err).toBe('');
  });

  test("the machine's warnings (they fail nothing) are listed under the scenario's PASS or FAIL", () => {
    // Start runs the pump, and nothing opens the inlet valve: the pump runs against it (a warning).
    const main = newPou('Main', {
      variables: plantVariables(tank),
      networks: [network('Pump', 'The pump runs on Start.', rung([contact(0, 0, 'Start')], coil(0, 'Pump')), { rows: 1 })],
    });
    const project = newProject('Deadhead', {
      scenarios: [{ name: 'Pump on Start', csv: '# plant: tank\n# cycle: 100ms\nscan,tank.Start,expect Pump\n1,1,1\n60,,1\n' }],
      plant: { id: 'tank' },
      pous: [main],
      tasks: [{ name: 'MainTask', cycleMs: 100, priority: 1, programs: [{ instance: 'MainInstance', pou: 'Main' }] }],
    });
    const r = rungsmith(['test', 'p.json'], { 'p.json': JSON.stringify(project) });
    expect(r.code).toBe(0);
    expect(r.out).toMatch(
      /^PASS Pump on Start \(60 scans\)\n {2}warning: the pump ran 3 s against the closed inlet valve at scan \d+ \(\d+\.\d\d s\)\n1 passed, 0 failed/,
    );
  });

  test('plants lists each machine with its I/O map, faults and quantities', () => {
    const all = rungsmith(['plants']);
    expect(all.code).toBe(0);
    expect(all.out).toMatch(
      /^tank: Tank level control\n {2}I\/O:\n {4}%IX0\.0 {2}Start {7}BOOL {2}operator \(button\) {2}Start push button \(NO\)\n/,
    );
    expect(all.out).toContain(
      '    %IW0    Level       INT   sensor             Level transmitter, litres (0 to 1000)',
    );
    expect(all.out).toContain('    high_stuck_off      High level switch stuck OFF');
    expect(all.out).toContain('    tank.level          REAL  L    Water in the tank');
    expect(rungsmith(['plants', 'tank']).out).toContain('Keep the tank between its level switches');
    expect(rungsmith(['plants', 'boiler']).code).toBe(2);
  });
});
