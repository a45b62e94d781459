// The factories of generated scan code kept by their text (src/engine/runtime/codeCache.ts): a new
// PLC whose code reads the same as one made before calls the same factory. What must hold: only
// the very same text gives the same factory (a near miss of the same length runs its own code),
// and PLCs made from one factory share code, never state.
import { describe, expect, test } from 'vitest';
import { planDispatch } from '../../src/engine/compile/dispatch';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { dispatchFactory, keptFactories } from '../../src/engine/runtime/codeCache';
import { bottleFillerProject } from '../../bench/bottleFiller';
import { ladder, project, vars } from './ladder';

function programOf(rows: string[]) {
  const { program, diagnostics } = compileProgram(project(vars('A BOOL', 'Q BOOL', 'R BOOL'), [ladder(rows)]));
  if (!program) throw new Error(JSON.stringify(diagnostics));
  return program;
}

const bodiesOf = (program: ReturnType<typeof programOf>) => planDispatch(program.networks, program.functions, program.symbols.fbs.map((f) => f.type)).bodies;

describe('generated code kept by its text', () => {
  test('the same text gives the same factory; another text, even of the same length, its own', () => {
    const body = 'return () => 1;';
    const again = ['return () => ', '1;'].join('');
    expect(dispatchFactory(again)).toBe(dispatchFactory(body));
    const near = 'return () => 2;';
    expect(near.length).toBe(body.length);
    expect(dispatchFactory(near)).not.toBe(dispatchFactory(body));
    expect((dispatchFactory(near)() as () => number)()).toBe(2);
    expect((dispatchFactory(body)() as () => number)()).toBe(1);
  });

  test('a normally open and a normally closed contact run their own code, whichever PLC was made first', () => {
    const open = programOf(['[A] (Q)']);
    const closed = programOf(['[/A] (Q)']);
    expect(bodiesOf(open)).not.toEqual(bodiesOf(closed));
    for (const order of [[open, closed], [closed, open]] as const) {
      const [first, second] = order.map((p) => createPlc(p, { cycleMs: 10 }));
      for (const plc of [first!, second!]) {
        plc.write('A', true);
        plc.scan();
      }
      const q = (p: typeof open) => (p === open ? 1 : 0);
      expect([first!.read('Q'), second!.read('Q')].map(Number)).toEqual([q(order[0]), q(order[1])]);
    }
  });

  test('two PLCs of one program share the code, not the state: the second starts cold and each scans its own inputs', () => {
    const p = bottleFillerProject(2);
    const { program } = compileProgram(p);
    const a = createPlc(program!, { cycleMs: 10 });
    const cold = a.values();
    const inputs = p.globals.filter((v) => v.type === 'BOOL' && (v.location ?? '').startsWith('%I')).map((v) => v.name);
    for (let k = 0; k < 40; k++) {
      inputs.forEach((name, i) => a.write(name, (k + i) % 3 !== 0));
      a.scan();
    }
    expect(a.values()).not.toEqual(cold);
    const kept = keptFactories();
    const b = createPlc(program!, { cycleMs: 10 });
    // Every function of b's code was found (nothing new made), and b starts at the initial values.
    expect(keptFactories()).toBe(kept);
    expect(b.values()).toEqual(cold);
    const before = a.values();
    for (let k = 0; k < 30; k++) {
      inputs.forEach((name) => b.write(name, k % 2 === 0));
      b.scan();
    }
    expect(a.values()).toEqual(before);
    expect(b.values()).not.toEqual(cold);
  });

  test('only a bounded amount of code is kept: the least recently used text goes first', () => {
    const chunk = `/*${'x'.repeat(1024 * 1024)}*/`;
    const first = dispatchFactory(`${chunk}return 'first';`);
    const recent = dispatchFactory(`${chunk}return 'recent';`);
    for (let i = 0; i < 20; i++) {
      dispatchFactory(`${chunk}return ${i};`);
      expect(dispatchFactory(`${chunk}return 'recent';`)).toBe(recent);
    }
    expect(keptFactories()).toBeLessThan(20);
    expect(dispatchFactory(`${chunk}return 'first';`)).not.toBe(first);
  });
});
