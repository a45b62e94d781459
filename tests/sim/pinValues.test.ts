// Values on box pins that no name reads (issue 24): the data lines between blocks, as the engine
// keeps them, carried in the session's frames and in a recorded scan's view, and the texts the
// canvas draws beside each pin (operands, literals, FB instance pins, data lines).
import { describe, expect, test } from 'vitest';
import { boxPinTexts } from '../../src/editor/sim/pinLiveValues';
import { blockLibrary } from '../../src/model/library';
import type { BoxElement } from '../../src/model/elements';
import type { Project } from '../../src/model/project';
import { createSimStore } from '../../src/store/simStore';
import { ladder, plcOf, project, vars } from '../engine/ladder';
import { SimHarness } from './harness';
import { loopback } from './loopback';

const lastOf = <T,>(xs: T[]): T => xs[xs.length - 1]!;

/**
 * Network 1: ADD(A, B) -> data line -> MOVE.IN, MOVE.OUT -> Sum. Network 2: TON T1 with PT the
 * variable Preset and IN from the rail; its ET feeds nothing (shown at the pin).
 */
function lineProject(): Project {
  return project(vars('A INT := 2', 'B INT := 3', 'Sum INT', 'Preset TIME := T#5s', 'T1 TON'), [
    ladder(['- # # - # #', '. # # - # #', '. # # . . .'], {
      boxes: [
        { row: 0, col: 1, type: 'ADD', inputs: { IN1: 'A', IN2: 'B' }, outputs: {} },
        { row: 0, col: 4, type: 'MOVE', inputs: {}, outputs: { OUT: 'Sum' } },
      ],
    }),
    ladder(['- # # .', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T1', inputs: { PT: 'Preset' }, outputs: {} }] }),
  ]);
}

const boxes = (p: Project) => p.pous[0]!.networks[0]!.elements.filter((e): e is BoxElement => e.kind === 'box');

describe('data lines on box pins', () => {
  test('the engine lists the line ADD.OUT -> MOVE.IN once per side and reads its value of the last scan', () => {
    const p = lineProject();
    const [add, move] = boxes(p);
    const elements = p.pous[0]!.networks[0]!.elements;
    const plc = plcOf(p);
    const lines = plc.probe!().pinLines(0, 2);
    const addOut = lines.lines.findIndex((l) => l.network === 0 && l.element === elements.indexOf(add!) && l.pin === 'OUT' && l.side === 'out');
    const moveIn = lines.lines.findIndex((l) => l.network === 0 && l.element === elements.indexOf(move!) && l.pin === 'IN' && l.side === 'in');
    expect(addOut).toBeGreaterThanOrEqual(0);
    expect(moveIn).toBeGreaterThanOrEqual(0);
    expect(lines.lines[moveIn]!.type).toBe('INT');
    const values: unknown[] = [];
    plc.scan();
    lines.read(values as never);
    expect(values[addOut]).toBe(5);
    expect(values[moveIn]).toBe(5);
    plc.write('A', 40);
    plc.scan();
    lines.read(values as never);
    expect(values[moveIn]).toBe(43);
  });

  test("frames carry the shown body's lines by box id; a recorded scan's view carries that scan's", () => {
    const p = lineProject();
    const [add, move] = boxes(p);
    const h = new SimHarness().send({ type: 'run', project: p }).advance(200);
    // The layout lists the inputs on data lines once; frames carry their values, aligned with it.
    const at = h.layout.pins!.findIndex((x) => x.element === move!.id && x.pin === 'IN');
    expect(h.layout.pins![at]).toEqual({ element: move!.id, pin: 'IN', type: 'INT' });
    expect(h.frame.pins[at]).toBe(5);
    // Pins given a variable are read by its name: no line is listed for them (ADD.IN1 = A, T1.PT = Preset).
    expect(h.layout.pins!.some((x) => x.element === add!.id)).toBe(false);
    expect(h.layout.pins!.some((x) => x.pin === 'PT')).toBe(false);
    const before = h.frame.scan;
    h.send({ type: 'write', name: 'A', input: { value: 40 } }).advance(100);
    expect(h.frame.pins[at]).toBe(43);
    h.send({ type: 'historySeek', scan: before });
    const view = lastOf(h.of('historyView')).view;
    expect(view.pins[at]).toBe(5);
  });

  test('the canvas texts: operands, the FB instance pins, the literal, the line into MOVE (formatted by type)', () => {
    const { transport, scheduler } = loopback();
    const store = createSimStore(transport);
    const s = () => store.getState();
    const p = lineProject();
    const lib = blockLibrary(p);
    s().run(p);
    scheduler.advance(200);
    const [add, move] = boxes(p);
    const n1 = p.pous[0]!.networks[0]!;
    const ton = p.pous[0]!.networks[1]!.elements.find((e): e is BoxElement => e.kind === 'box')!;
    expect(boxPinTexts(s(), n1, add!, lib)).toEqual({ inputs: { IN1: '2', IN2: '3' }, outputs: {} });
    expect(boxPinTexts(s(), n1, move!, lib)).toEqual({ inputs: { IN: '5' }, outputs: { OUT: '5' } });
    const tonTexts = boxPinTexts(s(), p.pous[0]!.networks[1]!, ton, lib)!;
    expect(tonTexts.inputs.PT).toBe('T#5s');
    expect(tonTexts.outputs.ET).toMatch(/^T#/);
    // A literal on an input shows as its pin's type writes it.
    const literal = { ...add!, inputs: { IN1: 'A', IN2: '16#0A' } };
    expect(boxPinTexts(s(), n1, literal, lib)?.inputs.IN2).toBe('10');
  });
});
