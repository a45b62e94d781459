// One cycle of a chart as MATIEC's generated C runs it (generate_c_sfc.cc), written as JavaScript
// over the chart's variables:
//   1. elapsed time since the last call; every active step's T grows by it, X is kept as prev;
//   2. every action's Q, set and reset are cleared; SD/DS/SL countdowns run (set or reset at 0);
//   3. transitions are tested in their order (PRIORITY first): a transition whose source steps are
//      all active takes its condition's value; one with a PRIORITY deactivates its sources at once;
//   4. the other firing transitions deactivate their sources, then every firing transition
//      activates its targets (X := TRUE, T := T#0s);
//   5. each step's associations, by qualifier (N, S, R, L, D, P, P0, P1, SL, SD, DS), using
//      active = X, activated = X AND NOT prev, deactivated = NOT X AND prev;
//   6. set stores an action, reset clears it; Q := Q OR stored;
//   7. BOOL variables used as actions: reset -> FALSE, else set -> TRUE; then each action body
//      whose Q is TRUE runs, in text order.
import type { StOp } from '../st/lowered';
import type { Access } from '../compile/symbols';
import { emitSt, type StEmitter } from '../st/emit';
import type { ChartIR, RangeIR } from './ir';

/** What the chart's code needs from compile/emitter.ts's Emitter (its ST pieces are written by st/emit.ts). */
export interface ChartEmitter extends StEmitter {
  readBit(a: Access): string;
  writeBit(a: Access, x: string): string;
  /** FB instances held in locals declared in the current block. */
  fbLocals: Map<number, string>;
}

export function emitChart(
  em: ChartEmitter,
  c: ChartIR,
  runBody: (range: RangeIR) => string[],
  lines: string[],
): void {
  const L = lines;
  const rd = (a: Access) => em.readValue({ from: 'access', access: a }, 'TIME');
  const wr = (a: Access, x: string) => em.writeValue(a, x, 'TIME');
  const bit = (a: Access) => em.readBit(a);
  const set = (a: Access, x: string) => em.writeBit(a, x);
  // Each ST piece sits in a block of its own: the locals it declares for FB instances stay in it.
  const st = (op: StOp) => {
    const saved = { lines: em.lines, fbLocals: em.fbLocals };
    em.lines = [];
    em.fbLocals = new Map();
    emitSt(em, op, (first, end) => runBody({ first, end }));
    L.push('{', ...em.lines, '}');
    em.lines = saved.lines;
    em.fbLocals = saved.fbLocals;
  };
  L.push(`{ // SFC ${c.pou}`);
  L.push(`const el$ = now - ${rd(c.lasttick)}; ${wr(c.lasttick, 'now')}`);
  // 1. steps
  for (const s of c.steps) L.push(set(s.prev, bit(s.x)), `if (${bit(s.x)}) { ${wr(s.t, `${rd(s.t)} + el$`)} }`);
  // 2. actions
  for (const a of c.actions) {
    L.push(set(a.state, '0'), set(a.set, '0'), set(a.reset, '0'));
    for (const [time, flag] of [
      [a.setTime, a.set],
      [a.resetTime, a.reset],
    ] as const)
      L.push(
        `if (${rd(time)} > 0) { ${wr(time, `${rd(time)} - el$`)} if (${rd(time)} <= 0) { ${wr(time, '0')} ${set(flag, '1')} } }`,
      );
  }
  // 3. transition tests
  for (const k of c.testOrder) {
    const t = c.transitions[k]!;
    const active = t.from.map((s) => bit(c.steps[s]!.x)).join(' & ') || '0';
    L.push(`if (${active}) {`);
    if ('st' in t.condition) st(t.condition.st);
    else {
      L.push(...runBody(t.condition.range));
      L.push(set(t.flag, bit(t.condition.result)));
    }
    if (t.priority) L.push(`if (${bit(t.flag)}) { ${t.from.map((s) => set(c.steps[s]!.x, '0')).join(' ')} }`);
    L.push(`} else { ${set(t.flag, '0')} }`);
  }
  // 4. deactivate, then activate
  for (const t of c.transitions)
    if (!t.priority && t.from.length)
      L.push(`if (${bit(t.flag)}) { ${t.from.map((s) => set(c.steps[s]!.x, '0')).join(' ')} }`);
  for (const t of c.transitions)
    if (t.to.length)
      L.push(
        `if (${bit(t.flag)}) { ${t.to.map((s) => `${set(c.steps[s]!.x, '1')} ${wr(c.steps[s]!.t, '0')}`).join(' ')} }`,
      );
  // 5. associations
  let open = -1;
  const close = () => {
    if (open >= 0) L.push('}');
  };
  for (const as of c.associations) {
    if (as.step !== open) {
      close();
      open = as.step;
      const s = c.steps[as.step]!;
      L.push(`{ const a$ = ${bit(s.x)}; const on$ = a$ & (${bit(s.prev)} ^ 1); const off$ = (a$ ^ 1) & ${bit(s.prev)};`);
    }
    const act = c.actions[as.action]!;
    const out = (v: '0' | '1') => (act.variable ? set(act.variable, v) : set(act.state, v));
    const time = em.constant(as.time);
    const T = rd(c.steps[as.step]!.t);
    switch (as.qualifier) {
      case 'N':
        L.push(`if (a$) { ${out('1')} }`, `if (off$) { ${out('0')} }`);
        break;
      case 'S':
        L.push(`if (a$) { ${set(act.set, '1')} }`);
        break;
      case 'R':
        L.push(`if (a$) { ${set(act.reset, '1')} }`);
        break;
      case 'L':
        L.push(`if (a$ && ${T} < ${time}) { ${out('1')} } else if (off$ || a$) { ${out('0')} }`);
        break;
      case 'D':
        L.push(`if (a$ && ${T} >= ${time}) { ${out('1')} } else if (off$) { ${out('0')} }`);
        break;
      case 'P':
      case 'P1':
        L.push(`if (on$) { ${out('1')} } else { ${out('0')} }`);
        break;
      case 'P0':
        L.push(`if (off$) { ${out('1')} } else { ${out('0')} }`);
        break;
      case 'SL':
        L.push(`if (on$) { ${set(act.set, '1')} ${wr(act.resetTime, time)} }`);
        break;
      case 'SD':
      case 'DS':
        L.push(`if (on$) { ${wr(act.setTime, time)} }`);
        if (as.qualifier === 'DS') L.push(`if (off$) { ${wr(act.setTime, '0')} }`);
        break;
    }
  }
  close();
  // 6. stored actions
  for (const a of c.actions)
    L.push(
      `if (${bit(a.set)}) { ${wr(a.setTime, '0')} ${set(a.stored, '1')} }`,
      `if (${bit(a.reset)}) { ${wr(a.resetTime, '0')} ${set(a.stored, '0')} }`,
      set(a.state, `${bit(a.state)} | ${bit(a.stored)}`),
    );
  // 7. variables, then bodies
  for (const k of c.variables) {
    const a = c.actions[k]!;
    L.push(`if (${bit(a.reset)}) { ${set(a.variable!, '0')} } else if (${bit(a.set)}) { ${set(a.variable!, '1')} }`);
  }
  for (const k of c.bodies) {
    const a = c.actions[k]!;
    L.push(`if (${bit(a.state)}) {`);
    if (a.body && 'range' in a.body) L.push(...runBody(a.body.range));
    else if (a.body) st(a.body.st);
    L.push('}');
  }
  L.push('}');
}
