// JavaScript for an ST/IL body (one network holding one `st` operation), written through the
// network code emitter (compile/codegen.ts) so operands are parameters in the dispatch loops and
// literals in straight-line segments, exactly as for LD networks. The body is a labelled block
// (RETURN leaves it); loops are labelled `for (;;)` loops whose iterations ask the scanner, every
// 65,536 iterations, whether the scan has run too long (X.loop throws the watchdog fault, naming
// the POU and the line of the loop); IL's jumps run a `switch` over its labels inside a loop.
import type { ElementaryType, Value } from '../../model/iecTypes';
import type { ResolvedFunction } from '../library/fnTypes';
import type { Source } from '../compile/ir';
import { accessName, type Access } from '../compile/symbols';
import type { StOp, TExpr, TStmt } from './lowered';

/** What the ST code needs from the network emitter (compile/emitter.ts Emitter). */
export interface StEmitter {
  lines: string[];
  readonly depth: number;
  readonly pc: { readonly functions: readonly ResolvedFunction[]; readonly functionsUsed: Set<number> };
  p(int: number): string;
  constant(v: Value): string;
  argArray(n: number): string;
  fbRef(index: number): string;
  readValue(src: Source, to: ElementaryType): string;
  writeValue(a: Access, x: string, from: ElementaryType): string;
  /** Slot expression of an element chosen by variable indexes (set while an ST body is written). */
  elemSlot: (a: Extract<Access, { kind: 'elem' }>) => string;
}

/** Statement text running a body: written in place, or `X.call(first, end, now, scan);`. */
export type BodyWriter = (first: number, end: number) => string[];

/** Loop iterations between two checks of the scan time. */
const LOOP_CHECK = 0xffff;

interface Code {
  readonly pre: readonly string[];
  readonly code: string;
}

class StGen {
  private readonly d: number;
  private loopCount = 0;
  private readonly loops: { brk: string; cont: string }[] = [];
  private readonly block: string;
  private readonly machine: string;
  /**
   * Statement-level observation and stops (the step plan only, a generator): before each
   * statement `X.st(i, line); yield;` (the scanner records the line, and a step may pause there),
   * after each write `X.w(i, line, name, type, value)` (the value it left). `i` is the generator's network.
   */
  private readonly instrument: boolean;
  private line = 0;

  constructor(
    private readonly em: StEmitter,
    private readonly op: StOp,
    private readonly body: BodyWriter,
    instrument: boolean,
  ) {
    this.d = em.depth;
    this.block = `S${this.d}`;
    this.machine = `M${this.d}`;
    this.instrument = instrument;
  }

  /** Instrumented: the statement at `line` starts (recorded; a step may pause here). */
  private stop(line: number): string {
    this.line = line;
    return `X.st(i, ${line}); yield;`;
  }

  /** A write to `dst`, reported to the scanner after it in instrumented code. */
  private write(dst: Access, x: string, from: ElementaryType): string {
    const w = this.em.writeValue(dst, x, from);
    const name = this.instrument && dst.kind !== 'const' ? accessName(dst) : undefined;
    if (name === undefined) return w;
    const back = this.em.readValue({ from: 'access', access: dst }, dst.type);
    return `${w} X.w(i, ${this.line}, ${JSON.stringify(name)}, ${JSON.stringify(dst.type)}, ${back});`;
  }

  run(): string[] {
    const before = this.em.elemSlot;
    this.em.elemSlot = (a) => this.elemSlot(a);
    try {
      return this.body_();
    } finally {
      this.em.elemSlot = before;
    }
  }

  /**
   * `slot + X.ix(network, line, i, lower, upper, what) * mult + ...`: X.ix checks the bounds (a
   * runtime fault, LD-E62) and gives i - lower. Index expressions are plain values (no calls of
   * user functions, which need statements first).
   */
  private elemSlot(a: Extract<Access, { kind: 'elem' }>): string {
    const em = this.em;
    const parts = a.terms.map((t) => {
      const c = this.expr(t.index);
      if (c.pre.length) throw new Error(`${t.what}: an index calling a user FUNCTION is not supported`);
      const m = t.mult[a.v.store];
      const ix = `X.ix(${em.p(this.op.network)}, ${t.line}, ${c.code}, ${em.p(t.lower)}, ${em.p(t.upper)}, ${JSON.stringify(t.what)})`;
      return m === 1 ? ix : `${ix} * ${em.p(m)}`;
    });
    return `${em.p(a.v.slot)} + ${parts.join(' + ')}`;
  }

  private body_(): string[] {
    const out: string[] = [`${this.block}: {`];
    if (this.op.crSlots > 0) out.push(`let ${Array.from({ length: this.op.crSlots }, (_, i) => `c${this.d}_${i} = 0`).join(', ')};`);
    if (this.op.labels) {
      out.push(`let q${this.d} = 0, w${this.d} = 0;`, `${this.machine}: for (;;) { switch (q${this.d}) {`, 'case 0:');
      out.push(...this.stmts(this.op.body));
      out.push(`} break ${this.machine}; }`);
    } else out.push(...this.stmts(this.op.body));
    out.push('}');
    return out;
  }

  private watchdog(counter: string, line: number): string {
    return `if (++${counter} > ${LOOP_CHECK}) { ${counter} = 0; X.loop(${this.em.p(this.op.network)}, ${line}); }`;
  }

  private stmts(list: readonly TStmt[]): string[] {
    const out: string[] = [];
    for (const s of list) out.push(...this.stmt(s));
    return out;
  }

  private stmt(s: TStmt): string[] {
    const em = this.em;
    switch (s.k) {
      case 'assign': {
        const v = this.expr(s.value);
        return [...v.pre, this.write(s.dst, v.code, s.value.type)];
      }
      case 'eval': {
        const v = this.expr(s.value);
        return [...v.pre, `r = ${v.code};`];
      }
      case 'if': {
        const out: string[] = [];
        let close = 0;
        s.branches.forEach((b, i) => {
          // Instrumented: an ELSIF's condition is a stop of its own.
          const hook = i > 0 && this.instrument && b.line !== undefined ? [this.stop(b.line)] : [];
          const c = this.expr(b.cond);
          if (i === 0) out.push(...c.pre, `if (${c.code}) {`);
          else if (c.pre.length || hook.length) {
            out.push('} else {', ...hook, ...c.pre, `if (${c.code}) {`);
            close++;
          } else out.push(`} else if (${c.code}) {`);
          out.push(...this.stmts(b.body));
        });
        if (s.otherwise) out.push('} else {', ...this.stmts(s.otherwise));
        out.push('}'.repeat(close + 1));
        return out;
      }
      case 'case': {
        const sel = this.expr(s.selector);
        const v = `s${this.d}_${this.loopCount++}`;
        const out = [...sel.pre, `{ const ${v} = ${sel.code};`];
        s.arms.forEach((arm, i) => {
          const test = arm.labels
            .map((l) => (l.hi === undefined ? `${v} === ${em.constant(l.lo)}` : `(${v} >= ${em.constant(l.lo)} && ${v} <= ${em.constant(l.hi)})`))
            .join(' || ');
          out.push(`${i === 0 ? '' : '} else '}if (${test}) {`, ...this.stmts(arm.body));
        });
        if (s.otherwise) out.push(s.arms.length ? '} else {' : '{', ...this.stmts(s.otherwise));
        if (s.arms.length || s.otherwise) out.push('}');
        out.push('}');
        return out;
      }
      case 'for': {
        const k = this.loopCount++;
        const ctl: Source = { from: 'access', access: s.control };
        const from = this.expr(s.from);
        const out = [...from.pre, this.write(s.control, from.code, s.from.type)];
        const { brk, cont, w } = this.openLoop(k);
        const by = this.expr(s.by);
        const to = this.expr(s.to);
        const i = em.readValue(ctl, s.control.type);
        const b = `b${this.d}_${k}`;
        out.push(`let ${w} = 0;`, `${brk}: for (;;) {`, ...by.pre, ...to.pre);
        // As MATIEC writes it: the sign of BY (read on every iteration) picks the end test.
        if (s.by.k === 'const') {
          const positive = Number(s.by.value) > 0;
          out.push(`if (!(${i} ${positive ? '<=' : '>='} ${to.code})) break;`);
          out.push(`const ${b} = ${by.code};`);
        } else out.push(`const ${b} = ${by.code};`, `if (!(${b} > 0 ? ${i} <= ${to.code} : ${i} >= ${to.code})) break;`);
        out.push(this.watchdog(w, s.line), `${cont}: {`, ...this.stmts(s.body), '}');
        em.pc.functionsUsed.add(s.add);
        out.push(this.write(s.control, `Cfn${s.add}.impl2(ctx, ${em.readValue(ctl, s.control.type)}, ${b})`, s.control.type), '}');
        this.loops.pop();
        return out;
      }
      case 'while': {
        const k = this.loopCount++;
        const { brk, cont, w } = this.openLoop(k);
        const c = this.expr(s.cond);
        const out = [`let ${w} = 0;`, `${brk}: for (;;) {`, ...c.pre, `if (!(${c.code})) break;`, this.watchdog(w, s.line), `${cont}: {`, ...this.stmts(s.body), '}', '}'];
        this.loops.pop();
        return out;
      }
      case 'repeat': {
        const k = this.loopCount++;
        const { brk, cont, w } = this.openLoop(k);
        const body = this.stmts(s.body);
        const c = this.expr(s.until);
        this.loops.pop();
        return [`let ${w} = 0;`, `${brk}: for (;;) {`, this.watchdog(w, s.line), `${cont}: {`, ...body, '}', ...c.pre, `if (${c.code}) break;`, '}'];
      }
      case 'exit':
        return [`break ${this.loops[this.loops.length - 1]!.brk};`];
      case 'continue':
        return [`break ${this.loops[this.loops.length - 1]!.cont};`];
      case 'return':
        return [`break ${this.block};`];
      case 'fb': {
        const f = em.fbRef(s.fb);
        const out: string[] = [];
        for (const i of s.ins) {
          const v = this.expr(i.value);
          out.push(...v.pre, `${f}.${i.pin} = ${v.code};`);
        }
        out.push(`${f}.execute(now);`);
        for (const o of s.outs) out.push(this.write(o.dst, o.negated ? `!${f}.${o.pin}` : `${f}.${o.pin}`, o.type));
        return out;
      }
      case 'call':
        return this.call(s);
      case 'now':
        return [this.write(s.dst, 'now', 'TIME')];
      case 'setcr': {
        const v = this.expr(s.value);
        return [...v.pre, `c${this.d}_${s.slot} = ${v.code};`];
      }
      case 'label':
        return [`case ${s.id + 1}:`];
      case 'goto':
        return [`{ q${this.d} = ${s.id + 1}; ${s.back ? this.watchdog(`w${this.d}`, s.line) : ''} continue ${this.machine}; }`];
      case 'line':
        return this.instrument ? [this.stop(s.line)] : [];
    }
  }

  private openLoop(k: number): { brk: string; cont: string; w: string } {
    const l = { brk: `L${this.d}_${k}`, cont: `C${this.d}_${k}` };
    this.loops.push(l);
    return { ...l, w: `w${this.d}_${k}` };
  }

  private call(s: Extract<TStmt, { k: 'call' }>): string[] {
    const em = this.em;
    const out: string[] = [];
    for (const i of s.inits) out.push(em.writeValue(i.dst, em.constant(i.value), i.dst.type));
    for (const a of s.assigns) {
      const v = this.expr(a.value);
      out.push(...v.pre, em.writeValue(a.dst, v.code, a.value.type));
    }
    out.push(...this.body(s.first, s.end));
    for (const o of s.outs) {
      const v = em.readValue({ from: 'access', access: o.src }, o.dst.type);
      out.push(this.write(o.dst, o.negated ? `!${v}` : v, o.dst.type));
    }
    return out;
  }

  private expr(e: TExpr): Code {
    const em = this.em;
    switch (e.k) {
      case 'const':
        return { pre: [], code: em.constant(e.value) };
      case 'read':
        return { pre: [], code: em.readValue({ from: 'access', access: e.access }, e.type) };
      case 'cr':
        return { pre: [], code: `c${this.d}_${e.slot}` };
      case 'not': {
        const a = this.expr(e.a);
        return { pre: a.pre, code: `!${a.code}` };
      }
      case 'big': {
        const a = this.expr(e.a);
        return { pre: a.pre, code: `BigInt(${a.code})` };
      }
      case 'logic':
      case 'cmp': {
        const a = this.expr(e.a);
        const b = this.expr(e.b);
        const op = e.k === 'cmp' ? e.op : e.op === 'AND' ? '&&' : e.op === 'OR' ? '||' : '!==';
        return { pre: [...a.pre, ...b.pre], code: `(${a.code} ${op} ${b.code})` };
      }
      case 'pow': {
        const a = this.expr(e.a);
        const b = this.expr(e.b);
        const pow = `Math.pow(${a.code}, Number(${b.code}))`;
        return { pre: [...a.pre, ...b.pre], code: e.type === 'REAL' ? `Math.fround(${pow})` : pow };
      }
      case 'rdiv': {
        const a = this.expr(e.a);
        const b = this.expr(e.b);
        const q = `(${a.code} / ${b.code})`;
        return { pre: [...a.pre, ...b.pre], code: e.type === 'REAL' ? `Math.fround${q}` : q };
      }
      case 'seq': {
        const pre = this.stmts(e.pre);
        const v = this.expr(e.value);
        return { pre: [...pre, ...v.pre], code: v.code };
      }
      case 'fn': {
        em.pc.functionsUsed.add(e.fn);
        const f = `Cfn${e.fn}`;
        const resolved = em.pc.functions[e.fn]!;
        const args = e.args.map((a) => this.expr(a));
        const pre = args.flatMap((a) => a.pre);
        if (args.length === 1 && resolved.impl1) return { pre, code: `${f}.impl1(ctx, ${args[0]!.code})` };
        if (args.length === 2 && resolved.impl2) return { pre, code: `${f}.impl2(ctx, ${args[0]!.code}, ${args[1]!.code})` };
        const arr = em.argArray(args.length);
        return { pre: [...pre, ...args.map((a, i) => `${arr}[${i}] = ${a.code};`)], code: `${f}.impl(ctx, ${arr})` };
      }
    }
  }
}

/**
 * The statements of an ST/IL body, into `em.lines`; `instrument`: with the statement hooks (only
 * in the generators of the step plan, compile/dispatch.ts stepBody).
 */
export function emitSt(em: StEmitter, op: StOp, body: BodyWriter, instrument = false): void {
  em.lines.push(...new StGen(em, op, body, instrument).run());
}
