// Which box pins take an operand typed on the canvas, and the order Enter / Tab visit them.
import { describe, expect, test } from 'vitest';
import type { BoxElement } from '../../src/model/elements';
import { newProject } from '../../src/model/factory';
import type { Network } from '../../src/model/project';
import {
  firstField,
  INSTANCE_FIELD,
  nextField,
  openPins,
  pinSlots,
  tabStops,
} from '../../src/editor/canvas/pinOperands';
import { createDocumentStore, selectNetworks } from '../../src/store/documentStore';
import type { ElementTemplate } from '../../src/store/networkEdits';

/** A network drawn through the store, as the editor does. */
function draw(...steps: [row: number, col: number, t: ElementTemplate][]): { n: Network; box: BoxElement } {
  const store = createDocumentStore(newProject('p'));
  const net = selectNetworks(store.getState())[0]!.id;
  for (const [row, col, t] of steps) store.getState().placeElement(net, { row, col }, t);
  const n = selectNetworks(store.getState())[0]!;
  return { n, box: n.elements.find((e): e is BoxElement => e.kind === 'box')! };
}

const TON = (instance: string, inputs: Record<string, string> = {}): ElementTemplate => ({
  kind: 'box',
  blockType: 'TON',
  instance,
  inputs,
  outputs: {},
});
const coil: ElementTemplate = { kind: 'coil', coil: 'COIL', variable: 'Lamp' };

describe('pin operand fields', () => {
  test('a TON placed on the first column: IN is wired from the rail, PT, Q and ET take operands', () => {
    const { n, box } = draw([0, 0, TON('T1')]);
    expect(pinSlots(n, box).map((s) => `${s.side} ${s.pin}${s.wired ? ' wired' : ''}`)).toEqual([
      'input IN wired',
      'input PT',
      'output Q',
      'output ET',
    ]);
    expect([...openPins(n, box).inputs]).toEqual(['PT']);
  });

  test('an input with an operand is no longer drawn as ???', () => {
    const { n, box } = draw([0, 0, TON('T1', { PT: 'T#2s' })]);
    expect([...openPins(n, box).inputs]).toEqual([]);
  });

  test('an output joined to a coil is wired: Tab skips it', () => {
    const { n, box } = draw([0, 0, TON('T1')], [0, 3, coil]);
    expect(tabStops(n, box)).toEqual([INSTANCE_FIELD, 'PT', 'ET']);
  });

  test('Enter opens the unnamed instance first, then the first empty pin', () => {
    const unnamed = draw([0, 0, TON('')]);
    expect(firstField(unnamed.n, unnamed.box)).toBe(INSTANCE_FIELD);
    const named = draw([0, 0, TON('T1')]);
    expect(firstField(named.n, named.box)).toBe('PT');
    const preset = draw([0, 0, TON('T1', { PT: 'T#2s' })]);
    expect(firstField(preset.n, preset.box)).toBe('Q');
  });

  test('Tab goes instance → PT → Q → ET and wraps; Shift+Tab goes back', () => {
    const { n, box } = draw([0, 0, TON('T1')]);
    const order: string[] = [];
    let field: string | undefined = INSTANCE_FIELD;
    for (let i = 0; i < 5; i++) {
      field = nextField(n, box, field!, false);
      order.push(field!);
    }
    expect(order).toEqual(['PT', 'Q', 'ET', INSTANCE_FIELD, 'PT']);
    expect(nextField(n, box, 'PT', true)).toBe(INSTANCE_FIELD);
    expect(nextField(n, box, INSTANCE_FIELD, true)).toBe('ET');
  });

  test('a function has no instance field and never EN/ENO', () => {
    const { n, box } = draw([0, 0, { kind: 'box', blockType: 'ADD', inputs: {}, outputs: {} }]);
    expect(tabStops(n, box)).toEqual(['IN1', 'IN2', 'OUT']);
    expect(firstField(n, box)).toBe('IN1');
    expect([...openPins(n, box).inputs]).toEqual(['IN1', 'IN2']);
  });

  test('a box on the rail with every pin wired has no field to type', () => {
    const { n, box } = draw([0, 2, { kind: 'box', blockType: 'R_TRIG', instance: 'R1', inputs: {}, outputs: {} }]);
    // CLK is open here (nothing left of column 2), Q too.
    expect(tabStops(n, box)).toEqual([INSTANCE_FIELD, 'CLK', 'Q']);
    const wired = draw(
      [0, 0, { kind: 'box', blockType: 'R_TRIG', instance: 'R1', inputs: {}, outputs: {} }],
      [0, 3, coil],
    );
    expect(tabStops(wired.n, wired.box)).toEqual([INSTANCE_FIELD]);
  });
});
