// bench:engine's ST case: N calls of the Motor FB (userBlocksBench.ts) from ONE ST body against the
// same N calls from N LD networks, both compiled by the engine; outputs compared at the end.
import { newPou, newProject } from '../src/model/factory';
import type { Project } from '../src/model/project';
import { compareMotorPrograms, fbProject } from './userBlocksBench';

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
  const { usA: usLd, usB: usSt, mismatches } = compareMotorPrograms(fbProject(count), stCallsProject(count), count, warmMs);
  const ratio = usSt / usLd;
  console.log(
    `${count.toLocaleString('en-US')} calls of a 3-network FB from one ST body: ${usSt.toFixed(1)} µs/scan; ` +
      `from ${count.toLocaleString('en-US')} LD networks: ${usLd.toFixed(1)} µs/scan; ratio ${ratio.toFixed(2)}; ` +
      `outputs ${mismatches === 0 ? 'agree' : `DIFFER for ${mismatches} motors`}`,
  );
  if (mismatches) process.exitCode = 1;
  return { usSt, usLd, ratio };
}
