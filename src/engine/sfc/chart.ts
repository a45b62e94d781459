// A chart checked against its POU and lowered over an instance's scope: its steps become variables
// of the instance (`Step.X`, `Step.T`, watchable as `Instance.Step.X`), MATIEC's hidden records
// (previous X, action flags and countdowns, transition values, last call time) hidden variables
// under `Instance._SFC.`, LD pieces bodies of networks, ST pieces compiled by the ST compiler
// (src/engine/st: the whole language, calls of functions and FBs included) into `st` operations
// (a condition assigns the transition's value). All of it lives in the program's stores, so it is reset on a cold restart and kept
// with the instance's variables.
import type { Network, Pou, Profile, SfcChart, SfcCode, Variable } from '../../model/project';
import type { ResolvedFunction } from '../library/fnTypes';
import type { CallBuilder } from '../compile/context';
import type { StOp } from '../st/lowered';
import { compileStExpression, compileStStatements, describeStError, stOp, type StError, type StScope } from '../st/index';
import { parseLiteral } from '../values/literals';
import type { Reporter } from '../compile/report';
import { SymbolTable, type Access, type UfbSymbol, type VarSymbol } from '../compile/symbols';
import type { ActionIR, AssociationIR, ChartIR, RangeIR, StepIR, TransitionIR } from './ir';

export const QUALIFIERS = ['N', 'R', 'S', 'L', 'D', 'P', 'P0', 'P1', 'SD', 'DS', 'SL'] as const;
const TIMED = new Set(['L', 'D', 'SD', 'DS', 'SL']);

/** Lowers an LD piece of the chart (an action body or a condition) as a body of networks over the scope. */
export type PieceLowering = (piece: Pou) => RangeIR | undefined;

/** What the ST inside a chart is compiled with (see st/index.ts StScope), and the chart's network. */
export interface ChartStContext {
  readonly profile: Profile;
  /** The program's function table. */
  readonly functions: ResolvedFunction[];
  /** Builds the bodies of user FB and function calls; absent when the POU is only checked. */
  readonly calls?: CallBuilder;
  /** The network holding the chart (named by the watchdog when an ST loop runs too long). */
  readonly network: number;
}

const bool = (name: string, initial?: string): Variable => ({
  name,
  type: 'BOOL',
  varClass: 'local',
  retain: false,
  comment: '',
  ...(initial ? { initial } : {}),
});
const time = (name: string): Variable => ({ name, type: 'TIME', varClass: 'local', retain: false, comment: '' });

class Quiet {
  errors = 0;
  error(): void {
    this.errors++;
  }
  warning(): void {}
}
const quiet = () => new Quiet() as unknown as Reporter;

/** The POU a step's two variables are declared from (a step reads like an instance: `S1.X`). */
function stepPou(name: string, initial: boolean): Pou {
  return {
    id: `sfc-step-${name}` as Pou['id'],
    name: 'SFC_STEP',
    kind: 'PROGRAM',
    language: 'LD',
    comment: '',
    variables: [bool('X', initial ? 'TRUE' : undefined), time('T')],
    networks: [],
  };
}

/** The chart's variables in one instance, allocated once however many times the instance is called. */
interface ChartState {
  readonly steps: readonly { readonly sym: UfbSymbol; readonly x: VarSymbol; readonly t: VarSymbol; readonly prev: VarSymbol }[];
  readonly hidden: SymbolTable;
  readonly locals: ReadonlyMap<string, VarSymbol>;
  readonly lasttick: VarSymbol;
  readonly actions: Map<string, { state: VarSymbol; set: VarSymbol; reset: VarSymbol; stored: VarSymbol; setTime: VarSymbol; resetTime: VarSymbol }>;
  readonly flags: VarSymbol[];
}

const states = new WeakMap<object, Map<string, ChartState>>();

const v = (t: SymbolTable, name: string): VarSymbol => t.own(name) as VarSymbol;
const acc = (s: VarSymbol): Access => ({ kind: 'var', v: s, type: s.type });

function chartState(chart: SfcChart, scope: SymbolTable): ChartState {
  let perStorage = states.get(scope.storage);
  if (!perStorage) states.set(scope.storage, (perStorage = new Map()));
  const hit = perStorage.get(scope.prefix);
  if (hit) return hit;
  const hidden = new SymbolTable(scope.storage, `${scope.prefix}_SFC.`, scope.library, true);
  hidden.declare(time('lasttick'), false, quiet());
  const steps = chart.steps.map((s, k) => {
    const sp = stepPou(s.name, s.initial);
    const table = new SymbolTable(scope.storage, `${scope.prefix}${s.name}.`, scope.library);
    for (const d of sp.variables) table.declare(d, false, quiet());
    const sym: UfbSymbol = { kind: 'ufb', name: `${scope.prefix}${s.name}`, type: 'SFC_STEP', pou: sp, scope: table, retain: false };
    hidden.declare(bool(`P${k}`), false, quiet());
    return { sym, x: v(table, 'X'), t: v(table, 'T'), prev: v(hidden, `P${k}`) };
  });
  const locals = new Map<string, VarSymbol>();
  for (const name of chart.locals ?? []) {
    hidden.declare(bool(name), false, quiet());
    const l = hidden.own(name);
    if (l?.kind === 'var') locals.set(name.toUpperCase(), l);
  }
  const flags = chart.transitions.map((_, k) => {
    hidden.declare(bool(`T${k}`), false, quiet());
    return v(hidden, `T${k}`);
  });
  const state: ChartState = { steps, hidden, locals, lasttick: v(hidden, 'lasttick'), actions: new Map(), flags };
  perStorage.set(scope.prefix, state);
  return state;
}

function actionRecord(state: ChartState, key: string) {
  let rec = state.actions.get(key);
  if (!rec) {
    const k = state.actions.size;
    const h = state.hidden;
    for (const f of ['state', 'set', 'reset', 'stored']) h.declare(bool(`A${k}_${f}`), false, quiet());
    for (const f of ['srt', 'rrt']) h.declare(time(`A${k}_${f}`), false, quiet());
    rec = {
      state: v(h, `A${k}_state`),
      set: v(h, `A${k}_set`),
      reset: v(h, `A${k}_reset`),
      stored: v(h, `A${k}_stored`),
      setTime: v(h, `A${k}_srt`),
      resetTime: v(h, `A${k}_rrt`),
    };
    state.actions.set(key, rec);
  }
  return rec;
}

/**
 * Checks the chart of an SFC POU and lowers it over `scope` (the POU's own symbols, an FB
 * instance's or a program instance's). `scopes` are the tables its step names and condition
 * results are bound in (the instance's own table and this call's). Errors go to `r`: LD-E40 (no
 * chart, no initial step), LD-E41 (step names), LD-E42 (transitions), LD-E43 (actions and
 * qualifiers), LD-E44 (code inside the chart).
 */
export function lowerChart(
  pou: Pou,
  scope: SymbolTable,
  scopes: readonly SymbolTable[],
  r: Reporter,
  lowerPiece: PieceLowering,
  stContext: ChartStContext,
): ChartIR | undefined {
  const before = r.errors;
  const chart = pou.sfc;
  if (!chart) {
    r.error('LD-E40', `the SFC body of ${pou.name} has no chart to run; import it again from its PLCopen file`);
    return undefined;
  }
  if (!chart.steps.some((s) => s.initial)) r.error('LD-E40', `the chart of ${pou.name} has no initial step`);
  const stepIndex = new Map<string, number>();
  chart.steps.forEach((s, k) => {
    const key = s.name.toUpperCase();
    if (stepIndex.has(key)) r.error('LD-E41', `the step name ${s.name} is used twice in ${pou.name}`);
    else if (scope.own(s.name) && scope.own(s.name)?.kind !== 'ufb')
      r.error('LD-E41', `the step ${s.name} has the name of a variable of ${pou.name}; rename one of them`);
    stepIndex.set(key, k);
  });
  const stepOf = (name: string, where: string): number => {
    const k = stepIndex.get(name.toUpperCase());
    if (k === undefined) r.error('LD-E42', `${where} names the step "${name}", which the chart does not have`);
    return k ?? -1;
  };
  chart.transitions.forEach((t, k) => {
    const where = `transition ${t.localId ?? k + 1}`;
    if (!t.from.length) r.error('LD-E42', `${where} follows no step`);
    if (!t.to.length) r.error('LD-E42', `${where} leads to no step`);
  });
  if (r.errors > before) return undefined;

  const state = chartState(chart, scope);
  for (const t of scopes) {
    state.steps.forEach((s) => t.bind(s.sym.name.slice(scope.prefix.length), s.sym));
    for (const [name, l] of state.locals) if (!t.own(name)) t.bind(name, l);
  }

  const piece = (code: SfcCode, name: string, variables = pou.variables): RangeIR | undefined => {
    if (code.language !== 'LD') return undefined;
    return lowerPiece({
      id: `${pou.id}-${name}` as Pou['id'],
      name: `${pou.name}.${name}`,
      kind: pou.kind,
      language: 'LD',
      comment: '',
      variables,
      networks: code.networks as Network[],
    });
  };
  const stScope: StScope = {
    symbols: scope,
    profile: stContext.profile,
    functions: stContext.functions,
    ...(stContext.calls ? { calls: stContext.calls } : {}),
    pouName: pou.name,
  };
  /** An ST piece compiled into an `st` operation, or undefined after LD-E44 naming every error. */
  const stPiece = (text: string, what: string, compile: () => { stmts?: StOp['body']; errors: StError[] }): StOp | undefined => {
    const c = compile();
    if (c.stmts && !c.errors.length) return stOp(c.stmts, stContext.network, 'ST');
    const shown = text.replace(/\s+/g, ' ').trim();
    for (const e of c.errors)
      r.error('LD-E44', `${what} (ST "${shown.length > 60 ? `${shown.slice(0, 57)}...` : shown}") does not compile: ${describeStError(e)}`);
    return undefined;
  };
  const code = (c: SfcCode, what: string): boolean => {
    if (c.language !== 'none') return true;
    r.error('LD-E44', `${what} cannot run: ${c.why}`);
    return false;
  };

  // Actions: the declared ones with a body, then BOOL variables named by associations.
  const actions: ActionIR[] = [];
  const actionIndex = new Map<string, number>();
  const bodies: number[] = [];
  for (const a of chart.actions) {
    const what = `the action ${a.name} of ${pou.name}`;
    if (!code(a.body, what)) continue;
    const rec = actionRecord(state, a.name.toUpperCase());
    let body: ActionIR['body'];
    if (a.body.language === 'ST') {
      const text = a.body.text;
      const op = stPiece(text, what, () => {
        const c = compileStStatements(text, stScope);
        return { ...(c.body ? { stmts: c.body } : {}), errors: c.errors };
      });
      if (op) body = { st: op }; // else LD-E44 is reported; the action stays known to its steps
    } else {
      const range = piece(a.body, a.name);
      if (range) body = { range };
    }
    actionIndex.set(a.name.toUpperCase(), actions.length);
    bodies.push(actions.length);
    actions.push({ name: a.name, ...recordAccess(rec), ...(body ? { body } : {}) });
  }
  const variables: number[] = [];
  const associations: AssociationIR[] = [];
  chart.steps.forEach((s, k) => {
    for (const as of s.associations) {
      const where = `step ${s.name} of ${pou.name}`;
      const q = as.qualifier.toUpperCase();
      if (!(QUALIFIERS as readonly string[]).includes(q)) {
        r.error('LD-E43', `${where} gives action ${as.action} the qualifier "${as.qualifier}"; use N, R, S, L, D, P, P0, P1, SD, DS or SL`);
        continue;
      }
      let ms = 0;
      if (TIMED.has(q)) {
        const lit = as.duration ? parseLiteral(as.duration, 'TIME') : undefined;
        if (!lit?.ok || typeof lit.value !== 'number') {
          r.error('LD-E43', `${where} gives action ${as.action} the qualifier ${q}, which needs a duration like T#2s${as.duration ? ` (not "${as.duration}")` : ''}`);
          continue;
        }
        ms = lit.value;
      }
      let index = actionIndex.get(as.action.toUpperCase());
      if (index === undefined) {
        const res = scope.resolve(as.action, { literals: false, implicitLocations: false });
        if (!res.ok || res.access.type !== 'BOOL' || res.access.kind === 'const' || res.access.kind === 'pin') {
          r.error(
            'LD-E43',
            res.ok
              ? `${where} names the action "${as.action}", a ${res.access.type} ${res.access.kind === 'pin' ? 'pin' : 'value'}; an action is an action of the POU or a BOOL variable`
              : `${where} names the action "${as.action}", which is neither an action of ${pou.name} nor a variable`,
          );
          continue;
        }
        index = actions.length;
        actionIndex.set(as.action.toUpperCase(), index);
        variables.push(index);
        actions.push({ name: as.action, ...recordAccess(actionRecord(state, as.action.toUpperCase())), variable: res.access });
      }
      associations.push({ step: k, action: index, qualifier: q, time: ms });
    }
  });

  const transitions: TransitionIR[] = [];
  chart.transitions.forEach((t, k) => {
    const what = `the condition of transition ${t.localId ?? k + 1} (from ${t.from.join(', ')})`;
    const from = t.from.map((s) => stepOf(s, `transition ${t.localId ?? k + 1}`));
    const to = t.to.map((s) => stepOf(s, `transition ${t.localId ?? k + 1}`));
    if (!code(t.condition, what)) return;
    let condition: TransitionIR['condition'] | undefined;
    if (t.condition.language === 'ST') {
      const text = t.condition.text.replace(/;\s*$/, '');
      const flag = acc(state.flags[k]!);
      const op = stPiece(text, what, () => {
        const c = compileStExpression(text, stScope, 'BOOL');
        return { ...(c.expr ? { stmts: [{ k: 'assign', dst: flag, value: c.expr }] } : {}), errors: c.errors };
      });
      if (!op) return;
      condition = { st: op };
    } else if (t.condition.language === 'LD') {
      const resultName = t.condition.result ?? '';
      const res = scope.resolve(resultName, { literals: false, implicitLocations: false });
      if (!res.ok || res.access.type !== 'BOOL') {
        r.error('LD-E44', `${what} writes "${resultName}", which is not a BOOL variable`);
        return;
      }
      const range = piece(t.condition, `T${k}`);
      if (range) condition = { range, result: res.access };
    }
    if (!condition) return;
    transitions.push({ from, to, priority: t.priority !== undefined, flag: acc(state.flags[k]!), condition });
  });
  if (r.errors > before) return undefined;

  // MATIEC's test list: a transition with a PRIORITY goes before the first one of a higher
  // number; one without goes last (its priority counts as 0).
  const list: { k: number; p: number }[] = [];
  chart.transitions.forEach((t, k) => {
    if (t.priority === undefined) list.push({ k, p: 0 });
    else {
      let at = 0;
      while (at < list.length && list[at]!.p <= t.priority) at++;
      list.splice(at, 0, { k, p: t.priority });
    }
  });
  const steps: StepIR[] = state.steps.map((s, k) => ({ name: chart.steps[k]!.name, x: acc(s.x), t: acc(s.t), prev: acc(s.prev) }));
  return {
    pou: pou.name,
    lasttick: acc(state.lasttick),
    steps,
    actions,
    transitions,
    testOrder: list.map((e) => e.k),
    associations,
    variables,
    bodies,
  };
}

function recordAccess(rec: ReturnType<typeof actionRecord>) {
  return {
    state: acc(rec.state),
    set: acc(rec.set),
    reset: acc(rec.reset),
    stored: acc(rec.stored),
    setTime: acc(rec.setTime),
    resetTime: acc(rec.resetTime),
  };
}
