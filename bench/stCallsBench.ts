// bench:engine's ST case: N calls of the Motor FB (userBlocksBench.ts) from ONE ST body against the
// same N calls from N LD networks, both compiled by the engine; outputs compared at the end.
import { compileProgram, createPlc } from '../src/engine/plc';
import { newPou, newProject } from '../src/model/factory';
import type { Project } from '../src/model/project';
import { fbProject } from './userBlocksBench';

/** The LD project's Main rewritten as one ST body: `M0(Start := Tick, Stop := Stop, Fault := Fault, Out => Out0);` per motor. */
export function stCallsProject(count: number): Project {
  const ld = fbProject(count);
  const [main, motor] = ld.pous;
  const lines = Array.from({ length: count }, (_, k) => `M${k}(Start := Tick, Stop := Stop, Fault := Fault, Out => Out${k});`);
  const st = newPou('Main', { variables: main!.variables, networks: [], language: 'ST', source: lines.join('\n') });
  return newProject('StCalls', { pous: [st, motor!] });
}

/** µs per scan of both, best of five rounds after `warmMs` of alternating warm-up. */
export function measureStCalls(count: number, warmMs: number): { usSt: number; usLd: number; ratio: number } {
  const make = (p: Project) => {
    const { program, diagnostics } = compileProgram(p);
    if (!program) throw new Error(`bench program does not compile: ${diagnostics[0]?.message}`);
    return createPlc(program, { cycleMs: 10, maxScanMs: 60_000 });
  };
  const ld = make(fbProject(count));
  const st = make(stCallsProject(count));
  let k = 0;
  const run = (plc: ReturnType<typeof make>, scans: number, from: number): number => {
    const t = performance.now();
    for (let s = 0; s < scans; s++) {
      plc.write('Tick', ((from + s) >> 3) % 2 === 0);
      plc.scan();
    }
    return (performance.now() - t) / scans;
  };
  const scans = Math.max(200, Math.round(400_000 / count));
  const started = performance.now();
  while (performance.now() - started < warmMs) {
    run(ld, scans, k);
    run(st, scans, k);
    k += scans;
  }
  let bestLd = Infinity;
  let bestSt = Infinity;
  for (let round = 0; round < 5; round++) {
    bestLd = Math.min(bestLd, run(ld, scans, k));
    bestSt = Math.min(bestSt, run(st, scans, k));
    k += scans;
  }
  let mismatches = 0;
  for (let m = 0; m < count; m++) if (ld.read(`Out${m}`) !== st.read(`Out${m}`)) mismatches++;
  const ratio = bestSt / bestLd;
  console.log(
    `${count.toLocaleString('en-US')} calls of a 3-network FB from one ST body: ${(bestSt * 1000).toFixed(1)} µs/scan; ` +
      `from ${count.toLocaleString('en-US')} LD networks: ${(bestLd * 1000).toFixed(1)} µs/scan; ratio ${ratio.toFixed(2)}; ` +
      `outputs ${mismatches === 0 ? 'agree' : `DIFFER for ${mismatches} motors`}`,
  );
  if (mismatches) process.exitCode = 1;
  return { usSt: bestSt * 1000, usLd: bestLd * 1000, ratio };
}
