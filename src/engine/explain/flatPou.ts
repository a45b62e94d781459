// "Why?" over a whole IEC program: the compiled program runs every body (programs, FB instances'
// calls, function calls) as one list of networks. This builds the matching document view — a POU
// whose network k is the document network that flattened network k was compiled from, with the
// body's own names written by instance path (`Run` in Motor1's body reads `Motor1.Run`) — so an
// explanation can follow a value into and out of FB bodies and name what it finds by path.
import type { LdElement } from '../../model/elements';
import type { Network, Pou, Project } from '../../model/project';
import type { CompiledProgram } from '../compile/program';

type BodyInfo = CompiledProgram['bodies'][number];

const same = (a: string | undefined, b: string | undefined) => (a ?? '').toUpperCase() === (b ?? '').toUpperCase();

/** `Run` → `Motor1.Run` when the body's POU declares `Run` itself (not as VAR_EXTERNAL). */
function qualifier(pou: Pou, prefix: string): (operand: string) => string {
  if (!prefix) return (o) => o;
  const own = new Set(pou.variables.filter((v) => v.varClass !== 'external').map((v) => v.name.toUpperCase()));
  return (operand) => {
    const text = operand.trim();
    const head = /^[A-Za-z_][A-Za-z0-9_]*/.exec(text)?.[0];
    return head && own.has(head.toUpperCase()) ? `${prefix}${text}` : operand;
  };
}

function qualifyElement(el: LdElement, q: (operand: string) => string): LdElement {
  switch (el.kind) {
    case 'contact':
    case 'coil':
      return el.variable ? { ...el, variable: q(el.variable) } : el;
    case 'box': {
      const map = (r: Readonly<Record<string, string>>) => Object.fromEntries(Object.entries(r).map(([k, v]) => [k, v ? q(v) : v]));
      return { ...el, ...(el.instance ? { instance: q(el.instance) } : {}), inputs: map(el.inputs), outputs: map(el.outputs) };
    }
    default:
      return el;
  }
}

/** The document POU of each flattened network's body, and the body itself. */
export function bodyAt(program: CompiledProgram, network: number): BodyInfo | undefined {
  return program.bodies.find((b) => network >= b.first && network < b.end);
}

/**
 * The flattened program as one POU (see above). Bodies whose POU is not written in LD, or not in
 * `project`, leave their networks empty. `main` is the program's own POU (named in explanations).
 */
export function flattenedPou(program: CompiledProgram, project: Project, main: Pou): Pou {
  const networks: Network[] = new Array<Network>(program.networks.length);
  for (const body of program.bodies) {
    const pou = project.pous.find((p) => same(p.name, body.pou));
    if (!pou || pou.language !== 'LD') continue;
    const q = qualifier(pou, body.instance ? `${body.instance}.` : '');
    for (let k = 0; k < body.end - body.first && k < pou.networks.length; k++) {
      const n = pou.networks[k]!;
      networks[body.first + k] = body.instance ? { ...n, elements: n.elements.map((el) => qualifyElement(el, q)) } : n;
    }
  }
  return { ...main, networks };
}

/**
 * The flattened network where network `network` of the shown body ran in a recorded scan: the
 * body of `instance` (an FB instance path or a program instance) — its call that ran (the last of
 * several), else its first — or a function's call that ran; `executed` tells which ran.
 */
export function flatNetwork(
  program: CompiledProgram,
  view: { readonly pou: string; readonly instance?: string },
  network: number,
  executed: (network: number) => boolean,
): number | undefined {
  const body = shownBody(program, view, executed);
  return body && network < body.end - body.first ? body.first + network : undefined;
}

/**
 * The body a view shows in a scan: the call of `instance` (an FB instance path or a program
 * instance), or of function `pou`, that ran — the last of several (calls run in body order) — else
 * its first call.
 */
export function shownBody(
  program: CompiledProgram,
  view: { readonly pou: string; readonly instance?: string },
  executed: (network: number) => boolean,
): BodyInfo | undefined {
  let best: BodyInfo | undefined;
  for (const b of program.bodies) {
    const mine = view.instance !== undefined ? same(b.instance, view.instance) : b.kind === 'function' && same(b.pou, view.pou);
    if (!mine) continue;
    if (!best || (b.end > b.first && executed(b.first))) best = b;
  }
  return best;
}
