// npm run test:interop — the corpus files with SFC POUs import, compile and run; the traffic light's chart follows the
// trace MATIEC's generated code gives (computed by hand from the chart and generate_c_sfc.cc).
import { describe, expect, test } from 'vitest';
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { Plc } from '../../src/engine/api';
import type { Project } from '../../src/model/project';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { corpusText } from './corpusDir';

const load = (file: string): Project => {
  const r = importPlcopen(corpusText(file));
  if (!r.ok) throw new Error(`${file} does not import`);
  return r.project;
};

const run = (project: Project, pou: string): Plc => {
  const { program, diagnostics } = compileProgram(project, { pou });
  expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
  const plc = createPlc(program!, { cycleMs: 10 });
  plc.scans(100);
  expect(plc.fault).toBeUndefined();
  return plc;
};

describe('SFC POUs of the corpus', () => {
  test("Aqua: the program general runs its SFC FBs principal and urgence (LD transitions)", () => {
    const plc = run(load('gracesrm__Aqua.xml'), 'general');
    const steps = plc.variableNames().filter((n) => /^principal\d*\.S\d+\.X$/.test(n));
    expect(steps.length).toBeGreaterThan(10);
    expect(steps.filter((n) => plc.read(n) === true)).toHaveLength(1);
  });

  test('Multi_Language: plc_prg runs CounterSFC (ST transitions and actions)', () => {
    const plc = run(load('openplc-editor__Multi_Language.xml'), 'plc_prg');
    const sfc = plc.variableNames().find((n) => /\.Count\.X$/.test(n))!;
    const inst = sfc.split('.')[0]!;
    // Reset is FALSE: Start -> Count at the first cycle, then Cnt := Cnt + 1 and OUT := Cnt each cycle.
    expect(plc.read(`${inst}.OUT`)).toBe(plc.read(`${inst}.Cnt`));
    expect(Number(plc.read(`${inst}.Cnt`))).toBe(100); // Count stays active while Reset is FALSE
  });

  test("first_steps' CounterSFC: Cnt counts each cycle in Count and is reset to the CONSTANT global", () => {
    const project = load('beremiz__first_steps.xml');
    const counter = project.pous.find((p) => p.name === 'CounterSFC')!;
    const main = { ...counter, id: 'main' as typeof counter.id, name: 'Main', kind: 'PROGRAM' as const };
    const plc = createPlc(compileProgram({ ...project, pous: [main, ...project.pous] }, { pou: 'Main' }).program!, { cycleMs: 10 });
    plc.scans(10);
    expect(plc.read('Cnt')).toBe(10);
    plc.write('Reset', true);
    plc.scans(2);
    expect([plc.read('ResetCounter.X'), plc.read('OUT')]).toEqual([true, plc.read('ResetCounterValue')]);
  });
});

describe('traffic light (svghmi_traffic_light), as MATIEC runs it', () => {
  const project = load('beremiz__svghmi_traffic_light.xml');
  const fb = project.pous.find((p) => p.name === 'traffic_light_sequence')!;
  // The FB's chart run as a program of its own (same chart, inputs written directly).
  const main = { ...fb, id: 'tl' as typeof fb.id, name: 'TL', kind: 'PROGRAM' as const };
  const steps = ['Standstill', 'ORANGE', 'RED', 'PEDESTRIAN_GREEN', 'PEDESTRIAN_RED', 'GREEN'];
  const lights = ['RED_LIGHT', 'ORANGE_LIGHT', 'GREEN_LIGHT', 'PEDESTRIAN_RED_LIGHT', 'PEDESTRIAN_GREEN_LIGHT'];
  const state = (plc: Plc) => [
    steps.find((s) => plc.read(`${s}.X`) === true),
    lights.map((l) => (plc.read(l) === true ? 1 : 0)).join(''),
  ];

  test('the cycle ORANGE, RED, PEDESTRIAN_GREEN, PEDESTRIAN_RED, GREEN and back, scan by scan', () => {
    const { program, diagnostics } = compileProgram({ ...project, pous: [main, ...project.pous] }, { pou: 'TL' });
    expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    const plc = createPlc(program!, { cycleMs: 100 });
    const at = (scan: number) => {
      plc.scans(scan - plc.scanCount);
      return state(plc);
    };
    expect(at(1)).toEqual(['Standstill', '00000']);
    plc.write('SWITCH_BUTTON', true);
    // Scan 2 (t = 100 ms): SWITCH_BUTTON fires; ORANGE sets ORANGE_LIGHT and PEDESTRIAN_RED_LIGHT.
    expect(at(2)).toEqual(['ORANGE', '01010']);
    // D T#2s: STOP_CARS once ORANGE.T reaches 2 s (scan 22), the transition fires at the next scan.
    expect(at(22)).toEqual(['ORANGE', '01010']);
    expect(plc.read('STOP_CARS')).toBe(true);
    expect(at(23)).toEqual(['RED', '10010']);
    expect(plc.read('STOP_CARS')).toBe(false); // D: FALSE when its step ends
    expect(at(43)).toEqual(['RED', '10010']);
    expect(at(44)).toEqual(['PEDESTRIAN_GREEN', '10001']);
    expect(at(144)).toEqual(['PEDESTRIAN_GREEN', '10001']); // D T#10s
    expect(at(145)).toEqual(['PEDESTRIAN_RED', '10010']);
    expect(at(166)).toEqual(['GREEN', '00110']);
    // WARN_CARS after 20 s of GREEN (scan 366); the OR block feeding the transition runs in
    // COMPUTE_FUNCTION_BLOCKS after the test, so the transition fires one scan later.
    expect(at(366)).toEqual(['GREEN', '00110']);
    expect(plc.read('WARN_CARS')).toBe(true);
    expect(at(367)).toEqual(['ORANGE', '01010']);
    // Switched off in ORANGE: the FBD transition STOP (a NOT block) is one scan late as well.
    plc.write('SWITCH_BUTTON', false);
    expect(at(368)).toEqual(['ORANGE', '01010']);
    expect(at(369)).toEqual(['Standstill', '01000']);
  });

  test('a pedestrian request ends GREEN 2 s later: SR0 and TON3 in a feedback loop, TON3.Q fed back from the previous call', () => {
    const { program, diagnostics } = compileProgram({ ...project, pous: [main, ...project.pous] }, { pou: 'TL' });
    expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    const plc = createPlc(program!, { cycleMs: 100 });
    const at = (scan: number) => {
      plc.scans(scan - plc.scanCount);
      return state(plc);
    };
    // Scan 1 with the switch off stores COMPUTE_FUNCTION_BLOCKS (SR0, TON3, OR run every scan from then on).
    expect(at(1)).toEqual(['Standstill', '00000']);
    plc.write('SWITCH_BUTTON', true);
    expect(at(166)).toEqual(['GREEN', '00110']);
    // Scan 170 (t = 16.9 s), button pressed for one scan: SR0(S1 := TRUE, R := TON3.Q = FALSE) sets
    // Q1; TON3(IN := SR0.Q1) starts.
    expect(at(169)).toEqual(['GREEN', '00110']);
    plc.write('PEDESTRIAN_BUTTON', true);
    expect(at(170)).toEqual(['GREEN', '00110']);
    expect([plc.read('SR0.Q1'), plc.read('TON3.Q')]).toEqual([true, false]);
    plc.write('PEDESTRIAN_BUTTON', false);
    // Scan 190 (t = 18.9 s): TON3's ET reaches T#2s, Q; SR0 ran first and read TON3.Q of scan 189 (FALSE).
    expect(at(190)).toEqual(['GREEN', '00110']);
    expect([plc.read('SR0.Q1'), plc.read('TON3.Q')]).toEqual([true, true]);
    // Scan 191: the transition reads OR(TON3.Q, WARN_CARS) of scan 190: GREEN -> ORANGE; SR0 is
    // reset by TON3.Q of scan 190, so TON3 stops.
    expect(at(191)).toEqual(['ORANGE', '01010']);
    expect([plc.read('SR0.Q1'), plc.read('TON3.Q')]).toEqual([false, false]);
  });

  test('switched on at the first scan, the chart never stores COMPUTE_FUNCTION_BLOCKS (as in MATIEC)', () => {
    const { program } = compileProgram({ ...project, pous: [main, ...project.pous] }, { pou: 'TL' });
    const plc = createPlc(program!, { cycleMs: 100 });
    plc.write('SWITCH_BUTTON', true);
    plc.scans(166);
    plc.write('PEDESTRIAN_BUTTON', true);
    plc.scans(40);
    // Standstill was left at the first scan, before its S association ran: the blocks wired to the
    // conditions never run, so the pedestrian request is never seen and GREEN waits for WARN_CARS.
    expect(state(plc)[0]).toBe('GREEN');
  });
});
