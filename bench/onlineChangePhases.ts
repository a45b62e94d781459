// The steps of an online change on the worker, timed one by one in Node (min of N runs: on a busy
// machine the minimum is the least disturbed): the fingerprint, the compile, the new PLC, the
// monitoring layout, the pins' data lines. `node --cpu-prof --import tsx bench/onlineChangePhases.ts`
// for where the time goes inside them.
//   npx tsx bench/onlineChangePhases.ts [bottle|seal] [runs]
import { bottleFillerProject } from './bottleFiller';
import { sealInProject } from '../tests/e2e/sealInProject';
import type { Project } from '../src/model/project';
import { realEngine } from '../src/sim/engineAdapter';
import { buildLayout, programFingerprint } from '../src/sim/layout';
import { withPinLines } from '../src/sim/pinValues';
import type { CompiledProgram } from '../src/engine/plc';

const which = process.argv[2] ?? 'bottle';
const runs = Number(process.argv[3] ?? 5);
const project: Project = which === 'seal' ? sealInProject(1000) : bottleFillerProject(50);
const clock = { now: () => 0, set() {} };

const times = new Map<string, number[]>();
const timed = <T>(name: string, f: () => T): T => {
  const t0 = performance.now();
  const r = f();
  const list = times.get(name) ?? [];
  list.push(performance.now() - t0);
  times.set(name, list);
  return r;
};
for (let r = 0; r < runs; r++) {
  timed('fingerprint', () => programFingerprint(project));
  const { program } = timed('compile', () => realEngine.compile(project));
  const plc = timed('createPlc', () => realEngine.createPlc(program!, { cycleMs: 10, clock } as never));
  const layout = timed('layout', () => buildLayout(project, plc.pou, plc.variableNames(), 10, { instances: plc.instances() }));
  timed('pinLines', () => withPinLines(layout, plc, program as CompiledProgram, project));
}
for (const [k, v] of times) console.log(`${k.padEnd(12)} min ${Math.min(...v).toFixed(1)} ms  all ${v.map((x) => x.toFixed(0)).join(' ')}`);
