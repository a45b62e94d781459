// The scan history rebuilds recorded scans by replaying the program: on random programs driven as a
// user and a gateway would (inputs between scans, writes, forces, stepping a scan network by network
// with a write in the middle, a warm restart, a real-time clock), every rebuilt scan's values and
// power flow equal what the live PLC showed after that scan, and change and condition searches give
// what the live values say.
import { describe, expect, it, onTestFinished, vi } from 'vitest';
import type { Plc } from '../../src/engine/api';
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { Value } from '../../src/model/iecTypes';
import type { Network, Project } from '../../src/model/project';
import { HistoryRecorder } from '../../src/sim/historyRecorder';
import type { HistoryOptions } from '../../src/sim/history';
import { buildLayout, findPou } from '../../src/sim/layout';
import { ladder, project, vars } from '../engine/ladder';
import { sfcPou, step, tr } from '../engine/sfcHelpers';
import { io, stProject, textPou } from '../engine/stHelpers';

function rng(seed: number) {
  let s = seed >>> 0;
  return () => {
    s = (s * 1664525 + 1013904223) >>> 0;
    return s / 2 ** 32;
  };
}

const INPUTS = ['A', 'B', 'C', 'D'];
const MEMS = ['X', 'Y', 'Z'];

function randomNetwork(r: () => number, n: number): Network {
  const pick = <T,>(xs: readonly T[]) => xs[Math.floor(r() * xs.length)]!;
  if (n % 4 === 3) {
    // A timer or a counter on a random contact.
    const timer = r() < 0.5;
    const coil = pick(['(X)', '(Y)', '(Z)', '(S:Y)', '(R:X)']);
    return ladder([`[${pick(INPUTS)}] # # ${coil}`, '. # # .', '. # # .'], {
      boxes: [timer ? { row: 0, col: 1, type: 'TON', instance: `T${n}`, inputs: { PT: 'T#45ms' } } : { row: 0, col: 1, type: 'CTU', instance: `T${n}`, inputs: { R: pick(INPUTS), PV: '3' } }],
    });
  }
  const rows = 1 + Math.floor(r() * 2);
  const lines: string[] = [];
  for (let row = 0; row < rows; row++) {
    const tokens = ['+'];
    for (let col = 0; col < 1 + Math.floor(r() * 3); col++) {
      const v = pick([...INPUTS, ...MEMS]);
      tokens.push(pick([`[${v}]`, `[/${v}]`, `[P:${v}]`, `[N:${v}]`]));
    }
    tokens.push('+');
    if (row === 0) tokens.push(pick(['(X)', '(Y)', '(Z)', '(/X)', '(S:Y)', '(R:Y)', '(P:Z)']));
    lines.push(tokens.join(' '));
  }
  return ladder(lines);
}

function randomProgram(seed: number): Project {
  const r = rng(seed);
  const networks = Array.from({ length: 3 + Math.floor(r() * 6) }, (_, n) => randomNetwork(r, n));
  const fbs = networks.flatMap((net) => net.elements.flatMap((e) => (e.kind === 'box' && e.instance ? [`${e.instance} ${e.blockType}`] : [])));
  return project(vars(...INPUTS.map((n, i) => `${n} BOOL %IX0.${i}`), ...MEMS.map((n) => `${n} BOOL`), 'Count INT', ...fbs), networks);
}

/** A program in ST calling a user FB in ST: counters, wrapping arithmetic, a LINT, a loop, a timer. */
function stProgram(): Project {
  const edge = textPou(
    'Edge',
    'FUNCTION_BLOCK',
    [...io('input', 'X BOOL'), ...io('output', 'Rise BOOL'), ...vars('Prev BOOL', 'N INT')],
    'Rise := X AND NOT Prev;\nPrev := X;\nIF Rise THEN N := N + 1; END_IF;',
  );
  const main = textPou(
    'Main',
    'PROGRAM',
    vars('A BOOL %IX0.0', 'B BOOL %IX0.1', 'Level INT %IW1', 'Out BOOL %QX0.0', 'Count INT', 'Acc DINT', 'Big LINT := 1', 'T1 TON', 'F1 Edge', 'i INT', 'Ratio REAL', 'P1 PID', 'Drive REAL'),
    [
      'T1(IN := A, PT := T#35ms);',
      'F1(X := B);',
      'IF T1.Q THEN Count := Count + 1; END_IF;',
      'IF F1.Rise THEN Acc := Acc + Count * Level; ELSE Acc := Acc - 1; END_IF;',
      'Big := Big * 3 + Acc;',
      'FOR i := 0 TO 3 DO Acc := Acc + i; END_FOR;',
      'Ratio := DINT_TO_REAL(Acc) / 7.0;',
      'Out := T1.Q XOR B;',
      // A PID holds inner FBs (its integral and derivative terms).
      'P1(AUTO := A, PV := Ratio, SP := 5.0, KP := 0.5, TR := 2.0, TD := 0.1, CYCLE := T#10ms);',
      'Drive := P1.XOUT;',
    ].join('\n'),
  );
  return stProject([main, edge]);
}

/** A chart with timed steps and timed qualifiers (D, L, SD), step times read by the program. */
function sfcProgram(): Project {
  const main = sfcPou('Main', 'PROGRAM', vars('Go BOOL %IX0.0', 'Stop BOOL %IX0.1', 'Busy BOOL', 'Late BOOL', 'Short BOOL', 'Kept BOOL', 'Cnt INT'), {
    steps: [step('Idle*'), step('Run', 'N Busy', 'D Late T#40ms', 'L Short T#25ms', 'SD Kept T#30ms', 'N Count'), step('Done', 'R Kept')],
    transitions: [tr('Idle', 'Run', 'Go'), tr('Run', 'Done', 'Run.T >= T#70ms OR Stop'), tr('Done', 'Idle', 'NOT Go')],
    actions: [{ name: 'Count', body: { language: 'ST', text: 'Cnt := Cnt + 1;' } }],
  });
  return stProject([main]);
}

interface Live {
  values: Value[];
  power: number[];
}

/**
 * Runs `scans` scans of `p` on a real-time-like clock with random outside changes, recording into a
 * recorder and keeping what the live PLC showed after each scan.
 */
function runLive(p: Project, seed: number, scans: number, opts: HistoryOptions, meddle?: (recorder: HistoryRecorder, scan: number) => void) {
  const { program, diagnostics } = compileProgram(p);
  if (!program) throw new Error(diagnostics.map((d) => d.message).join('\n'));
  const clock = { t: 0, now() { return this.t; } };
  const plc: Plc = createPlc(program, { cycleMs: 10, clock });
  const layout = buildLayout(p, plc.pou, plc.variableNames(), 10);
  const recorder = new HistoryRecorder(plc, layout, program, findPou(p, plc.pou)!, opts);
  const probe = plc.probe!();
  const names = layout.variables.map((v) => v.name);
  const inputs = layout.variables.filter((v) => v.role === 'input');
  const locals = layout.variables.filter((v) => v.role === 'local' && !v.name.includes('.') && v.type === 'BOOL');
  const r = rng(seed);
  const live: Live[] = [];
  /** The output image after each scan and whatever the history did after it: what the gateway would be sent. */
  const posted: Record<string, Value>[] = [];
  const randomValue = (type: string): Value => (type === 'BOOL' ? r() < 0.5 : Math.floor(r() * 20));
  let scan = 0;
  while (scan < scans) {
    const u = r();
    if (u < 0.25 && inputs.length) {
      const v = inputs[Math.floor(r() * inputs.length)]!;
      plc.write(v.name, randomValue(v.type));
    } else if (u < 0.3 && inputs.length) {
      const v = inputs[Math.floor(r() * inputs.length)]!;
      plc.setInputs({ [v.location!]: randomValue(v.type) });
    } else if (u < 0.33 && locals.length) plc.write(locals[Math.floor(r() * locals.length)]!.name, r() < 0.5);
    else if (u < 0.35 && locals.length) plc.force(locals[Math.floor(r() * locals.length)]!.name, r() < 0.5);
    else if (u < 0.37) plc.unforceAll();
    else if (u < 0.375) plc.warmRestart();
    clock.t += 10 + r() * 0.37;
    // Now and then a scan stepped network by network, with a write in the middle of it (an input
    // written there is read at the next scan).
    let done = false;
    if (r() < 0.08) {
      done = plc.stepNetwork().scanDone;
      if (!done && scan > 0) meddle?.(recorder, scan);
      if (!done && r() < 0.5 && locals.length) plc.write(locals[0]!.name, r() < 0.5);
      else if (!done && inputs.length) plc.write(inputs[0]!.name, randomValue(inputs[0]!.type));
    }
    if (!done) {
      const report = plc.scan();
      if (report.fault) throw new Error(report.fault.message);
    }
    expect(plc.scanCount).toBe(scan + 1);
    scan++;
    recorder.record(scan, clock.t);
    const values = names.map((n) => plc.read(n));
    const power = [...probe.power, ...Array.from(probe.ranIn, (s) => (s === plc.scanCount ? 1 : 0))];
    live.push({ values, power });
    meddle?.(recorder, scan);
    posted.push(plc.outputs());
  }
  return { recorder, live, names, posted };
}

function expectReplayEqualsLive(recorder: HistoryRecorder, live: Live[], label: string) {
  const h = recorder.history;
  for (let s = h.first!; s <= h.last!; s++) {
    const state = recorder.seek(s)!;
    expect(state.values, `${label}: values after scan ${s}`).toEqual(live[s - 1]!.values);
    expect([...state.power], `${label}: power of scan ${s}`).toEqual(live[s - 1]!.power);
  }
}

describe('replaying recorded scans', () => {
  it('rebuilds every scan of random ladder programs exactly as it ran', () => {
    let programs = 0;
    for (let seed = 1; seed <= 25; seed++) {
      const p = randomProgram(seed);
      if (!compileProgram(p).program) continue; // a random shape the rules refuse
      programs++;
      const { recorder, live } = runLive(p, seed, 300, { keyEvery: 1 + (seed % 40) });
      expect(recorder.history.count).toBe(300);
      expectReplayEqualsLive(recorder, live, `seed ${seed}`);
    }
    expect(programs).toBeGreaterThanOrEqual(20);
  });

  it('rebuilds every scan of an ST program calling a user FB (timers, a PID, LINT, REAL, loops)', () => {
    const { recorder, live } = runLive(stProgram(), 99, 600, { keyEvery: 64 });
    expectReplayEqualsLive(recorder, live, 'ST');
    // Out of order, as a user drags the timeline.
    for (const s of [600, 1, 333, 332, 64, 65, 129, 7]) expect(recorder.seek(s)!.values).toEqual(live[s - 1]!.values);
  });

  it('rebuilds every scan of an SFC chart (step times, timed qualifiers)', () => {
    const { recorder, live, names } = runLive(sfcProgram(), 21, 500, { keyEvery: 32 });
    expectReplayEqualsLive(recorder, live, 'SFC');
    // The chart really moved: Run (N Busy) became active and left again.
    const run = names.indexOf('Busy');
    expect(live.filter((l) => l.values[run] === true).length).toBeGreaterThan(10);
    expect(live.filter((l) => l.values[run] === false).length).toBeGreaterThan(10);
  });

  it('seeks and searches between live scans (and in the middle of one) leave the live run as it was', () => {
    // Where periodic keys fall depends on measured scan and save times (historyRecorder.ts: a key
    // when the scans since the last one took SAVE_SHARE times what saving takes), so two runs on a
    // busy machine place them differently. With the clock those times are measured on stopped, keys
    // fall every keyEvery scans in both runs, and an extra key can only come from a seek or search
    // the recorder took for an outside change, which is what the segment counts below catch.
    const stopped = vi.spyOn(performance, 'now').mockReturnValue(0);
    onTestFinished(() => stopped.mockRestore());
    for (const [p, seed] of [
      [randomProgram(4), 4],
      [stProgram(), 8],
    ] as const) {
      const plain = runLive(p, seed, 400, { keyEvery: 50 });
      const meddled = runLive(p, seed, 400, { keyEvery: 50 }, (recorder, scan) => {
        if (scan % 7 === 0) recorder.seek(1 + ((scan * 31) % scan));
        if (scan % 29 === 0) recorder.findChange(plain.names[0]!, 1, 1);
        if (scan % 41 === 0) recorder.findCondition(`${plain.names[1]!} AND NOT ${plain.names[0]!}`, scan, -1);
      });
      expect(meddled.live).toEqual(plain.live);
      // Replaying old scans on the live PLC never changes the output image the gateway is sent.
      expect(meddled.posted).toEqual(plain.posted);
      // The ST program drives %QX0.0 ON in some scans, so the comparison above is not of empty images.
      if (seed === 8) expect(plain.posted.some((o) => o['%QX0.0'] === true)).toBe(true);
      expect(plain.recorder.history.segmentCount).toBeGreaterThanOrEqual(400 / 50); // a key at least every keyEvery scans
      expect(meddled.recorder.history.segmentCount).toBe(plain.recorder.history.segmentCount);
      expectReplayEqualsLive(meddled.recorder, meddled.live, `meddled seed ${seed}`);
    }
  });

  it('records only times and changed input images between keys', () => {
    const { recorder } = runLive(stProgram(), 5, 2000, {});
    const h = recorder.history;
    // Outside changes take keys; between them a scan costs its two times (and an input image when it changed).
    expect(h.bytes / h.count).toBeLessThan(400);
  });

  it('finds changes and conditions as the live values say', () => {
    const p = randomProgram(3);
    const { recorder, live, names } = runLive(p, 3, 400, { keyEvery: 16 });
    const liveChanges = (name: string) => {
      const i = names.indexOf(name);
      const out: number[] = [];
      for (let s = 2; s <= live.length; s++) if (live[s - 1]!.values[i] !== live[s - 2]!.values[i]) out.push(s);
      return out;
    };
    for (const name of ['A', 'X', 'Y', 'Z']) {
      const changes = liveChanges(name);
      for (const from of [1, 17, 100, 250, 399]) {
        expect(recorder.findChange(name, from, 1), `${name} after ${from}`).toBe(changes.find((s) => s > from));
        expect(recorder.findChange(name, from, -1), `${name} before ${from}`).toBe([...changes].reverse().find((s) => s < from));
      }
      const at = recorder.scanView(200)!.changedAt!(name);
      expect(at, `${name} last changed`).toBe([...changes].reverse().find((s) => s <= 200));
    }
    const a = names.indexOf('A');
    const x = names.indexOf('X');
    const holds = (s: number) => live[s - 1]!.values[a] === true && live[s - 1]!.values[x] === false;
    const scansHolding = live.map((_, k) => k + 1).filter(holds);
    for (const from of [1, 50, 200, 400]) {
      expect(recorder.findCondition('A AND NOT X', from, 1)).toBe(scansHolding.find((s) => s > from));
      expect(recorder.findCondition('A AND NOT X', from, -1)).toBe([...scansHolding].reverse().find((s) => s < from));
    }
  });

  it('exports a trace of the replayed values', () => {
    const { recorder, live, names } = runLive(stProgram(), 11, 50, { keyEvery: 8 });
    const csv = recorder.traceCsv(['Count', 'Out'], 10, 12).trim().split('\n');
    const at = (s: number, n: string) => live[s - 1]!.values[names.indexOf(n)];
    expect(csv[0]).toBe('scan,time_ms,Count,Out');
    expect(csv.slice(1).map((l) => l.split(',').slice(2).join(','))).toEqual([10, 11, 12].map((s) => `${String(at(s, 'Count'))},${at(s, 'Out') ? 1 : 0}`));
    expect(csv[1]!.split(',')[1]).toBe(String(recorder.history.timeOf(10)));
  });
});
