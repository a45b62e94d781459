// Test helper: networks from a compact row notation, and small projects around them.
//
// One string per grid row, tokens separated by spaces, one token per cell:
//   [A] contact   [/A] normally closed   [P:A] [N:A] transition   [NOT] inverting   [TRUE] constant
//   (A) coil      (/A) negated   (S:A) (R:A) set/reset   (M:A) (SM:A) (RM:A) retentive   (P:A) (N:A) transition
//   -  line       .  empty cell  #  cell covered by a box   >>LABEL jump   <RET> return
//   >C>|  connector C (ends the line on its left)   |>C>  continuation C (starts a line on its right)
// A `+` between tokens marks a point of a vertical line on that boundary (before the first token:
// the left rail): `+` at the same boundary in consecutive rows are joined by vertical links.
import type { CoilType, ContactType, LdElement, VLink } from '../../src/model/elements';
import { newNetwork, newProject, newPou, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Network, Profile, Project, Variable } from '../../src/model/project';
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { Plc } from '../../src/engine/api';
import { formatDiagnostic } from '../../src/engine/compile/report';

let ids = 0;
const nextId = (): ElementId => `e${++ids}` as ElementId;

export interface BoxSpec {
  readonly row: number;
  readonly col: number;
  readonly type: string;
  readonly instance?: string;
  readonly inputs?: Record<string, string>;
  readonly outputs?: Record<string, string>;
  readonly inputCount?: number;
  /** EN/ENO pins on an FB box; EN left open in the PLCopen file it came from (BoxElement). */
  readonly executionControl?: boolean;
  readonly enOpen?: boolean;
  /** PLCopen executionOrderId of the box, and of the variables beside its outputs (by pin). */
  readonly executionOrder?: number;
  readonly outputOrders?: Record<string, number>;
}

export interface LadderOptions {
  readonly cols?: number;
  readonly label?: string;
  readonly boxes?: readonly BoxSpec[];
  readonly vlinks?: readonly VLink[];
}

function cellElement(token: string, row: number, col: number): LdElement | undefined {
  const id = nextId();
  const at = { id, row, col };
  if (token === '.' || token === '#') return undefined;
  if (token === '-') return { ...at, kind: 'link' };
  if (token === '<RET>') return { ...at, kind: 'return' };
  let c = /^>(.*)>\|$/.exec(token);
  if (c) return { ...at, kind: 'connector', name: c[1]! };
  c = /^\|>(.*)>$/.exec(token);
  if (c) return { ...at, kind: 'continuation', name: c[1]! };
  if (token.startsWith('>>')) return { ...at, kind: 'jump', target: token.slice(2) };
  let m = /^\[(.*)\]$/.exec(token);
  if (m) {
    const body = m[1]!;
    if (body === 'NOT') return { ...at, kind: 'contact', contact: 'NOT', variable: '' };
    if (body.startsWith('/')) return { ...at, kind: 'contact', contact: 'NC', variable: body.slice(1) };
    const edge = /^([PN]):(.*)$/.exec(body);
    if (edge) return { ...at, kind: 'contact', contact: edge[1] as ContactType, variable: edge[2]! };
    return { ...at, kind: 'contact', contact: 'NO', variable: body };
  }
  m = /^\((.*)\)$/.exec(token);
  if (m) {
    const body = m[1]!;
    if (body.startsWith('/')) return { ...at, kind: 'coil', coil: 'NEG', variable: body.slice(1) };
    const typed = /^(S|R|M|SM|RM|P|N):(.*)$/.exec(body);
    if (typed) {
      const map: Record<string, CoilType> = {
        S: 'SET',
        R: 'RESET',
        M: 'M',
        SM: 'SM',
        RM: 'RM',
        P: 'P',
        N: 'N',
      };
      return { ...at, kind: 'coil', coil: map[typed[1]!]!, variable: typed[2]! };
    }
    return { ...at, kind: 'coil', coil: 'COIL', variable: body };
  }
  throw new Error(`unknown ladder token "${token}"`);
}

export function ladder(rows: readonly string[], opts: LadderOptions = {}): Network {
  const elements: LdElement[] = [];
  const vlinks: VLink[] = [...(opts.vlinks ?? [])];
  let width = 0;
  const plus = new Set<string>();
  rows.forEach((text, row) => {
    let col = 0;
    for (const token of text.trim().split(/\s+/).filter(Boolean)) {
      if (token === '+') {
        plus.add(`${row}:${col}`);
        if (plus.has(`${row - 1}:${col}`)) vlinks.push({ row: row - 1, boundary: col });
        continue;
      }
      const el = cellElement(token, row, col);
      if (el) elements.push(el);
      col++;
    }
    width = Math.max(width, col);
  });
  for (const b of opts.boxes ?? []) {
    elements.push({
      id: nextId(),
      kind: 'box',
      row: b.row,
      col: b.col,
      blockType: b.type,
      ...(b.instance ? { instance: b.instance } : {}),
      ...(b.inputCount ? { inputCount: b.inputCount } : {}),
      ...(b.executionControl ? { executionControl: true } : {}),
      ...(b.enOpen ? { enOpen: true } : {}),
      inputs: b.inputs ?? {},
      outputs: b.outputs ?? {},
      ...(b.executionOrder ? { executionOrder: b.executionOrder } : {}),
      ...(b.outputOrders ? { outputOrders: b.outputOrders } : {}),
    });
    width = Math.max(width, b.col + 2);
  }
  return newNetwork({
    rows: Math.max(rows.length, ...(opts.boxes ?? []).map((b) => b.row + 4)),
    cols: opts.cols ?? width,
    elements,
    vlinks,
    ...(opts.label ? { label: opts.label } : {}),
  });
}

/** `Name TYPE [%LOC] [:= init] [RETAIN] [CONSTANT]`, e.g. `Start BOOL %IX0.0`, `Count INT := 5 RETAIN`. */
export function vars(...specs: string[]): Variable[] {
  return specs.map((spec) => {
    const m = /^(\S+)\s+(\S+)(?:\s+(%\S+))?(?:\s*:=\s*(\S+))?(\s+RETAIN)?(\s+CONSTANT)?$/.exec(spec.trim());
    if (!m) throw new Error(`bad variable spec "${spec}"`);
    return variable(m[1]!, m[2]!, {
      ...(m[3] ? { location: m[3] } : {}),
      ...(m[4] ? { initial: m[4] } : {}),
      retain: Boolean(m[5]),
      ...(m[6] ? { constant: true } : {}),
    });
  });
}

export function project(
  variables: readonly Variable[],
  networks: readonly Network[],
  profile: Profile = 'iec',
): Project {
  const main = newPou('Main', { variables, networks });
  return newProject('Test', { pous: [main], profile });
}

/** Compiles (failing with the diagnostics when there are errors) and creates a PLC on a 10 ms virtual clock. */
export function plcOf(p: Project, cycleMs = 10, profile?: Profile): Plc {
  const { program, diagnostics } = compileProgram(p, profile ? { profile } : {});
  if (!program) throw new Error(`program does not compile:\n${diagnostics.map(formatDiagnostic).join('\n')}`);
  return createPlc(program, { cycleMs });
}

/**
 * Runs one scan per step, writing that step's values first, and records the named variables after
 * each scan (BOOL as 0/1): a trace to compare with what the PLC should do.
 */
export function trace(plc: Plc, steps: readonly Record<string, boolean | number>[], names: readonly string[]): (number | bigint | string)[][] {
  return steps.map((inputs) => {
    for (const [k, v] of Object.entries(inputs)) plc.write(k, v);
    plc.scan();
    return names.map((n) => {
      const v = plc.read(n);
      return typeof v === 'boolean' ? Number(v) : (v as number | bigint | string);
    });
  });
}
