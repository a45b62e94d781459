// Random but valid PLCopen LD programs for the differential fuzzer (scripts/fuzz.ts, docs/fuzz.md).
// Everything follows from (seed, index): the same pair gives the same file, stimulus and watch list.
// The XML is written directly, with positions on every connection (Beremiz's generator needs them):
// each network sits in a band of its own, its outputs (coils, output variables) stacked downwards
// in file order, so the order Beremiz gives them (by y) is the order of the file.

export interface FuzzCase {
  readonly name: string;
  readonly xml: string;
  /** `scan,<inputs>` with one row per scan. */
  readonly stim: string;
  readonly watch: readonly string[];
  readonly scans: number;
  /** What the program contains (for the summary): network kinds and block types. */
  readonly features: readonly string[];
}

/** mulberry32 */
function rng(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

type Ty = 'BOOL' | 'INT' | 'DINT' | 'REAL' | 'WORD' | 'STRING' | 'TIME';

interface Pt {
  readonly id: number;
  readonly param?: string;
  readonly x: number;
  readonly y: number;
}

type Expr = { k: 'c'; v: string; kind: 'NO' | 'NC' | 'P' | 'N' } | { k: 's' | 'p'; a: Expr; b: Expr };

const xmlEsc = (s: string) =>
  s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

const typeXml = (t: string) =>
  t === 'STRING'
    ? '<string />'
    : /^[A-Z]+$/.test(t) &&
        !['TON', 'TOF', 'TP', 'CTU', 'CTD', 'CTUD', 'R_TRIG', 'F_TRIG', 'SR', 'RS'].includes(t)
      ? `<${t} />`
      : `<derived name="${t}" />`;

export interface Decl {
  readonly name: string;
  readonly type: string;
  readonly address?: string;
  readonly init?: string;
}

export const declXml = (d: Decl) =>
  `<variable name="${d.name}"${d.address ? ` address="${d.address}"` : ''}><type>${typeXml(d.type)}</type>${
    d.init !== undefined ? `<initialValue><simpleValue value="${xmlEsc(d.init)}" /></initialValue>` : ''
  }</variable>`;

/** One LD (or FBD-in-LD) body being written. */
export class Body {
  readonly parts: string[] = [];
  private next = 1;
  /** Lowest y the next output element may take (outputs strictly downwards, > 10 apart). */
  outY = 0;

  id(): number {
    return this.next++;
  }

  private conn(dst: { x: number; y: number }, srcs: readonly Pt[]): string {
    return srcs
      .map(
        (s) =>
          `<connection refLocalId="${s.id}"${s.param ? ` formalParameter="${s.param}"` : ''}><position x="${dst.x}" y="${dst.y}" /><position x="${s.x}" y="${s.y}" /></connection>`,
      )
      .join('');
  }

  rail(x: number, y: number): Pt {
    const id = this.id();
    this.parts.push(
      `<leftPowerRail localId="${id}" height="20" width="3"><position x="${x}" y="${y - 10}" /><connectionPointOut formalParameter=""><relPosition x="3" y="10" /></connectionPointOut></leftPowerRail>`,
    );
    return { id, x: x + 3, y };
  }

  rightRail(x: number, y: number, srcs: readonly Pt[]): void {
    const id = this.id();
    const h = Math.max(20, ...srcs.map((s) => s.y - y + 20));
    this.parts.push(
      `<rightPowerRail localId="${id}" height="${h}" width="3"><position x="${x}" y="${y - 10}" />${srcs
        .map(
          (s) =>
            `<connectionPointIn><relPosition x="0" y="${s.y - y + 10}" />${this.conn({ x, y: s.y }, [s])}</connectionPointIn>`,
        )
        .join('')}</rightPowerRail>`,
    );
  }

  contact(srcs: readonly Pt[], x: number, y: number, v: string, kind: 'NO' | 'NC' | 'P' | 'N'): Pt {
    const id = this.id();
    const attrs = `negated="${kind === 'NC'}"${kind === 'P' ? ' edge="rising"' : kind === 'N' ? ' edge="falling"' : ''}`;
    this.parts.push(
      `<contact localId="${id}" height="15" width="21" ${attrs}><position x="${x}" y="${y - 8}" /><connectionPointIn><relPosition x="0" y="8" />${this.conn(
        { x, y },
        srcs,
      )}</connectionPointIn><connectionPointOut><relPosition x="21" y="8" /></connectionPointOut><variable>${v}</variable></contact>`,
    );
    return { id, x: x + 21, y };
  }

  coil(srcs: readonly Pt[], x: number, y: number, v: string, kind: string): Pt {
    const id = this.id();
    const attrs =
      kind === 'NEG'
        ? 'negated="true"'
        : kind === 'S'
          ? 'negated="false" storage="set"'
          : kind === 'R'
            ? 'negated="false" storage="reset"'
            : kind === 'P'
              ? 'negated="false" edge="rising"'
              : kind === 'N'
                ? 'negated="false" edge="falling"'
                : 'negated="false"';
    this.parts.push(
      `<coil localId="${id}" height="20" width="21" ${attrs}><position x="${x}" y="${y - 10}" /><connectionPointIn><relPosition x="0" y="10" />${this.conn(
        { x, y },
        srcs,
      )}</connectionPointIn><connectionPointOut><relPosition x="21" y="10" /></connectionPointOut><variable>${v}</variable></coil>`,
    );
    return { id, x: x + 21, y };
  }

  inVar(x: number, y: number, expr: string): Pt {
    const id = this.id();
    this.parts.push(
      `<inVariable localId="${id}" height="20" width="80" negated="false"><position x="${x}" y="${y - 10}" /><connectionPointOut><relPosition x="80" y="10" /></connectionPointOut><expression>${xmlEsc(
        expr,
      )}</expression></inVariable>`,
    );
    return { id, x: x + 80, y };
  }

  outVar(src: Pt, x: number, y: number, expr: string): void {
    const id = this.id();
    this.parts.push(
      `<outVariable localId="${id}" height="20" width="80" negated="false"><position x="${x}" y="${y - 10}" /><connectionPointIn><relPosition x="0" y="10" />${this.conn(
        { x, y },
        [src],
      )}</connectionPointIn><expression>${xmlEsc(expr)}</expression></outVariable>`,
    );
  }

  /** A block with its pins 40 apart; `inputs` in pin order (null: the pin is drawn but unwired). */
  block(
    x: number,
    y: number,
    typeName: string,
    instance: string | undefined,
    inputs: ReadonlyArray<readonly [string, readonly Pt[] | null]>,
    outputs: readonly string[],
  ): Record<string, Pt> {
    const id = this.id();
    const n = Math.max(inputs.length, outputs.length);
    const ins = inputs
      .map(
        ([name, srcs], i) =>
          `<variable formalParameter="${name}"><connectionPointIn><relPosition x="0" y="${30 + 40 * i}" />${srcs ? this.conn({ x, y: y + 30 + 40 * i }, srcs) : ''}</connectionPointIn></variable>`,
      )
      .join('');
    const outs = outputs
      .map(
        (name, i) =>
          `<variable formalParameter="${name}"><connectionPointOut><relPosition x="100" y="${30 + 40 * i}" /></connectionPointOut></variable>`,
      )
      .join('');
    this.parts.push(
      `<block localId="${id}" width="100" height="${40 * n + 20}" typeName="${typeName}"${instance ? ` instanceName="${instance}"` : ''}><position x="${x}" y="${y}" /><inputVariables>${ins}</inputVariables><inOutVariables /><outputVariables>${outs}</outputVariables></block>`,
    );
    const pts: Record<string, Pt> = {};
    outputs.forEach((name, i) => (pts[name] = { id, param: name, x: x + 100, y: y + 30 + 40 * i }));
    return pts;
  }

  connector(src: Pt, x: number, y: number, name: string): void {
    const id = this.id();
    this.parts.push(
      `<connector localId="${id}" name="${name}" height="20" width="60"><position x="${x}" y="${y - 10}" /><connectionPointIn><relPosition x="0" y="10" />${this.conn(
        { x, y },
        [src],
      )}</connectionPointIn></connector>`,
    );
  }

  continuation(x: number, y: number, name: string): Pt {
    const id = this.id();
    this.parts.push(
      `<continuation localId="${id}" name="${name}" height="20" width="60"><position x="${x}" y="${y - 10}" /><connectionPointOut><relPosition x="60" y="10" /></connectionPointOut></continuation>`,
    );
    return { id, x: x + 60, y };
  }
}

const BOOL_IN = ['I0', 'I1', 'I2', 'I3', 'I4', 'I5'];
const INT_IN = ['W0', 'W1', 'W2'];
/** At least 1 (lengths and positions of STRING functions: MATIEC's DELETE with P < 0 crashes, its MID with P = 0 reads the length byte). */
const COUNT_IN = 'W3';
const NSCANS = 24;

const STD_FBS: Record<string, { ins: [string, Ty][]; outs: [string, Ty][] }> = {
  TON: {
    ins: [
      ['IN', 'BOOL'],
      ['PT', 'TIME'],
    ],
    outs: [
      ['Q', 'BOOL'],
      ['ET', 'TIME'],
    ],
  },
  TOF: {
    ins: [
      ['IN', 'BOOL'],
      ['PT', 'TIME'],
    ],
    outs: [
      ['Q', 'BOOL'],
      ['ET', 'TIME'],
    ],
  },
  TP: {
    ins: [
      ['IN', 'BOOL'],
      ['PT', 'TIME'],
    ],
    outs: [
      ['Q', 'BOOL'],
      ['ET', 'TIME'],
    ],
  },
  CTU: {
    ins: [
      ['CU', 'BOOL'],
      ['R', 'BOOL'],
      ['PV', 'INT'],
    ],
    outs: [
      ['Q', 'BOOL'],
      ['CV', 'INT'],
    ],
  },
  CTD: {
    ins: [
      ['CD', 'BOOL'],
      ['LD', 'BOOL'],
      ['PV', 'INT'],
    ],
    outs: [
      ['Q', 'BOOL'],
      ['CV', 'INT'],
    ],
  },
  CTUD: {
    ins: [
      ['CU', 'BOOL'],
      ['CD', 'BOOL'],
      ['R', 'BOOL'],
      ['LD', 'BOOL'],
      ['PV', 'INT'],
    ],
    outs: [
      ['QU', 'BOOL'],
      ['QD', 'BOOL'],
      ['CV', 'INT'],
    ],
  },
  R_TRIG: { ins: [['CLK', 'BOOL']], outs: [['Q', 'BOOL']] },
  F_TRIG: { ins: [['CLK', 'BOOL']], outs: [['Q', 'BOOL']] },
  SR: {
    ins: [
      ['S1', 'BOOL'],
      ['R', 'BOOL'],
    ],
    outs: [['Q1', 'BOOL']],
  },
  RS: {
    ins: [
      ['S', 'BOOL'],
      ['R1', 'BOOL'],
    ],
    outs: [['Q1', 'BOOL']],
  },
};

interface FnSpec {
  readonly ins: readonly [string, Ty][];
  readonly out: Ty;
}

/** Generic and string functions, instantiated at one type. */
function fnSpecs(): Record<string, FnSpec[]> {
  const num = (t: Ty): FnSpec => ({
    ins: [
      ['IN1', t],
      ['IN2', t],
    ],
    out: t,
  });
  const cmp = (t: Ty): FnSpec => ({
    ins: [
      ['IN1', t],
      ['IN2', t],
    ],
    out: 'BOOL',
  });
  const s: Ty = 'STRING';
  return {
    ADD: [
      num('INT'),
      num('DINT'),
      num('REAL'),
      {
        ins: [
          ['IN1', 'INT'],
          ['IN2', 'INT'],
          ['IN3', 'INT'],
        ],
        out: 'INT',
      },
    ],
    SUB: [num('INT'), num('DINT'), num('REAL')],
    MUL: [
      num('INT'),
      num('DINT'),
      num('REAL'),
      {
        ins: [
          ['IN1', 'DINT'],
          ['IN2', 'DINT'],
          ['IN3', 'DINT'],
        ],
        out: 'DINT',
      },
    ],
    DIV: [num('INT'), num('DINT'), num('REAL')],
    MOD: [num('INT'), num('DINT')],
    MAX: [num('INT'), num('REAL')],
    MIN: [num('INT'), num('DINT')],
    LIMIT: [
      {
        ins: [
          ['MN', 'INT'],
          ['IN', 'INT'],
          ['MX', 'INT'],
        ],
        out: 'INT',
      },
      {
        ins: [
          ['MN', 'REAL'],
          ['IN', 'REAL'],
          ['MX', 'REAL'],
        ],
        out: 'REAL',
      },
    ],
    SEL: [
      {
        ins: [
          ['G', 'BOOL'],
          ['IN0', 'INT'],
          ['IN1', 'INT'],
        ],
        out: 'INT',
      },
      {
        ins: [
          ['G', 'BOOL'],
          ['IN0', s],
          ['IN1', s],
        ],
        out: s,
      },
    ],
    MUX: [
      {
        ins: [
          ['K', 'INT'],
          ['IN0', 'INT'],
          ['IN1', 'INT'],
          ['IN2', 'INT'],
        ],
        out: 'INT',
      },
    ],
    GT: [cmp('INT'), cmp('REAL'), cmp(s)],
    GE: [cmp('INT'), cmp('DINT'), cmp(s)],
    EQ: [cmp('INT'), cmp(s)],
    NE: [cmp('INT'), cmp(s)],
    LE: [cmp('INT'), cmp('REAL')],
    LT: [cmp('INT'), cmp(s)],
    AND: [num('WORD'), num('BOOL')],
    OR: [num('WORD'), num('BOOL')],
    XOR: [num('WORD'), num('BOOL')],
    NOT: [
      { ins: [['IN', 'WORD']], out: 'WORD' },
      { ins: [['IN', 'BOOL']], out: 'BOOL' },
    ],
    SHL: [
      {
        ins: [
          ['IN', 'WORD'],
          ['N', 'INT'],
        ],
        out: 'WORD',
      },
    ],
    SHR: [
      {
        ins: [
          ['IN', 'WORD'],
          ['N', 'INT'],
        ],
        out: 'WORD',
      },
    ],
    ROL: [
      {
        ins: [
          ['IN', 'WORD'],
          ['N', 'INT'],
        ],
        out: 'WORD',
      },
    ],
    ROR: [
      {
        ins: [
          ['IN', 'WORD'],
          ['N', 'INT'],
        ],
        out: 'WORD',
      },
    ],
    INT_TO_REAL: [{ ins: [['IN', 'INT']], out: 'REAL' }],
    REAL_TO_INT: [{ ins: [['IN', 'REAL']], out: 'INT' }],
    INT_TO_DINT: [{ ins: [['IN', 'INT']], out: 'DINT' }],
    DINT_TO_INT: [{ ins: [['IN', 'DINT']], out: 'INT' }],
    INT_TO_WORD: [{ ins: [['IN', 'INT']], out: 'WORD' }],
    WORD_TO_INT: [{ ins: [['IN', 'WORD']], out: 'INT' }],
    BOOL_TO_INT: [{ ins: [['IN', 'BOOL']], out: 'INT' }],
    INT_TO_BOOL: [{ ins: [['IN', 'INT']], out: 'BOOL' }],
    INT_TO_STRING: [{ ins: [['IN', 'INT']], out: s }],
    STRING_TO_INT: [{ ins: [['IN', s]], out: 'INT' }],
    REAL_TO_STRING: [{ ins: [['IN', 'REAL']], out: s }],
    LEN: [{ ins: [['IN', s]], out: 'INT' }],
    LEFT: [
      {
        ins: [
          ['IN', s],
          ['L', 'INT'],
        ],
        out: s,
      },
    ],
    RIGHT: [
      {
        ins: [
          ['IN', s],
          ['L', 'INT'],
        ],
        out: s,
      },
    ],
    MID: [
      {
        ins: [
          ['IN', s],
          ['L', 'INT'],
          ['P', 'INT'],
        ],
        out: s,
      },
    ],
    CONCAT: [
      {
        ins: [
          ['IN1', s],
          ['IN2', s],
        ],
        out: s,
      },
    ],
    INSERT: [
      {
        ins: [
          ['IN1', s],
          ['IN2', s],
          ['P', 'INT'],
        ],
        out: s,
      },
    ],
    DELETE: [
      {
        ins: [
          ['IN', s],
          ['L', 'INT'],
          ['P', 'INT'],
        ],
        out: s,
      },
    ],
    REPLACE: [
      {
        ins: [
          ['IN1', s],
          ['IN2', s],
          ['L', 'INT'],
          ['P', 'INT'],
        ],
        out: s,
      },
    ],
    FIND: [
      {
        ins: [
          ['IN1', s],
          ['IN2', s],
        ],
        out: 'INT',
      },
    ],
  };
}
const FNS = fnSpecs();

/** A project with one program `main` (LD body) run by one 10 ms task, and the POUs it calls. */
export function projectXml(
  name: string,
  userPous: readonly string[],
  decls: readonly Decl[],
  body: Body,
): string {
  return `<?xml version='1.0' encoding='utf-8'?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="Rungsmith" productName="${name}" productVersion="1" creationDateTime="2026-11-28T00:00:00" />
  <contentHeader name="${name}" modificationDateTime="2026-11-28T00:00:00">
    <coordinateInfo><fbd><scaling x="10" y="10" /></fbd><ld><scaling x="10" y="10" /></ld><sfc><scaling x="10" y="10" /></sfc></coordinateInfo>
  </contentHeader>
  <types><dataTypes /><pous>
${userPous.join('\n')}
<pou name="main" pouType="program"><interface><localVars>${decls.map(declXml).join('')}</localVars></interface><body><LD>
${body.parts.join('\n')}
</LD></body></pou>
  </pous></types>
  <instances><configurations><configuration name="Config0"><resource name="Res0">
    <task name="task0" priority="0" interval="T#10ms"><pouInstance name="instance0" typeName="main" /></task>
  </resource></configuration></configurations></instances>
</project>
`;
}

export function generate(seed: number, index: number): FuzzCase {
  const r = rng((seed * 1000003 + index * 7919 + 17) >>> 0);
  const pick = <T>(xs: readonly T[]): T => xs[Math.floor(r() * xs.length)]!;
  const chance = (p: number) => r() < p;
  const int = (lo: number, hi: number) => lo + Math.floor(r() * (hi - lo + 1));
  const name = `s${seed}_${String(index).padStart(4, '0')}`;
  const features: string[] = [];

  const decls: Decl[] = [];
  const declared = new Set<string>();
  const declare = (d: Decl) => {
    if (!declared.has(d.name)) {
      declared.add(d.name);
      decls.push(d);
    }
  };
  BOOL_IN.forEach((v, i) => declare({ name: v, type: 'BOOL', address: `%IX0.${i}` }));
  INT_IN.forEach((v, i) => declare({ name: v, type: 'INT', address: `%IW${i}` }));
  declare({ name: COUNT_IN, type: 'INT', address: '%IW3' });
  declare({ name: 'D0', type: 'DINT' });
  declare({ name: 'R0', type: 'REAL' });
  declare({ name: 'R1', type: 'REAL', init: '2.5' });
  declare({ name: 'B0', type: 'WORD' });
  declare({ name: 'B1', type: 'WORD', init: '16#00F0' });
  const strInit = ["'abc'", "''", "'hello world'", "'ab'", "'12'", "'bcab'", "'x'", "'-7'"];
  declare({ name: 'S0', type: 'STRING', init: pick(strInit) });
  declare({ name: 'S1', type: 'STRING', init: pick(strInit) });
  const stimulated: { name: string; type: Ty }[] = [
    ...BOOL_IN.map((v) => ({ name: v, type: 'BOOL' as Ty })),
    ...INT_IN.map((v) => ({ name: v, type: 'INT' as Ty })),
    { name: COUNT_IN, type: 'INT' },
    { name: 'D0', type: 'DINT' },
    { name: 'R0', type: 'REAL' },
    { name: 'B0', type: 'WORD' },
  ];

  const watch: string[] = [];
  const written = (v: string) => {
    if (!watch.includes(v)) watch.push(v);
  };
  let outN = 0;
  const newOut = (t: Ty) => {
    const v = `${t === 'BOOL' ? 'X' : t === 'STRING' ? 'T' : 'V'}${outN++}`;
    declare({ name: v, type: t });
    written(v);
    return v;
  };
  const boolVars = () => [...BOOL_IN, ...watch.filter((w) => /^Q\d$/.test(w))];
  const sources: Record<Ty, () => string> = {
    BOOL: () => pick(boolVars()),
    INT: () => (chance(0.25) ? pick(['0', '1', '2', '3', '-1', '5', '7']) : pick(INT_IN)),
    DINT: () =>
      chance(0.3) ? pick(['0', '3', '-2', '100000']) : pick(['D0', 'D0', 'W0'].filter((v) => v !== 'W0')),
    REAL: () => (chance(0.3) ? pick(['0.5', '-1.25', '3.0', '0.0']) : pick(['R0', 'R1'])),
    WORD: () => (chance(0.3) ? pick(['16#0F0F', '16#8001', '16#0000']) : pick(['B0', 'B1'])),
    STRING: () =>
      chance(0.35) ? pick(["'ab'", "''", "'xyz'", "'b'", "'abcabc'", "'5'"]) : pick(['S0', 'S1']),
    TIME: () => pick(['T#30ms', 'T#50ms', 'T#100ms', 'T#0ms']),
  };

  const body = new Body();
  let y = 20;
  const outY = (want: number) => {
    const v = Math.max(want, body.outY);
    body.outY = v + 30;
    return v;
  };

  const randExpr = (depth: number): Expr => {
    if (depth <= 0 || chance(0.35)) {
      const kind = pick(['NO', 'NO', 'NO', 'NC', 'NC', 'P', 'N'] as const);
      return { k: 'c', v: pick(boolVars()), kind };
    }
    return { k: chance(0.55) ? 's' : 'p', a: randExpr(depth - 1), b: randExpr(depth - 1) };
  };
  /** Lays out an expression from `srcs` at column col, row y; returns outputs, width (columns), height (px). */
  const lay = (
    e: Expr,
    srcs: readonly Pt[],
    col: number,
    ry: number,
  ): { outs: Pt[]; w: number; h: number } => {
    if (e.k === 'c') return { outs: [body.contact(srcs, 60 + col * 50, ry, e.v, e.kind)], w: 1, h: 40 };
    const a = lay(e.a, srcs, col, ry);
    if (e.k === 's') {
      const b = lay(e.b, a.outs, col + a.w, ry);
      return { outs: b.outs, w: a.w + b.w, h: Math.max(a.h, b.h) };
    }
    const b = lay(e.b, srcs, col, ry + a.h);
    return { outs: [...a.outs, ...b.outs], w: Math.max(a.w, b.w), h: a.h + b.h };
  };
  /** A rail and an expression at row ry; returns its output points and the x after it. */
  const railExpr = (ry: number, depth: number, oneOut = false) => {
    const rail = body.rail(20, ry);
    const l = lay(randExpr(depth), [rail], 0, ry);
    if (oneOut && l.outs.length > 1) {
      // an OR ends the expression: a contact after the join gives one output (a connector fed by an
      // OR is pasted without brackets by Beremiz's generator, issue 23 class 14, LD-X06)
      const c = body.contact(l.outs, 60 + l.w * 50, ry, pick(BOOL_IN), 'NO');
      return { outs: [c], x: 60 + (l.w + 1) * 50, h: l.h };
    }
    return { outs: l.outs, x: 60 + l.w * 50, h: l.h };
  };
  const coilKind = () => pick(['', '', '', 'NEG', 'S', 'R', 'P', 'N']);
  const coilVar = () => {
    const v = `Q${int(0, 7)}`;
    declare({ name: v, type: 'BOOL' });
    written(v);
    return v;
  };

  /** Value source for a typed input pin at row py. */
  const valueSrc = (t: Ty, py: number, x: number): Pt[] => {
    if (t === 'BOOL') {
      const l = railExpr(py, 1);
      return l.outs;
    }
    return [body.inVar(x, py, sources[t]())];
  };

  const userPous: string[] = [];
  let fnCount = 0;
  let fbCount = 0;
  let instCount = 0;

  const logicNet = () => {
    features.push('logic');
    const l = railExpr(y, 3);
    const n = int(1, 3);
    const coils: Pt[] = [];
    let h = l.h;
    for (let i = 0; i < n; i++) {
      const cy = outY(y + i * 40);
      coils.push(body.coil(l.outs, Math.max(l.x + 60, 400), cy, coilVar(), coilKind()));
      h = Math.max(h, cy - y + 40);
    }
    body.rightRail(Math.max(l.x + 60, 400) + 60, y, coils);
    y += h + 40;
  };

  const stdFbNet = () => {
    const nfb = chance(0.4) ? 2 : 1;
    let prevOut: Pt | undefined;
    let x = 300;
    let h = 0;
    for (let k = 0; k < nfb; k++) {
      const type = pick(Object.keys(STD_FBS));
      features.push(type);
      const spec = STD_FBS[type]!;
      const inst = `FB${instCount++}`;
      declare({ name: inst, type });
      const wiredEn = chance(0.2);
      const ins: [string, Pt[] | null][] = [];
      let py = y + 30;
      if (wiredEn) {
        features.push('fb-en');
        ins.push(['EN', railExpr(py, 1).outs]);
        py += 40;
      }
      spec.ins.forEach(([pin, t], i) => {
        if (i === 0 && prevOut) ins.push([pin, [prevOut]]);
        else if (t === 'BOOL' && i > 0 && chance(0.3)) ins.push([pin, null]);
        else if (t === 'TIME' || t === 'INT')
          ins.push([
            pin,
            [body.inVar(x - 120, py, t === 'INT' ? pick(['3', '2', '5', 'W1']) : sources.TIME())],
          ]);
        else ins.push([pin, valueSrc(t, py, x - 120)]);
        py += 40;
      });
      const outs = [...(wiredEn ? ['ENO'] : []), ...spec.outs.map(([o]) => o)];
      const pts = body.block(x, y, type, inst, ins, outs);
      const chainNext = k + 1 < nfb;
      let first = true;
      for (const [o, t] of spec.outs) {
        const p = pts[o]!;
        if (first && chainNext) {
          prevOut = p;
          first = false;
          if (chance(0.6)) continue;
        }
        first = false;
        const oy = outY(p.y);
        if (t === 'BOOL') {
          const c = body.coil([p], x + 160, oy, coilVar(), chance(0.8) ? '' : coilKind());
          body.rightRail(x + 240, oy, [c]);
        } else body.outVar(p, x + 160, oy, newOut(t));
      }
      h = Math.max(h, py - y, body.outY - y);
      x += 300;
    }
    if (nfb === 2) features.push('fb-chain');
    y += h + 40;
  };

  const fnNet = () => {
    const nfn = chance(0.35) ? 2 : 1;
    let prev: { p: Pt; t: Ty } | undefined;
    let x = 300;
    let h = 0;
    for (let k = 0; k < nfn; k++) {
      let type = pick(Object.keys(FNS));
      let spec = pick(FNS[type]!);
      if (prev) {
        const fits = Object.entries(FNS)
          .filter(([n]) => n !== 'NOT') // Beremiz writes a chained NOT as NOT(IN := ...), which iec2c cannot parse
          .flatMap(([n, ss]) =>
            ss
              .filter((s) => s.ins.some(([pin, t]) => t === prev!.t && !['N', 'L', 'P'].includes(pin)))
              .map((s) => [n, s] as const),
          );
        if (fits.length === 0) break;
        [type, spec] = pick(fits);
      }
      features.push(type);
      // NOT with EN: Beremiz writes NOT(EN := ..., IN := ...), which iec2c cannot parse (NOT is a keyword)
      const en = chance(0.5) && type !== 'NOT' ? 'wired' : chance(0.5) && type !== 'NOT' ? 'open' : 'none';
      if (en !== 'none') features.push(`en-${en}`);
      const ins: [string, Pt[] | null][] = [];
      let py = y + 30;
      if (en === 'wired') {
        ins.push(['EN', railExpr(py, 1).outs]);
        py += 40;
      } else if (en === 'open') {
        ins.push(['EN', null]);
        py += 40;
      }
      let chained = false;
      const varIn = spec.ins.findIndex(([, t]) => t !== 'BOOL');
      spec.ins.forEach(([pin, t], i) => {
        // a shift count or a string position never comes from another block: negative shifts are
        // undefined in MATIEC's C (not emulated, docs/fuzz.md), negative positions crash it
        if (prev && !chained && t === prev.t && !['N', 'L', 'P'].includes(pin)) {
          ins.push([pin, [prev.p]]);
          chained = true;
        } else if (t !== 'BOOL' && i === varIn && !prev) {
          // at least one variable input, so that literals alone never decide the type
          const v = sources[t]();
          ins.push([
            pin,
            [
              body.inVar(
                x - 120,
                py,
                /^[A-Z]/.test(v)
                  ? v
                  : t === 'STRING'
                    ? 'S0'
                    : t === 'INT'
                      ? 'W0'
                      : t === 'DINT'
                        ? 'D0'
                        : t === 'REAL'
                          ? 'R0'
                          : 'B0',
              ),
            ],
          ]);
        } else if (pin === 'N') ins.push([pin, [body.inVar(x - 120, py, String(int(0, 5)))]]);
        else if (pin === 'P' || pin === 'L')
          ins.push([
            pin,
            [body.inVar(x - 120, py, chance(0.5) ? String(int(pin === 'P' ? 1 : 0, 4)) : COUNT_IN)],
          ]);
        else ins.push([pin, valueSrc(t, py, x - 120)]);
        py += 40;
      });
      const wantEno = en !== 'none' && chance(0.4);
      const pts = body.block(x, y, type, undefined, ins, [...(en !== 'none' ? ['ENO'] : []), 'OUT']);
      const last = k + 1 === nfn;
      if (!last && chance(0.5)) {
        // the output feeds the next function only
      } else {
        const oy = outY(pts.OUT!.y);
        if (spec.out === 'BOOL' && chance(0.5)) {
          const c = body.coil([pts.OUT!], x + 160, oy, coilVar(), '');
          body.rightRail(x + 240, oy, [c]);
        } else body.outVar(pts.OUT!, x + 160, oy, newOut(spec.out));
      }
      if (wantEno) {
        const oy = outY(pts.ENO!.y);
        const c = body.coil([pts.ENO!], x + 160, oy, coilVar(), '');
        body.rightRail(x + 240, oy, [c]);
      }
      prev = { p: pts.OUT!, t: spec.out };
      h = Math.max(h, py - y, body.outY - y);
      x += 300;
    }
    if (nfn === 2) features.push('fn-chain');
    y += h + 40;
  };

  const stExpr = (vars: string[]) => {
    const a = pick(vars);
    const b = pick(vars);
    return pick([
      `${a} + ${b}`,
      `${a} * 2 - ${b}`,
      `${a} / 3 + ${b} MOD 4`,
      `MAX(${a}, ${b})`,
      `ABS(${a} - ${b})`,
      `LIMIT(-5, ${a}, 20) + 1`,
    ]);
  };

  const userFnNet = () => {
    const isFb = chance(0.5);
    const ld = chance(0.35);
    const ins: [string, Pt[] | null][] = [];
    let py = y + 30;
    const en = chance(0.4) ? 'wired' : chance(0.5) ? 'open' : 'none';
    if (en === 'wired') {
      ins.push(['EN', railExpr(py, 1).outs]);
      py += 40;
    } else if (en === 'open') {
      ins.push(['EN', null]);
      py += 40;
    }
    if (en !== 'none') features.push(`user-en-${en}`);
    const x = 300;
    let pts: Record<string, Pt>;
    let outs: [string, Ty][];
    if (!isFb) {
      const fname = `UFn${fnCount++}`;
      features.push(ld ? 'user-fn-ld' : 'user-fn-st');
      if (ld) {
        // a BOOL function with an LD body: X AND NOT Y (or OR), result by a coil on the function's name
        const fb = new Body();
        const rail = fb.rail(20, 20);
        const c1 = fb.contact([rail], 60, 20, 'X', pick(['NO', 'NC'] as const));
        const c2 = chance(0.5) ? fb.contact([c1], 110, 20, 'Y', pick(['NO', 'NC'] as const)) : undefined;
        const c3 = c2 ? undefined : fb.contact([rail], 60, 60, 'Y', 'NO');
        const coil = fb.coil(c2 ? [c2] : [c1, c3!], 200, 20, fname, '');
        fb.rightRail(260, 20, [coil]);
        userPous.push(
          `<pou name="${fname}" pouType="function"><interface><returnType><BOOL /></returnType><inputVars>${declXml({ name: 'X', type: 'BOOL' })}${declXml(
            {
              name: 'Y',
              type: 'BOOL',
            },
          )}</inputVars></interface><body><LD>${fb.parts.join('\n')}</LD></body></pou>`,
        );
        ins.push(['X', railExpr(py, 1).outs]);
        py += 40;
        ins.push(['Y', railExpr(py, 0).outs]);
        py += 40;
        outs = [['OUT', 'BOOL']];
      } else {
        const st = chance(0.5)
          ? `${fname} := ${stExpr(['A', 'B'])};`
          : `IF A > B THEN\n  ${fname} := A - B;\nELSE\n  ${fname} := ${stExpr(['A', 'B'])};\nEND_IF;`;
        userPous.push(
          `<pou name="${fname}" pouType="function"><interface><returnType><INT /></returnType><inputVars>${declXml({ name: 'A', type: 'INT' })}${declXml(
            {
              name: 'B',
              type: 'INT',
            },
          )}</inputVars></interface><body><ST><xhtml:p><![CDATA[${st}]]></xhtml:p></ST></body></pou>`,
        );
        ins.push(['A', [body.inVar(x - 120, py, pick(INT_IN))]]);
        py += 40;
        ins.push(['B', [body.inVar(x - 120, py, sources.INT())]]);
        py += 40;
        outs = [['OUT', 'INT']];
      }
      pts = body.block(x, y, fname, undefined, ins, [
        ...(en !== 'none' ? ['ENO'] : []),
        ...outs.map(([o]) => o),
      ]);
    } else {
      const fbname = `UFb${fbCount++}`;
      const inst = `U${instCount++}`;
      declare({ name: inst, type: fbname });
      features.push(ld ? 'user-fb-ld' : 'user-fb-st');
      let bodyXml: string;
      if (ld) {
        const fb = new Body();
        const rail = fb.rail(20, 20);
        const c1 = fb.contact([rail], 60, 20, 'GO', pick(['NO', 'P', 'NC'] as const));
        const coil = fb.coil([c1], 200, 20, 'Q', pick(['', 'S', 'NEG']));
        const rail2 = fb.rail(20, 80);
        const c2 = fb.contact([rail2], 60, 80, 'STOP', 'NO');
        const coil2 = fb.coil([c2], 200, 80, 'Q', 'R');
        const rail3 = fb.rail(20, 140);
        const iv = fb.inVar(60, 180, 'V');
        const add = fb.block(
          160,
          140,
          'ADD',
          undefined,
          [
            ['EN', [rail3]],
            ['IN1', [iv]],
            ['IN2', [fb.inVar(60, 220, 'C')]],
          ],
          ['ENO', 'OUT'],
        );
        fb.outVar(add.OUT!, 300, 200, 'C');
        fb.rightRail(260, 20, [coil, coil2]);
        bodyXml = `<LD>${fb.parts.join('\n')}</LD>`;
      } else {
        const st = pick([
          `IF GO AND NOT prev THEN\n  C := C + V;\nEND_IF;\nprev := GO;\nIF STOP THEN C := 0; END_IF;\nQ := C > 6;`,
          `tim(IN := GO, PT := T#40ms);\nQ := tim.Q AND NOT STOP;\nC := ${stExpr(['V', 'C'])};\nIF C > 100 OR C < -100 THEN C := 0; END_IF;`,
          `C := ${stExpr(['V', 'C'])};\nIF ABS(C) > 50 THEN C := V; END_IF;\nQ := GO XOR STOP;`,
        ]);
        bodyXml = `<ST><xhtml:p><![CDATA[${st}]]></xhtml:p></ST>`;
      }
      userPous.push(
        `<pou name="${fbname}" pouType="functionBlock"><interface><inputVars>${declXml({ name: 'GO', type: 'BOOL' })}${declXml({ name: 'STOP', type: 'BOOL' })}${declXml(
          {
            name: 'V',
            type: 'INT',
          },
        )}</inputVars><outputVars>${declXml({ name: 'Q', type: 'BOOL' })}${declXml({ name: 'C', type: 'INT' })}</outputVars><localVars>${declXml(
          {
            name: 'prev',
            type: 'BOOL',
          },
        )}${declXml({ name: 'tim', type: 'TON' })}</localVars></interface><body>${bodyXml}</body></pou>`,
      );
      ins.push(['GO', railExpr(py, 1).outs]);
      py += 40;
      ins.push(['STOP', chance(0.3) ? null : railExpr(py, 0).outs]);
      py += 40;
      ins.push(['V', [body.inVar(x - 120, py, sources.INT())]]);
      py += 40;
      outs = [
        ['Q', 'BOOL'],
        ['C', 'INT'],
      ];
      pts = body.block(x, y, fbname, inst, ins, [...(en !== 'none' ? ['ENO'] : []), ...outs.map(([o]) => o)]);
    }
    for (const [o, t] of outs) {
      const p = pts[o]!;
      const oy = outY(p.y);
      if (t === 'BOOL') {
        const c = body.coil([p], x + 160, oy, coilVar(), '');
        body.rightRail(x + 240, oy, [c]);
      } else body.outVar(p, x + 160, oy, newOut(t));
    }
    if (en !== 'none' && chance(0.5)) {
      const oy = outY(pts.ENO!.y);
      const c = body.coil([pts.ENO!], x + 160, oy, coilVar(), '');
      body.rightRail(x + 240, oy, [c]);
    }
    y += Math.max(py - y, body.outY - y) + 40;
  };

  const connectorNet = () => {
    const cname = `CN${y}`;
    if (chance(0.6)) {
      features.push('connector-bool');
      const l = railExpr(y, 2, true);
      body.connector(l.outs[0]!, l.x + 20, y, cname);
      const cy = y + l.h + 20;
      const cont = body.continuation(40, cy, cname);
      const c = body.contact([cont], 140, cy, pick(boolVars()), pick(['NO', 'NC'] as const));
      const oy = outY(cy);
      const coil = body.coil([c], 300, oy, coilVar(), coilKind());
      body.rightRail(380, oy, [coil]);
      y = oy + 60;
    } else {
      features.push('connector-int');
      const a = body.inVar(40, y + 30, pick(INT_IN));
      const b = body.inVar(40, y + 70, sources.INT());
      const op = pick(['ADD', 'SUB', 'MAX', 'MUL']);
      const pts = body.block(
        160,
        y,
        op,
        undefined,
        [
          ['IN1', [a]],
          ['IN2', [b]],
        ],
        ['OUT'],
      );
      body.connector(pts.OUT!, 300, y + 30, cname);
      const cy = y + 120;
      const cont = body.continuation(40, cy, cname);
      const c2 = body.inVar(40, cy + 40, sources.INT());
      const op2 = pick(['ADD', 'MIN', 'SUB']);
      const p2 = body.block(
        160,
        cy - 30,
        op2,
        undefined,
        [
          ['IN1', [cont]],
          ['IN2', [c2]],
        ],
        ['OUT'],
      );
      const oy = outY(p2.OUT!.y);
      body.outVar(p2.OUT!, 320, oy, newOut('INT'));
      y = oy + 60;
    }
  };

  const nNets = int(2, 5);
  for (let i = 0; i < nNets; i++) {
    y = Math.max(y, body.outY) + 20;
    pick([logicNet, logicNet, stdFbNet, stdFbNet, fnNet, fnNet, fnNet, userFnNet, userFnNet, connectorNet])();
  }

  // stimulus: BOOL inputs toggle at random, numbers ramp (small ranges so that zero, negatives and
  // out-of-range indexes occur)
  const cols = stimulated;
  const ramps = cols.map(() => ({ step: int(1, 3), off: int(-6, 4), mod: int(5, 13) }));
  const lines = [`scan,${cols.map((c) => c.name).join(',')}`];
  const state = cols.map(() => 0);
  for (let k = 1; k <= NSCANS; k++) {
    const row = cols.map((c, j) => {
      if (c.type === 'BOOL') {
        if (chance(0.3)) state[j] = 1 - state[j]!;
        return state[j]!;
      }
      const g = ramps[j]!;
      const v = ((k * g.step) % g.mod) + (c.name === COUNT_IN ? 1 : g.off);
      return c.type === 'WORD' ? (v * 4099) & 0xffff : c.type === 'DINT' ? v * 1234 : v;
    });
    lines.push(`${k},${row.join(',')}`);
  }

  const xml = projectXml(name, userPous, decls, body);
  return { name, xml, stim: `${lines.join('\n')}\n`, watch, scans: NSCANS, features: [...new Set(features)] };
}
