// A whole POU: variable table, labels (LD-R06), every network, then the program-wide warnings
// (LD-R12) and empty networks (LD-W01).
import { IDENTIFIER_RE } from '../../model/iecTypes';
import type { Pou, Profile, Project } from '../../model/project';
import type { Diagnostic } from '../api';
import { blockLibrary } from '../../model/library';
import { newPouContext, type CoilFamily, type LoweredPou, type Placement } from './context';
import type { NetworkIR } from './ir';
import { lowerChart } from '../sfc/chart';
import { startNetwork } from './lower';
import { lowerTextBody, refuseBody } from '../st/body';
import { Reporter } from './report';
import type { SymbolTable } from './symbols';
import { buildSymbols } from './pouSymbols';
import { yieldPoint } from '../yieldPoint';

const FAMILY_WORDS: Record<CoilFamily, string> = {
  assign: '( )',
  negated: '(/)',
  pulse: '(P)/(N)',
  latch: '(S)/(R)',
};

/** Checks and lowers one POU on its own. Diagnostics about the project's globals go to `globalsOut`. */
export function lowerPou(
  project: Project,
  pou: Pou,
  profile: Profile,
  out: Diagnostic[],
  globalsOut: Diagnostic[],
  place: Placement = { first: 0 },
): LoweredPou {
  const start = out.length;
  const varReporter = new Reporter(out, pou.name, -1);
  const symbols = buildSymbols(
    project,
    pou,
    varReporter,
    new Reporter(globalsOut, 'globals', -1),
    blockLibrary(project),
    profile,
  );
  checkPouKind(pou, symbols, varReporter);
  const lowered =
    pou.language === 'SFC' ? checkChart(project, pou, profile, symbols, out, place) : lowerPouBody(project, pou, profile, symbols, out, place);
  const ok =
    !out.slice(start).some((d) => d.severity === 'error') && !globalsOut.some((d) => d.severity === 'error');
  return { ...lowered, ok };
}

/**
 * The declarations of a POU checked on its own (what lowerPou reports before its networks): its
 * variables, the externals it names, LD-E22. Its networks are checked where they are lowered.
 */
export function checkDeclarations(project: Project, pou: Pou, profile: Profile, out: Diagnostic[]): void {
  const r = new Reporter(out, pou.name, -1);
  checkPouKind(pou, buildSymbols(project, pou, r, new Reporter([], 'globals', -1), blockLibrary(project), profile), r);
}

/** An SFC POU checked on its own: its chart (steps, transitions, qualifiers, the code inside it). */
function checkChart(project: Project, pou: Pou, profile: Profile, symbols: SymbolTable, out: Diagnostic[], place: Placement): LoweredPou {
  const start = out.length;
  const ctx = newPouContext(project, pou, profile, symbols, new Map(), place);
  lowerChart(
    pou,
    symbols,
    [symbols],
    new Reporter(out, pou.name, -1),
    (piece) => {
      lowerPouBody(project, piece, profile, symbols, out);
      return undefined;
    },
    { profile, functions: ctx.functions, network: 0 },
  );
  return { ctx, networks: [], ok: !out.slice(start).some((d) => d.severity === 'error') };
}

/** LD-E22: a FUNCTION keeps nothing between calls, so it declares no FB instance. */
function checkPouKind(pou: Pou, symbols: SymbolTable, r: Reporter): void {
  if (pou.kind !== 'FUNCTION') return;
  for (const v of pou.variables) {
    if (v.varClass === 'external') continue;
    const sym = symbols.own(v.name);
    if (sym?.kind === 'fb' || sym?.kind === 'ufb')
      r.error(
        'LD-E22',
        `the FUNCTION ${pou.name} declares "${v.name}", an instance of ${sym.type}; a function keeps nothing between calls, so the instance's state would be lost: make ${pou.name} a FUNCTION_BLOCK`,
      );
  }
}

/** Checks and lowers the networks of a POU over a symbol table (its own, or an instance's scope). */
export function lowerPouBody(
  project: Project,
  pou: Pou,
  profile: Profile,
  symbols: SymbolTable,
  out: Diagnostic[],
  place: Placement = { first: 0 },
): LoweredPou {
  if (pou.language === 'ST' || pou.language === 'IL')
    return lowerTextBody(project, pou as Pou & { language: 'ST' | 'IL' }, profile, symbols, out, place);
  if (pou.language !== 'LD') return refuseBody(project, pou, profile, symbols, out, place);
  const start = out.length;
  // LD-R06: labels are identifiers or unsigned integers, unique in the POU.
  const labels = new Map<string, number>();
  pou.networks.forEach((net, i) => {
    const label = net.label?.trim();
    if (!label) return;
    const r = new Reporter(out, pou.name, i, label);
    if (!IDENTIFIER_RE.test(label) && !/^\d+$/.test(label)) {
      r.error(
        'LD-R06',
        `the label "${label}" is not valid; use a name (letters, digits, _) or an unsigned number`,
      );
      return;
    }
    const key = label.toUpperCase();
    const first = labels.get(key);
    if (first !== undefined)
      r.error(
        'LD-R06',
        `the label "${label}" is already used by network ${first - place.first + 1}; labels must be unique in ${pou.name}`,
      );
    else labels.set(key, place.first + i);
  });

  const ctx = newPouContext(project, pou, profile, symbols, labels, place);
  const started = pou.networks.map((net, i) => {
    const r = new Reporter(out, pou.name, i, net.label?.trim());
    if (net.elements.length === 0 && net.vlinks.length === 0) {
      r.warning('LD-W01', 'this network is empty; draw a rung in it or delete it');
      const ir: NetworkIR = {
        index: place.first + i,
        ops: [],
        netCount: 0,
        railNets: [],
        elementNets: [],
        vlinkNets: [],
        constants: [],
        ...(net.label ? { label: net.label } : {}),
      };
      return { finish: () => ir };
    }
    // openplc: networks imported with turns next to another such network run their statements together.
    const grouped = profile === 'openplc' && !!net.turns && (!!pou.networks[i - 1]?.turns || !!pou.networks[i + 1]?.turns);
    const begun = startNetwork(ctx, net, i, r, grouped);
    yieldPoint();
    return begun;
  });
  // Profile openplc: each network's blocks no coil needed are lowered after every network's coils,
  // and run at the end of the body's last network (generated.ts).
  const lowered = started.map((p) => {
    const ir = p.finish();
    yieldPoint();
    return ir;
  });
  const lateOf = lowered.flatMap((ir) => (ir?.late ? [ir.index] : []));
  const last = lowered[lowered.length - 1];
  const networks = lateOf.length && last ? [...lowered.slice(0, -1), { ...last, runLate: lateOf }] : lowered;
  // Profile openplc: the instances with an executionOrderId run first, in id order over the whole
  // body (ties in network order), by the body's first network (generated.ts).
  const earlyOf = networks
    .flatMap((ir) => (ir?.earlyOrder ?? []).map((id, s) => ({ id, at: [ir!.index, s] as const })))
    .sort((a, b) => a.id - b.id)
    .map((e) => e.at);
  // Profile openplc: consecutive networks with imported turns (Network.turns) run the statements of
  // their coils and output variables together, in turn order, from the group's first network.
  const runs = new Map<number, (readonly [number, number])[]>();
  if (earlyOf.length) runs.set(0, earlyOf);
  const turned = (i: number) => profile === 'openplc' && !!pou.networks[i]?.turns;
  for (let i = 0; i < networks.length; ) {
    if (!turned(i) || !(turned(i - 1) || turned(i + 1))) {
      i++;
      continue;
    }
    const group: { key: number; at: readonly [number, number] }[] = [];
    const start = i;
    for (; i < networks.length && turned(i); i++) {
      const ir = networks[i];
      if (!ir?.earlyTurns) continue;
      const ordered = ir.earlyOrder?.length ?? 0;
      ir.earlyTurns.forEach((key, k) => group.push({ key, at: [ir.index, ordered + k] }));
    }
    group.sort((a, b) => a.key - b.key);
    runs.set(start, [...(runs.get(start) ?? []), ...group.map((e) => e.at)]);
  }
  for (const [i, list] of runs) {
    const ir = networks[i];
    if (ir && list.length) networks[i] = { ...ir, runEarly: list };
  }

  // LD-R12: a variable written by coils of different kinds.
  for (const [v, families] of ctx.coilWrites) {
    if (families.size < 2) continue;
    const places = [...families.values()];
    const second = places[1]!;
    const net = pou.networks[second.network];
    new Reporter(out, pou.name, second.network, net?.label?.trim()).warning(
      'LD-R12',
      `"${v.name}" is written by coils of different kinds (${[...families.keys()].map((f) => FAMILY_WORDS[f]).join(' and ')}); legal, but the last one in each scan wins — check this is intended`,
      { row: second.row, col: second.col },
    );
  }
  const ok = !out.slice(start).some((d) => d.severity === 'error');
  return { ctx, networks, ok };
}
