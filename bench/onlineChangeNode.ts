// The online change of bench:editor (an operand retyped while the program runs at a 10 ms cycle) in
// Node, on the real session and engine the worker runs (src/sim/session.ts), without the page: the
// cycles it misses, and where the scanning thread went longest without running a due scan (the
// stretches between two yield points, with the stack at both ends). For finding causes with
// `node --cpu-prof`; the figures a user sees are bench:editor's.
//   npx tsx bench/onlineChangeNode.ts [bottle|seal] [runs]
//   GAPS=1 also prints the longest stretches and the stacks that ended them.
import { bottleFillerProject } from './bottleFiller';
import { sealInProject } from '../tests/e2e/sealInProject';
import type { Project } from '../src/model/project';
import { realEngine } from '../src/sim/engineAdapter';
import { ScanRunner } from '../src/sim/scanRunner';
import { SimSession } from '../src/sim/session';
import type { Scheduler } from '../src/sim/scheduler';
import type { WorkerMessage } from '../src/sim/protocol';

const which = process.argv[2] ?? 'bottle';
const runs = Number(process.argv[3] ?? 3);
const project: Project = which === 'seal' ? sealInProject(1000) : bottleFillerProject(50);

const scheduler: Scheduler = {
  now: () => performance.now(),
  schedule(fn, ms) {
    if (ms > 0) {
      const h = setTimeout(fn, ms);
      return () => clearTimeout(h);
    }
    const h = setImmediate(fn);
    return () => clearImmediate(h);
  },
};

// Stretches without a poll or tick (the scanning thread busy elsewhere), with the stack that ended them.
interface Gap {
  ms: number;
  cpuMs: number;
  from: string;
  to: string;
}
const gaps: Gap[] = [];
let last = performance.now();
let lastStack = '';
let lastCpu = -1;
const cpuNow = () => {
  const u = process.cpuUsage();
  return (u.user + u.system) / 1000;
};
const proto = ScanRunner.prototype as unknown as { poll(): void; runTick(): void };
const watching = { on: false };
for (const name of ['poll', 'runTick'] as const) {
  const original = proto[name];
  proto[name] = function (this: unknown) {
    const now = performance.now();
    if (watching.on && process.env.GAPS) {
      const stack = new Error().stack!.split('\n').slice(2, 9).join('\n');
      const cpu = cpuNow();
      if (now - last > 8 && lastCpu >= 0) gaps.push({ ms: now - last, cpuMs: cpu - lastCpu, from: lastStack, to: stack });
      lastStack = stack;
      lastCpu = cpu;
    }
    last = now;
    original.call(this);
  };
}

const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));

/** An operand retyped: the first contact of the first PROGRAM reads another BOOL (as bench/onlineChangeFigures.ts does). */
function edited(p: Project): Project {
  const pouIndex = p.pous.findIndex((x) => x.kind === 'PROGRAM');
  const pou = p.pous[pouIndex]!;
  const contacts = pou.networks.flatMap((n) => n.elements).filter((e) => e.kind === 'contact');
  const first = contacts[0] as { id: string; variable: string };
  const other = contacts.find((e) => (e as { variable: string }).variable !== first.variable) as { variable: string };
  const networks = pou.networks.map((n) =>
    n.elements.some((e) => e.id === first.id)
      ? { ...n, elements: n.elements.map((e) => (e.id === first.id ? { ...e, variable: other.variable } : e)) }
      : n,
  );
  const pous = p.pous.map((x, i) => (i === pouIndex ? { ...pou, networks } : x));
  return { ...p, pous };
}

async function main() {
  const results: { late: number; applyMs: number; cpuMs: number }[] = [];
  for (let r = 0; r < runs; r++) {
    let state: { late: number; applied: boolean } = { late: 0, applied: false };
    let seq = 0;
    const session = new SimSession({
      engine: realEngine,
      scheduler,
      post: (m: WorkerMessage) => {
        // As the worker's postMessage does: the message is copied (structured clone) on the sending thread.
        const t0 = performance.now();
        structuredClone(m);
        const ms = performance.now() - t0;
        if (process.env.POSTS && ms > 2) console.log(`post ${m.type} copied in ${ms.toFixed(1)} ms`);
        if (m.type === 'frame') state = { ...state, late: m.frame.exec?.late ?? state.late };
        if (m.type === 'onlineApplied') state.applied = true;
      },
    });
    session.handle({ type: 'setCycle', cycleMs: 10 });
    session.handle({ type: 'run', project, docSeq: ++seq });
    await sleep(1000);
    session.handle({ type: 'setCycle', cycleMs: 10 });
    const before = state.late;
    const t0 = performance.now();
    const cpu0 = cpuNow();
    watching.on = true;
    session.handle({ type: 'load', project: edited(project), docSeq: ++seq });
    while (!state.applied) await sleep(1);
    const applyMs = performance.now() - t0;
    const cpuMs = cpuNow() - cpu0;
    await sleep(1000);
    watching.on = false;
    session.handle({ type: 'pause' });
    results.push({ late: state.late - before, applyMs, cpuMs });
    console.log(`run ${r + 1}: missed ${state.late - before} cycles, applied after ${Math.round(applyMs)} ms, process CPU from the edit to applied ${Math.round(cpuMs)} ms`);
  }
  if (process.env.GAPS) {
    gaps.sort((a, b) => (process.env.BYCPU ? b.cpuMs - a.cpuMs : b.ms - a.ms));
    for (const g of gaps.slice(0, Number(process.env.GAPS) || 8))
      console.log(`---- ${g.ms.toFixed(1)} ms (process CPU ${g.cpuMs.toFixed(1)} ms)\nFROM\n${g.from}\nTO\n${g.to}`);
  }
  const med = [...results].sort((a, b) => a.late - b.late)[Math.floor(results.length / 2)]!;
  console.log(`online-change-node ${which}: missed=${results.map((x) => x.late).join(',')} median=${med.late} cpu-ms=${results.map((x) => Math.round(x.cpuMs)).join(',')}`);
}

main().catch((e: unknown) => {
  console.error(e);
  process.exit(1);
});
