// Scan history figures for bench:sim (issue 14), measured on the engine in Node as the worker runs it:
// - recording overhead: scan time with every scan recorded vs without, for a 100-network program
//   (blocks of scans with and without recording alternate on one warmed-up PLC, the best block of
//   each counts, so a busy machine disturbs both alike);
// - seek: time to rebuild any of 100,000 recorded scans as a frame (values + decoded power by
//   layout), i.e. the worker's share of showing a scan from the timeline, the first one included
//   (it makes the replaying PLC);
// - searches that replay the whole range: the next change of a variable that never changes (first
//   time, then again), a condition that never holds (forwards and backwards).
import { compileProgram, createPlc, type CompiledProgram } from '../src/engine/plc';
import type { Plc } from '../src/engine/api';
import type { Project } from '../src/model/project';
import { HistoryRecorder } from '../src/sim/historyRecorder';
import { buildLayout, findPou } from '../src/sim/layout';
import { generateSimProgram } from './simProgram';

const BLOCK = 4000;
const ROUNDS = 12;

function setup(project: Project) {
  const { program } = compileProgram(project);
  if (!program) throw new Error('bench program does not compile');
  const plc = createPlc(program, { cycleMs: 10 });
  const layout = buildLayout(project, plc.pou, plc.variableNames(), 10);
  const recorder = new HistoryRecorder(plc, layout, program as CompiledProgram, findPou(project, plc.pou)!, { maxScans: 100_000 });
  return { plc, recorder };
}

/** Scans with inputs changing now and then, as an operator would; returns ms per scan. */
function runScans(plc: Plc, recorder: HistoryRecorder | undefined, scans: number): number {
  const t0 = performance.now();
  for (let i = 0; i < scans; i++) {
    const k = plc.scanCount + 1;
    if (k % 37 === 0) plc.write(`I${k % 16}`, (k / 37) % 2 === 1);
    plc.scan();
    recorder?.record(k, (k - 1) * 10);
  }
  return (performance.now() - t0) / scans;
}

export interface HistoryFigures {
  readonly overheadPct: number;
  readonly scanUs: number;
  readonly recordedScanUs: number;
  readonly firstSeekMs: number;
  readonly seekMedianMs: number;
  readonly seekP99Ms: number;
  readonly seekMaxMs: number;
  readonly bytes: number;
  readonly scans: number;
  /** Next change of a variable that never changes, over the whole range: first time, and asked again. */
  readonly changeSearchMs: number;
  readonly changeSearchAgainMs: number;
  /** A condition that never holds, over the whole range: forwards, backwards. */
  readonly conditionSearchMs: number;
  readonly conditionBackMs: number;
}

const timed = <T,>(fn: () => T): [T, number] => {
  const t0 = performance.now();
  const result = fn();
  return [result, performance.now() - t0];
};

export function historyFigures(networks = 100): HistoryFigures {
  const project = generateSimProgram(networks);
  // Overhead: one PLC warmed up (the engine's tiering, the JIT), then alternating blocks.
  const bench = setup(project);
  runScans(bench.plc, bench.recorder, 40_000);
  let plain = Infinity;
  let recorded = Infinity;
  for (let round = 0; round < ROUNDS; round++) {
    plain = Math.min(plain, runScans(bench.plc, undefined, BLOCK));
    recorded = Math.min(recorded, runScans(bench.plc, bench.recorder, BLOCK));
  }

  // 100,000 recorded scans on a fresh PLC, then seeks and searches as the timeline asks for them.
  const { plc, recorder } = setup(project);
  runScans(plc, recorder, 100_000);
  const h = recorder.history;
  const times: number[] = [];
  let seed = 7;
  for (let i = 0; i < 300; i++) {
    seed = (seed * 1103515245 + 12345) >>> 0;
    const scan = h.first! + (seed % h.count);
    const [view, ms] = timed(() => recorder.view(scan));
    times.push(ms);
    if (!view || view.scan !== scan) throw new Error(`seek to scan ${scan} failed`);
  }
  const firstSeekMs = times[0]!;
  times.sort((a, b) => a - b);
  // An output the bench run never turns on (checked): the search replays every scan.
  const quiet = 'Q15';
  const [c1, changeSearchMs] = timed(() => recorder.findChange(quiet, h.first!, 1));
  const [c2, changeSearchAgainMs] = timed(() => recorder.findChange(quiet, h.first!, 1));
  if (c1 !== undefined || c2 !== undefined) throw new Error(`${quiet} changes in the bench run; pick a variable that does not`);
  const never = 'I0 AND I1 AND I2 AND I3 AND I4 AND I5 AND I6 AND I7 AND I8 AND I9 AND I10 AND I11';
  const [f1, conditionSearchMs] = timed(() => recorder.findCondition(never, h.first!, 1));
  const [f2, conditionBackMs] = timed(() => recorder.findCondition(never, h.last!, -1));
  if (f1 !== undefined || f2 !== undefined) throw new Error('the never-holding condition holds in the bench run');
  return {
    overheadPct: ((recorded - plain) / plain) * 100,
    scanUs: plain * 1000,
    recordedScanUs: recorded * 1000,
    firstSeekMs,
    seekMedianMs: times[times.length >> 1]!,
    seekP99Ms: times[Math.floor(times.length * 0.99)]!,
    seekMaxMs: times[times.length - 1]!,
    bytes: h.bytes,
    scans: h.count,
    changeSearchMs,
    changeSearchAgainMs,
    conditionSearchMs,
    conditionBackMs,
  };
}

/** The figures as one line of words (bench:sim prints it). */
export function describeHistoryFigures(f: HistoryFigures, networks = 100): string {
  return (
    `Scan history, ${networks.toLocaleString('en-US')} networks: ${f.scanUs.toFixed(2)} µs per scan, ${f.recordedScanUs.toFixed(2)} µs recorded (${f.overheadPct >= 0 ? '+' : ''}${f.overheadPct.toFixed(0)} %, budget 20 %); ` +
    `${f.scans.toLocaleString('en-US')} scans in ${(f.bytes / 1048576).toFixed(1)} MB; ` +
    `seek to a random scan median ${f.seekMedianMs.toFixed(2)} ms, p99 ${f.seekP99Ms.toFixed(2)} ms, max ${f.seekMaxMs.toFixed(2)} ms, the first ${f.firstSeekMs.toFixed(2)} ms (budget 50 ms); ` +
    `replaying all of them to find a change ${f.changeSearchMs.toFixed(0)} ms (again ${f.changeSearchAgainMs.toFixed(1)} ms), a condition ${f.conditionSearchMs.toFixed(0)} ms forwards, ${f.conditionBackMs.toFixed(0)} ms backwards`
  );
}

// Run alone: `npx tsx bench/historyFigures.ts [networks]` (default 100).
if (process.argv[1]?.endsWith('historyFigures.ts')) {
  const networks = Number(process.argv[2] ?? 100);
  const f = historyFigures(networks);
  console.log(describeHistoryFigures(f, networks));
  console.log(JSON.stringify(f));
}
