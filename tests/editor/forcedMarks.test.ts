// Which canvas elements are marked forced (issue 4: "forced values marked distinctly").
import { describe, expect, it } from 'vitest';
import { elementForced } from '../../src/editor/sim/useNetworkSim';
import type { LdElement } from '../../src/model/elements';
import type { ElementId } from '../../src/model/ids';
import type { SimState } from '../../src/store/simState';

const at = { row: 0, col: 0 };
const id = (s: string) => s as ElementId;
/** Only the forced map matters for the marks; names are kept upper-case like the store does. */
const state = (...names: string[]) => ({ forced: new Map(names.map((n) => [n.toUpperCase(), true])) }) as unknown as SimState;

const coil: LdElement = { id: id('c'), kind: 'coil', coil: 'COIL', variable: 'Motor', ...at };
const contact: LdElement = { id: id('k'), kind: 'contact', contact: 'NC', variable: 'motor', ...at };
const timer: LdElement = { id: id('t'), kind: 'box', blockType: 'TON', instance: 'T1', inputs: { IN: 'Start', PT: 'T#1s' }, outputs: {}, ...at };
const adder: LdElement = { id: id('a'), kind: 'box', blockType: 'ADD', inputs: { IN1: 'A', IN2: 'B' }, outputs: { OUT: 'Total' }, ...at };
const wire: LdElement = { id: id('w'), kind: 'link', ...at };

describe('forced marks on the canvas', () => {
  it('marks every contact and coil of a forced variable, whatever the case of its name', () => {
    expect(elementForced(state('Motor'), coil)).toBe(true);
    expect(elementForced(state('Motor'), contact)).toBe(true);
    expect(elementForced(state('Start'), coil)).toBe(false);
  });

  it('marks a function block when one of its outputs is forced, and a function when a variable its outputs drive is', () => {
    expect(elementForced(state('T1.Q'), timer)).toBe(true);
    expect(elementForced(state('Start'), timer)).toBe(false); // an input operand is not the block's value
    expect(elementForced(state('Total'), adder)).toBe(true);
    expect(elementForced(state('A'), adder)).toBe(false);
  });

  it('never marks wires, and nothing when no force is set', () => {
    expect(elementForced(state('Motor'), wire)).toBe(false);
    expect([coil, contact, timer, adder].some((el) => elementForced(state(), el))).toBe(false);
  });
});
