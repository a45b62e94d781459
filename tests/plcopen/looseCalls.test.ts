// What Beremiz/OpenPLC files do that IEC is strict about, run as MATIEC runs the code those tools
// generate (LD-SEMANTICS.md section 9): a box whose type differs from its instance's declared type
// (LD-R10 warning), a typed integer literal of another type that fits (LD-W03), a VAR_EXTERNAL whose
// global is declared outside the file (LD-W16).
import { describe, expect, it } from 'vitest';
import { checkProject } from '../../src/engine/check';
import type { Plc } from '../../src/engine/api';
import type { Project } from '../../src/model/project';
import { readableNames } from '../../src/sim/layout';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import type { ImportReport } from '../../src/plcopen/types';
import { run } from './fixtures';
import { graphOf, ldXml, specGraph, type LdNetwork, type LdVar } from './ldXml';

function load(xml: string): { project: Project; report: ImportReport } {
  const r = importPlcopen(xml);
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return r;
}
/** One rising edge on A: a scan with A on, one with A off. */
function pulse(plc: Plc): void {
  plc.write('A', true);
  plc.scan();
  plc.write('A', false);
  plc.scan();
}
const found = (project: Project) => checkProject(project).map((d) => `${d.severity} ${d.rule} ${d.message}`);

describe('a box typed TP on an instance declared TOF (DS401GUI MAIN_TEST)', () => {
  const vars: LdVar[] = [
    { name: 'A', type: 'BOOL' },
    { name: 'Q', type: 'BOOL' },
    { name: 't1', type: 'TOF' },
  ];
  const nets: LdNetwork[] = [
    {
      objects: [
        { id: 1, kind: 'contact', v: 'A', in: ['rail'] },
        { id: 2, kind: 'block', type: 'TP', instance: 't1', inputs: { IN: ['1'], PT: ['=T#50ms'] }, outputs: ['Q', 'ET'] },
        { id: 3, kind: 'coil', v: 'Q', in: ['2.Q'] },
      ],
      toRail: [3],
    },
  ];
  const { project } = load(ldXml(vars, nets));

  it('keeps the file’s box and wiring, warns LD-R10 and nothing else', () => {
    expect(graphOf(project)).toEqual(specGraph(nets));
    const box = project.pous[0]!.networks[0]!.elements.find((e) => e.kind === 'box');
    expect(box).toMatchObject({ blockType: 'TP', instance: 't1' });
    expect(found(project)).toEqual([
      'warning LD-R10 the box says TP but t1 is declared TOF; Beremiz/OpenPLC call t1 as a TOF and so does the simulator',
    ]);
  });

  it('runs t1 as the TOF it is declared: Q stays on for PT after A falls (a TP would pulse)', () => {
    const plc = run(project, 'Main');
    const q: boolean[] = [];
    const scan = (a: boolean, n: number) => {
      plc.write('A', a);
      for (let i = 0; i < n; i++) {
        plc.scan();
        q.push(plc.read('Q') as boolean);
      }
    };
    scan(true, 10); // 100 ms on: a TP would have ended its 50 ms pulse
    scan(false, 8); // off-delay 50 ms
    expect(q).toEqual([...Array(10).fill(true), true, true, true, true, true, false, false, false]);
  });

  it('a box whose wired pins the declared type lacks stays an LD-R10 error', () => {
    const bad = load(
      ldXml(
        [...vars.slice(0, 2), { name: 't1', type: 'TON' }],
        [
          {
            objects: [
              { id: 1, kind: 'contact', v: 'A', in: ['rail'] },
              { id: 2, kind: 'block', type: 'CTU', instance: 't1', inputs: { CU: ['1'], PV: ['=3'] }, outputs: ['Q', 'CV'] },
              { id: 3, kind: 'coil', v: 'Q', in: ['2.Q'] },
            ],
            toRail: [3],
          },
        ],
      ),
    ).project;
    expect(found(bad).filter((d) => d.startsWith('error'))).toEqual([
      'error LD-R10 the CTU block "t1": "t1" is declared as TON, not CTU, and TON has no CU, PV as the box wires; make the box a TON or declare "t1" as CTU',
    ]);
  });
});

describe('a typed literal of another integer type (DS401GUI passes UINT#n to USINT inputs)', () => {
  const program = (pv: string) =>
    load(
      ldXml(
        [
          { name: 'A', type: 'BOOL' },
          { name: 'Q', type: 'BOOL' },
          { name: 'C', type: 'CTU' },
        ],
        [
          {
            objects: [
              { id: 1, kind: 'contact', v: 'A', in: ['rail'] },
              { id: 2, kind: 'block', type: 'CTU', instance: 'C', inputs: { CU: ['1'], PV: [`=${pv}`] }, outputs: ['Q', 'CV'] },
              { id: 3, kind: 'coil', v: 'Q', in: ['2.Q'] },
            ],
            toRail: [3],
          },
        ],
      ),
    ).project;

  it('that fits: LD-W03 saying Beremiz and OpenPLC refuse it, and the value is used', () => {
    const project = program('UINT#3');
    expect(found(project)).toEqual([
      'warning LD-W03 input PV of the CTU block "C": UINT#3 is typed UINT but the input is INT; its value 3 fits, so the simulator passes it, but Beremiz and OpenPLC refuse this; write 3 or INT#3',
    ]);
    const plc = run(project, 'Main');
    const q: boolean[] = [];
    for (let i = 0; i < 3; i++) {
      pulse(plc);
      q.push(plc.read('Q') as boolean);
    }
    expect(q).toEqual([false, false, true]);
    expect(plc.read('C.PV')).toBe(3);
  });

  it('that does not fit stays LD-E03', () => {
    expect(found(program('UDINT#40000')).filter((d) => d.startsWith('error'))).toEqual([
      'error LD-E03 input PV of the CTU block "C": UDINT#40000 is an UDINT, but INT is needed here',
    ]);
  });
});

describe('a VAR_EXTERNAL whose global is declared outside the file (OpenPLC Arduino_7_Segments)', () => {
  const xml = ldXml(
    [
      { name: 'A', type: 'BOOL' },
      { name: 'C', type: 'CTU' },
    ],
    [
      {
        objects: [
          { id: 1, kind: 'contact', v: 'A', in: ['rail'] },
          { id: 2, kind: 'block', type: 'CTU', instance: 'C', inputs: { CU: ['1'], PV: ['=100'] }, outputs: ['Q', 'CV'], assign: { CV: 'current_count' } },
        ],
        toRail: [2],
      },
    ],
  ).replace(
    '<interface><localVars>',
    '<interface><externalVars><variable name="current_count"><type><INT/></type><initialValue><simpleValue value="5"/></initialValue></variable></externalVars><localVars>',
  );
  const { project, report } = load(xml);

  it('the import report names it as a note, the check warns LD-W16, no error', () => {
    expect(report.notes.map((n) => n.message)).toEqual([
      'current_count is declared outside the file (VAR_EXTERNAL of Main); the simulator keeps it as a global INT, and export writes the file back without it',
    ]);
    expect(report.warnings.filter((w) => /current_count/.test(w.message))).toEqual([]);
    expect(found(project)).toEqual([
      'warning LD-W16 current_count is declared outside the project (VAR_EXTERNAL, no global of that name: MATIEC on its own refuses that, "the external variable does not match with any global variable", unless the build declares it, as OpenPLC\'s board builds do); the simulator keeps it as a global INT starting at 5, which you can write and force in the watch table',
    ]);
  });

  it('runs with it as a global: written by the program, listed, writable and forceable', () => {
    expect(readableNames(project, project.pous[0]!).find((v) => v.name === 'current_count')).toMatchObject({ type: 'INT' });
    const plc = run(project, 'Main');
    expect(plc.read('current_count')).toBe(5);
    for (let i = 0; i < 3; i++) pulse(plc);
    expect(plc.read('current_count')).toBe(3);
    plc.force('current_count', 42);
    plc.scan();
    expect(plc.read('current_count')).toBe(42);
  });

  it('exports the file as it was: the external kept, no global invented', () => {
    const out = exportPlcopen(project);
    expect(out).toMatch(/<externalVars>\s*<variable name="current_count">/);
    expect(out).not.toMatch(/<globalVars>/);
    const again = load(out);
    expect(again.project.globals).toEqual([]);
    expect(again.report.notes).toEqual(report.notes.map((n) => ({ ...n, line: again.report.notes[0]!.line })));
  });
});
