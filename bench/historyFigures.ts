// Scan history figures for bench:sim (issue 14), measured on the engine in Node as the worker runs it:
// - recording overhead: scan time with every scan recorded vs without, for a 100-network program;
// - seek: time to rebuild any of 100,000 recorded scans as a frame (values + decoded power by layout),
//   i.e. the worker's share of showing a scan from the timeline.
import { compileProgram, createPlc, type CompiledProgram } from '../src/engine/plc';
import type { Project } from '../src/model/project';
import { HistoryRecorder } from '../src/sim/historyRecorder';
import { buildLayout, findPou } from '../src/sim/layout';
import { generateSimProgram } from './simProgram';

function setup(project: Project) {
  const { program } = compileProgram(project);
  if (!program) throw new Error('bench program does not compile');
  const plc = createPlc(program, { cycleMs: 10 });
  const layout = buildLayout(project, plc.pou, plc.variableNames(), 10);
  return { plc, layout, program: program as CompiledProgram, pou: findPou(project, plc.pou)! };
}

/** Scans with inputs changing now and then, as an operator would; returns ms per scan. */
function runScans(project: Project, scans: number, record: boolean): { msPerScan: number; recorder?: HistoryRecorder } {
  const { plc, layout, program, pou } = setup(project);
  const recorder = record ? new HistoryRecorder(plc, layout, program, pou, { maxScans: 100_000 }) : undefined;
  const t0 = performance.now();
  for (let k = 1; k <= scans; k++) {
    if (k % 37 === 0) plc.write(`I${k % 16}`, (k / 37) % 2 === 1);
    plc.scan();
    recorder?.record(k, (k - 1) * 10);
  }
  return { msPerScan: (performance.now() - t0) / scans, ...(recorder ? { recorder } : {}) };
}

export interface HistoryFigures {
  readonly overheadPct: number;
  readonly scanUs: number;
  readonly recordedScanUs: number;
  readonly seekMedianMs: number;
  readonly seekMaxMs: number;
  readonly bytes: number;
  readonly scans: number;
}

export function historyFigures(): HistoryFigures {
  const project = generateSimProgram(100);
  // Warm up the engine's tiering, then take the best of three runs each way.
  runScans(project, 20_000, false);
  runScans(project, 20_000, true);
  const plain = Math.min(...[0, 1, 2].map(() => runScans(project, 20_000, false).msPerScan));
  const recorded = Math.min(...[0, 1, 2].map(() => runScans(project, 20_000, true).msPerScan));
  const { recorder } = runScans(project, 100_000, true);
  const h = recorder!.history;
  const times: number[] = [];
  let seed = 7;
  for (let i = 0; i < 300; i++) {
    seed = (seed * 1103515245 + 12345) >>> 0;
    const scan = h.first! + (seed % h.count);
    const t0 = performance.now();
    const view = recorder!.view(scan);
    times.push(performance.now() - t0);
    if (!view || view.scan !== scan) throw new Error(`seek to scan ${scan} failed`);
  }
  times.sort((a, b) => a - b);
  return {
    overheadPct: ((recorded - plain) / plain) * 100,
    scanUs: plain * 1000,
    recordedScanUs: recorded * 1000,
    seekMedianMs: times[times.length >> 1]!,
    seekMaxMs: times[times.length - 1]!,
    bytes: h.bytes,
    scans: h.count,
  };
}

// Run alone: `npx tsx bench/historyFigures.ts`.
if (process.argv[1]?.endsWith('historyFigures.ts')) {
  const f = historyFigures();
  console.log(JSON.stringify(f));
}
