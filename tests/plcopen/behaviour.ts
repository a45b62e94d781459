// Behaviour of a program over many scans, to compare a project with its PLCopen round trip.
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { Value } from '../../src/model/iecTypes';
import { blockLibrary } from '../../src/model/library';
import type { Project } from '../../src/model/project';
import { gridGraph } from '../../src/plcopen/gridGraph';

/** Variables a test may drive: %I inputs and BOOLs no element writes. */
function drivable(project: Project, pou: string): string[] {
  const p = project.pous.find((x) => x.name === pou)!;
  const written = new Set<string>();
  for (const n of p.networks)
    for (const e of n.elements) {
      if (e.kind === 'coil') written.add(e.variable.toUpperCase());
      if (e.kind === 'box') for (const o of Object.values(e.outputs)) written.add(o.toUpperCase());
    }
  return p.variables
    .filter((v) => v.type === 'BOOL' && (v.location?.startsWith('%I') || !written.has(v.name.toUpperCase())))
    .map((v) => v.name);
}

/** One line per scan with every readable value, driving inputs with a fixed pseudo-random pattern. */
export function trace(project: Project, pou: string, scans = 60): string[] {
  const { program, diagnostics } = compileProgram(project, { pou });
  if (!program) throw new Error(`${pou} does not compile: ${diagnostics.map((d) => d.message).join('; ')}`);
  const plc = createPlc(program, { cycleMs: 100 });
  const inputs = drivable(project, pou);
  let seed = 12345;
  const rnd = () => (seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648;
  const names = plc.variableNames();
  const out: string[] = [];
  for (let k = 0; k < scans; k++) {
    for (const i of inputs) if (rnd() < 0.3) plc.write(i, rnd() < 0.5);
    plc.scan();
    out.push(names.map((n) => `${n}=${String(plc.read(n) as Value)}`).join(' '));
  }
  return out;
}

/** "Main coil:SET:Motor.in <- contact:NO:Start.out" for every wire of every network (multiset, sorted).
 * Network numbers are left out: an import splits a network holding independent rungs in two. */
export function connections(project: Project): string[] {
  const out: string[] = [];
  for (const pou of project.pous)
    pou.networks.forEach((net) => {
      const g = gridGraph(net, blockLibrary(project));
      const desc = (i: number) => {
        const e = net.elements[i]!;
        switch (e.kind) {
          case 'contact':
            return `contact:${e.contact}:${e.variable}`;
          case 'coil':
            return `coil:${e.coil}:${e.variable}`;
          case 'box':
            return `box:${e.blockType}:${e.instance ?? ''}:${JSON.stringify(e.inputs)}:${JSON.stringify(e.outputs)}`;
          case 'jump':
            return `jump:${e.target}`;
          default:
            return e.kind;
        }
      };
      g.sources.forEach((pins, ei) =>
        pins.forEach((srcs, pin) => {
          for (const s of srcs)
            out.push(
              `${pou.name} ${desc(ei)}.${pin} <- ${s.kind === 'rail' ? 'rail' : `${desc(s.el)}.${s.pin}`}`,
            );
        }),
      );
    });
  return out.sort();
}
