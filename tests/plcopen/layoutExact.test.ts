// Issue 12 §1: the grid drawn for a PLCopen LD body means exactly the file's graph.
import { describe, expect, it } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { trace } from './behaviour';
import { fixture, run } from './fixtures';
import { CASES } from './layoutCases';
import { graphOf, ldXml, specGraph, type LdNetwork } from './ldXml';

describe('layout draws exactly the file (hand-written shapes)', () => {
  it.each(CASES)('$name: $about', ({ name, networks, connectors }) => {
    const r = importPlcopen(fixture(`layout-${name}.xml`));
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    // Wires the grid cannot route directly go through a connector/continuation pair (>C1>).
    const pairs = r.project.pous[0]!.networks.flatMap((n) => n.elements).filter((e) => e.kind === 'connector');
    expect(pairs.length > 0).toBe(connectors === true);
    expect(r.report.warnings.filter((w) => /cannot be drawn/.test(w.message))).toEqual([]);
    // A contact the import drew twice (a wire the grid cannot share) reads the same variable: one line.
    const twice = r.report.warnings.some((w) => /drawn twice/.test(w.message));
    const drawn = graphOf(r.project);
    expect(twice ? [...new Set(drawn)] : drawn).toEqual(specGraph(networks));
    const diags = checkProject(r.project).filter((d) => d.severity === 'error' || /R0[1-4]|R11/.test(d.rule));
    expect(diags.map((d) => `${d.rule} ${d.message}`)).toEqual([]);
    // Behaviour survives export and import again (the grid is read back as the same graph).
    const again = importPlcopen(exportPlcopen(r.project));
    if (!again.ok) throw new Error(JSON.stringify(again.errors));
    expect(graphOf(again.project)).toEqual(graphOf(r.project));
    expect(trace(again.project, 'Main', 100)).toEqual(trace(r.project, 'Main', 100));
  });

  it('nested OR: Q7 = I0 OR (I3 AND (I4 OR I5)) OR I6 on every input combination', () => {
    const r = importPlcopen(fixture('layout-nested-or.xml'));
    if (!r.ok) throw new Error('import');
    const plc = run(r.project, 'Main');
    for (let k = 0; k < 32; k++) {
      const [i0, i3, i4, i5, i6] = [0, 1, 2, 3, 4].map((b) => ((k >> b) & 1) === 1);
      plc.write('I0', i0!);
      plc.write('I3', i3!);
      plc.write('I4', i4!);
      plc.write('I5', i5!);
      plc.write('I6', i6!);
      plc.scan();
      expect(plc.read('Q7')).toBe(i0! || (i3! && (i4! || i5!)) || i6!);
    }
  });

  it('one output into two ORs: X := T1.Q OR B and Y := T1.Q OR C, scan by scan, and exported back so', () => {
    const r = importPlcopen(fixture('layout-output-into-two-ors.xml'));
    if (!r.ok) throw new Error('import');
    const check = (project: typeof r.project) => {
      const plc = run(project, 'Main');
      let differ = 0;
      for (let k = 0; k < 40; k++) {
        const [a, b, c] = [k % 8 < 5, k % 3 === 0, k % 5 === 1];
        plc.write('A', a);
        plc.write('B', b);
        plc.write('C', c);
        plc.scan();
        const q = plc.read('T1.Q') === true;
        expect([plc.read('X'), plc.read('Y')], `scan ${k + 1}`).toEqual([q || b, q || c]);
        if (plc.read('X') !== plc.read('Y')) differ++;
      }
      expect(differ).toBeGreaterThan(5);
    };
    check(r.project);
    // The export writes each coil's own OR (X: Q and B; Y: Q and C), through the connector pair.
    const xml = exportPlcopen(r.project);
    const again = importPlcopen(xml);
    if (!again.ok) throw new Error('re-import');
    expect(again.report.warnings.filter((w) => /cannot be drawn/.test(w.message))).toEqual([]);
    check(again.project);
  });

  it('CTUD: QU drives A and B, QD drives C, CV goes to Count only', () => {
    const r = importPlcopen(fixture('layout-ctud-outputs.xml'));
    if (!r.ok) throw new Error('import');
    const plc = run(r.project, 'Main');
    const pulse = (v: string) => {
      plc.write(v, true);
      plc.scan();
      plc.write(v, false);
      plc.scan();
    };
    plc.scan();
    expect([plc.read('A'), plc.read('B'), plc.read('C'), plc.read('Count')]).toEqual([false, false, true, 0]);
    for (let k = 0; k < 3; k++) pulse('Up');
    expect([plc.read('A'), plc.read('B'), plc.read('C'), plc.read('Count')]).toEqual([true, true, false, 3]);
  });
});

describe('the layout follows the file’s geometry', () => {
  it('elements on one y share a row, columns follow x, the OR branch sits below', () => {
    const net = {
      objects: [
        { id: 1, kind: 'contact', v: 'A', in: ['rail'] },
        { id: 2, kind: 'contact', v: 'B', in: ['1'] },
        { id: 3, kind: 'contact', v: 'C', in: ['rail'] },
        { id: 4, kind: 'contact', v: 'D', in: ['3'] },
        { id: 5, kind: 'coil', v: 'X', in: ['2', '4'] },
        { id: 6, kind: 'coil', v: 'Y', in: ['2', '4'] },
      ],
      toRail: [5, 6],
      pos: {
        1: { x: 50, y: 20 },
        2: { x: 120, y: 20 },
        3: { x: 50, y: 80 },
        4: { x: 120, y: 80 },
        5: { x: 400, y: 20 },
        6: { x: 400, y: 80 },
      },
    } satisfies LdNetwork;
    const r = importPlcopen(ldXml([...'ABCDXY'].map((name) => ({ name, type: 'BOOL' })), [net]));
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    expect(graphOf(r.project)).toEqual(specGraph([net]));
    const at = new Map(
      r.project.pous[0]!.networks[0]!.elements.flatMap((e) =>
        e.kind === 'contact' || e.kind === 'coil' ? [[e.variable, [e.row, e.col]] as const] : [],
      ),
    );
    const row = (v: string) => at.get(v)![0];
    const col = (v: string) => at.get(v)![1];
    expect([row('A'), row('B'), row('X')]).toEqual([0, 0, 0]);
    expect([row('C'), row('D'), row('Y')]).toEqual([1, 1, 1]);
    expect(col('A')).toBeLessThan(col('B'));
    expect(col('C')).toBeLessThan(col('D'));
    expect(col('X')).toBe(col('Y'));
  });
});
