// A hand-drawn fan-out into an OR (one-way vertical links, LD-SEMANTICS section 1) exports as the
// grid means it: coil X wired from contact A only, coil Y from A and B; read back, it is drawn
// and runs the same.
import { describe, expect, it } from 'vitest';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { ladder, project, vars } from '../engine/ladder';
import { trace } from './behaviour';
import { graphOf } from './ldXml';

describe('export of one-way vertical links', () => {
  it('X gets A only and Y gets A OR B, in the file and after reading it back', () => {
    // |--[A]--+------( X )
    // |       +--+---( Y )
    // |--+[B]----+
    const p = project(vars('A BOOL', 'B BOOL', 'X BOOL', 'Y BOOL'), [
      ladder(['[A] + - (X)', '. + - + (Y)', '- [B] + .']),
    ]);
    const drawn = graphOf(p);
    expect(drawn).toEqual([
      'coil:COIL:X.IN <- contact:NO:A.OUT',
      'coil:COIL:Y.IN <- contact:NO:A.OUT',
      'coil:COIL:Y.IN <- contact:NO:B.OUT',
      'contact:NO:A.IN <- rail',
      'contact:NO:B.IN <- rail',
    ]);
    const xml = exportPlcopen(p);
    // Coil X's input is wired from one element, Y's from two.
    const coilIn = (v: string) => {
      const m = new RegExp(`<coil [^>]*>(?:(?!</coil>).)*?<variable>${v}</variable>`, 's').exec(xml);
      return [...(m?.[0].matchAll(/<connection refLocalId/g) ?? [])].length;
    };
    expect([coilIn('X'), coilIn('Y')]).toEqual([1, 2]);
    const back = importPlcopen(xml);
    if (!back.ok) throw new Error(JSON.stringify(back.errors));
    expect(back.report.warnings.filter((w) => /cannot be drawn/.test(w.message))).toEqual([]);
    // The import may draw contact A once per coil ("drawn twice"): the same wires.
    expect([...new Set(graphOf(back.project))]).toEqual(drawn);
    expect(trace(back.project, 'Main', 40)).toEqual(trace(p, 'Main', 40));
  });
});
