// Binding program variables located at %I.../%Q... to the gateway's points, checked before Run.
import type { Diagnostic } from '../engine/api';
import { parseLocation } from '../model/iecTypes';
import type { Project, Variable } from '../model/project';
import { canonicalAddress, type PointInfo } from '../protocol/points';

/** LD-EIO1: located variable has no point on the gateway; LD-EIO2: its type does not fit the point; LD-WIO1: signedness differs. */
export const IO_RULES = { missing: 'LD-EIO1', type: 'LD-EIO2', sign: 'LD-WIO1' } as const;

export interface Binding {
  /** POU name, or "" for a global variable. */
  readonly pou: string;
  readonly variable: string;
  readonly varType: string;
  readonly address: string;
  readonly point: PointInfo;
}

export interface BindingReport {
  readonly bindings: readonly Binding[];
  /** Errors block Run with hardware attached; warnings are shown. */
  readonly problems: readonly Diagnostic[];
}

const WORD_TYPES = ['WORD', 'INT', 'UINT'];

function checkOne(pou: string, v: Variable, points: ReadonlyMap<string, PointInfo>): Binding | Diagnostic | undefined {
  const location = v.location?.trim();
  if (!location) return undefined;
  const loc = parseLocation(location);
  if (!loc || loc.area === 'M') return undefined; // memory is the program's own, not field I/O
  const where = pou ? `${pou}.${v.name}` : `global ${v.name}`;
  const diag = (severity: Diagnostic['severity'], rule: Diagnostic['rule'], message: string): Diagnostic => ({ severity, rule, pou, network: -1, message });
  const address = canonicalAddress(location);
  const point = address ? points.get(address) : undefined;
  if (!address || !point) {
    return diag('error', IO_RULES.missing, `${where} AT ${location}: the gateway has no I/O point ${address ?? location}`);
  }
  if (point.type === 'BOOL' ? v.type !== 'BOOL' : !WORD_TYPES.includes(v.type)) {
    const fits = point.type === 'BOOL' ? 'BOOL' : 'WORD, INT or UINT';
    return diag('error', IO_RULES.type, `${where} AT ${address} is ${v.type}, but the gateway point is ${point.type} (use ${fits})`);
  }
  return { pou, variable: v.name, varType: v.type, address, point };
}

/** Checks every located variable of the project against the gateway's points (welcome.points). */
export function checkBindings(project: Project, points: readonly PointInfo[]): BindingReport {
  const byAddress = new Map(points.map((p) => [p.address, p]));
  const bindings: Binding[] = [];
  const problems: Diagnostic[] = [];
  const scopes: [string, readonly Variable[]][] = [['', project.globals], ...project.pous.map((p): [string, readonly Variable[]] => [p.name, p.variables])];
  for (const [pou, vars] of scopes) {
    for (const v of vars) {
      const r = checkOne(pou, v, byAddress);
      if (!r) continue;
      if ('rule' in r) {
        problems.push(r);
        continue;
      }
      bindings.push(r);
      const signed = (t: string) => t === 'INT';
      if (r.point.type !== 'WORD' && r.point.type !== 'BOOL' && signed(r.varType) !== signed(r.point.type)) {
        problems.push({
          severity: 'warning',
          rule: IO_RULES.sign,
          pou,
          network: -1,
          message: `${pou ? `${pou}.${v.name}` : `global ${v.name}`} AT ${r.address} is ${r.varType} but the gateway point is ${r.point.type}: values above 32767 read as negative`,
        });
      }
    }
  }
  return { bindings, problems };
}
