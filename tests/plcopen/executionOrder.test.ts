// PLCopen executionOrderId (issue 12, LD-SEMANTICS.md section 6): the ids of blocks and of
// outVariables beside block outputs are kept by the import (BoxElement.executionOrder,
// outputOrders), run under the openplc profile as Beremiz's generator runs them (before every coil
// of the POU body, in id order), saved with the project, and written back by the export, so that
// export -> import runs the same.
import { describe, expect, test } from 'vitest';
import { withoutExecutionOrder, type BoxElement } from '../../src/model/elements';
import { loadProject, saveProject } from '../../src/model/load';
import type { Profile, Project } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { plcOf, trace } from '../engine/ladder';
import { ldXml, type LdNetwork } from './ldXml';

// Network 1: Seen := Edge.  Network 2: Pulse -> C1 (CTU, id 2); C1.CV -> INT_TO_REAL (id 1) -> R;
// Pulse -> RT (R_TRIG) -> Edge (an outVariable, id 3).
// The ST Beremiz generates (orderedInstances first, in id order, then coils and outVariables by position):
//   _TMP_INT_TO_REAL3_OUT := INT_TO_REAL(EN := TRUE, IN := C1.CV);   (* id 1: C1 not called yet *)
//   C1(CU := Pulse, PV := 100);                                      (* id 2 *)
//   RT(CLK := Pulse);  Edge := RT.Q;                                 (* id 3: the outVariable calls RT *)
//   Seen := Edge;
//   R := _TMP_INT_TO_REAL3_OUT;
const NETWORKS: LdNetwork[] = [
  {
    objects: [
      { id: 10, kind: 'contact', v: 'Edge', in: ['rail'] },
      { id: 11, kind: 'coil', v: 'Seen', in: ['10'] },
    ],
    toRail: [11],
    pos: { 10: { x: 50, y: 20 }, 11: { x: 300, y: 20 } },
  },
  {
    objects: [
      { id: 1, kind: 'contact', v: 'Pulse', in: ['rail'] },
      { id: 2, kind: 'block', type: 'CTU', instance: 'C1', inputs: { CU: ['1'], PV: ['=100'] }, outputs: ['Q', 'CV'], order: 2 },
      { id: 3, kind: 'block', type: 'INT_TO_REAL', inputs: { EN: ['rail'], IN: ['2.CV'] }, outputs: ['ENO', 'OUT'], assign: { OUT: 'R' }, order: 1 },
      { id: 4, kind: 'block', type: 'R_TRIG', instance: 'RT', inputs: { CLK: ['1'] }, outputs: ['Q'], assign: { Q: 'Edge' }, assignOrder: { Q: 3 } },
    ],
    pos: { 1: { x: 50, y: 120 }, 2: { x: 150, y: 110 }, 3: { x: 300, y: 130 }, 4: { x: 150, y: 220 } },
  },
];
const XML = ldXml(
  [
    { name: 'Pulse', type: 'BOOL' },
    { name: 'Edge', type: 'BOOL' },
    { name: 'Seen', type: 'BOOL' },
    { name: 'R', type: 'REAL' },
    { name: 'C1', type: 'CTU' },
    { name: 'RT', type: 'R_TRIG' },
  ],
  NETWORKS,
);

const STEPS = [{ Pulse: true }, { Pulse: false }, { Pulse: true }, { Pulse: false }];
const NAMES = ['C1.CV', 'R', 'Edge', 'Seen'];

function imported(xml: string): Project {
  const r = importPlcopen(xml);
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return r.project;
}
const run = (p: Project, profile: Profile) => trace(plcOf({ ...p, profile }), STEPS, NAMES);
const boxes = (p: Project) =>
  p.pous[0]!.networks.flatMap((n) => n.elements).filter((e): e is BoxElement => e.kind === 'box');
const stripped = (p: Project): Project => ({
  ...p,
  pous: p.pous.map((pou) => ({ ...pou, networks: pou.networks.map((n) => ({ ...n, elements: n.elements.map(withoutExecutionOrder) })) })),
});

describe('PLCopen executionOrderId: import, run, export, import again', () => {
  const project = imported(XML);

  test('a TC6 v2.01 file runs under openplc: its networks follow the drawing, the ids stay on the instances', () => {
    expect(project.profile).toBe('openplc');
    const coils = project.pous[0]!.networks.map((n) => n.elements.filter((e) => e.kind === 'coil').length);
    expect(coils).toEqual([1, 0]); // Seen's network, drawn first, stays first

    // Under another profile (a TC6 v2.0 file: CODESYS, TwinCAT) a network's smallest id still places it.
    const other = imported(XML.replace('http://www.plcopen.org/xml/tc6_0201', 'http://www.plcopen.org/xml/tc6_0200'));
    expect(other.profile).toBe('iec');
    expect(other.pous[0]!.networks.map((n) => n.elements.filter((e) => e.kind === 'coil').length)).toEqual([0, 1]);
  });

  test('the import keeps the ids on the boxes and on the variable beside RT.Q', () => {
    const orders = Object.fromEntries(boxes(project).map((b) => [b.blockType, [b.executionOrder, b.outputOrders]]));
    expect(orders).toEqual({ CTU: [2, undefined], INT_TO_REAL: [1, undefined], R_TRIG: [undefined, { Q: 3 }] });
  });

  test('under openplc the ordered instances run first, in id order; iec ignores the ids', () => {
    expect(run(project, 'openplc')).toEqual([
      [1, 0, 1, 1], // R read C1.CV before C1 counted; Edge written before Seen's coil reads it
      [1, 1, 0, 0],
      [2, 1, 1, 1],
      [2, 2, 0, 0],
    ]);
    // Without the ids: Seen reads Edge before RT runs, R follows C1.CV in the same scan.
    expect(run(stripped(project), 'openplc')).toEqual([
      [1, 1, 1, 0],
      [1, 1, 0, 1],
      [2, 2, 1, 0],
      [2, 2, 0, 1],
    ]);
    expect(run(project, 'iec')).toEqual(run(stripped(project), 'iec'));
  });

  test('the export writes the ids back, and the re-imported project runs the same', () => {
    const xml = exportPlcopen(project);
    expect(xml).toMatch(/<block [^>]*typeName="CTU"[^>]*executionOrderId="2"/);
    expect(xml).toMatch(/<block [^>]*typeName="INT_TO_REAL"[^>]*executionOrderId="1"/);
    expect(xml).toMatch(/<outVariable [^>]*executionOrderId="3"/);
    expect(xml).not.toMatch(/<block [^>]*typeName="R_TRIG"[^>]*executionOrderId/);
    const again = imported(xml);
    expect(boxes(again).map((b) => [b.blockType, b.executionOrder, b.outputOrders])).toEqual(
      boxes(project).map((b) => [b.blockType, b.executionOrder, b.outputOrders]),
    );
    for (const profile of ['openplc', 'iec'] as const) expect(run(again, profile)).toEqual(run(project, profile));
  });

  test('the ids are saved with the project and loaded back', () => {
    const loaded = loadProject(saveProject(project));
    if (!loaded.ok) throw new Error(JSON.stringify(loaded.errors));
    expect(boxes(loaded.project)).toEqual(boxes(project));
    expect(run(loaded.project, 'openplc')).toEqual(run(project, 'openplc'));
  });
});
