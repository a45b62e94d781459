// An output pin with neither a wire nor an operand shows the same `???` as an open input, except
// the BOOL output that carries the power flow on (ENO, else the first BOOL output) and in-out pins.
import { describe, expect, test } from 'vitest';
import { networkColumns } from '../../src/editor/canvas/columns';
import { openPins } from '../../src/editor/canvas/pinOperands';
import type { BoxElement } from '../../src/model/elements';
import { newPou, newProject, variable } from '../../src/model/factory';
import { blockLibrary, type BlockLibrary } from '../../src/model/library';
import type { Network } from '../../src/model/project';
import { createDocumentStore, selectNetworks } from '../../src/store/documentStore';
import type { ElementTemplate } from '../../src/store/networkEdits';

function draw(steps: [row: number, col: number, t: ElementTemplate][]): { n: Network; box: BoxElement } {
  const store = createDocumentStore(newProject('p'));
  const net = selectNetworks(store.getState())[0]!.id;
  for (const [row, col, t] of steps) store.getState().placeElement(net, { row, col }, t);
  const n = selectNetworks(store.getState())[0]!;
  return { n, box: n.elements.find((e): e is BoxElement => e.kind === 'box')! };
}

const box = (blockType: string, extra: Partial<BoxElement> = {}): ElementTemplate =>
  ({ kind: 'box', blockType, inputs: {}, outputs: {}, ...extra }) as ElementTemplate;
const coil: ElementTemplate = { kind: 'coil', coil: 'COIL', variable: 'Lamp' };
const outs = (n: Network, b: BoxElement, lib?: BlockLibrary) => [...openPins(n, b, lib).outputs];

describe('??? on open outputs', () => {
  test('TON: ET shows ???, Q (the power flow) does not', () => {
    const { n, box: b } = draw([[0, 0, box('TON', { instance: 'T1' })]]);
    expect(outs(n, b)).toEqual(['ET']);
  });

  test('ADD: OUT shows ???, ENO never', () => {
    const { n, box: b } = draw([[0, 0, box('ADD')]]);
    expect(outs(n, b)).toEqual(['OUT']);
  });

  test('a BOOL output of a function is marked: the power flow goes on through ENO', () => {
    const { n, box: b } = draw([[0, 0, box('GT')]]);
    expect(outs(n, b)).toEqual(['OUT']);
  });

  test('an FB with EN/ENO: its Q is marked, ENO is not', () => {
    const { n, box: b } = draw([[0, 0, box('TON', { instance: 'T1', executionControl: true })]]);
    expect(outs(n, b)).toEqual(['Q', 'ET']);
  });

  test('an output with an operand or joined to a coil is not marked', () => {
    const named = draw([[0, 0, box('TON', { instance: 'T1', outputs: { ET: 'Elapsed' } })]]);
    expect(outs(named.n, named.box)).toEqual([]);
    const add = draw([
      [0, 0, box('ADD')],
      [0, 3, coil],
    ]);
    // ADD's ENO goes on to the coil; OUT (row 1) is still open.
    expect(outs(add.n, add.box)).toEqual(['OUT']);
  });

  test('the ??? takes room in the column right of the box, as on the input side', () => {
    const open = draw([[0, 0, box('ADD')]]);
    const named = draw([[0, 0, box('ADD', { outputs: { OUT: 'X' } })]]);
    const right = (n: Network) => {
      const nc = networkColumns(n);
      return nc.xs[3]! - nc.xs[2]!;
    };
    // "???" is wider than "X": the open box's last column is wider.
    expect(right(open.n)).toBeGreaterThan(right(named.n));
  });

  test('an in-out pin of a user block is not marked on its output side', () => {
    const fb = newPou('Scale', {
      kind: 'FUNCTION_BLOCK',
      variables: [
        variable('Go', 'BOOL', { varClass: 'input' }),
        variable('Buf', 'INT', { varClass: 'inOut' }),
        variable('Done', 'BOOL', { varClass: 'output' }),
        variable('Count', 'INT', { varClass: 'output' }),
      ],
    });
    const project = newProject('p', { pous: [newPou('Main'), fb] });
    const lib = blockLibrary(project);
    const store = createDocumentStore(project);
    const net = selectNetworks(store.getState())[0]!.id;
    store.getState().placeElement(net, { row: 0, col: 0 }, box('Scale', { instance: 'S1' }));
    const n = selectNetworks(store.getState())[0]!;
    const b = n.elements.find((e): e is BoxElement => e.kind === 'box')!;
    expect(outs(n, b, lib)).toEqual(['Count']);
    expect([...openPins(n, b, lib).inputs]).toEqual(['Buf']);
  });
});
