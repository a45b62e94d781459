// Names that resolve elsewhere (issue 12 section 3): globals of the configuration and its resources,
// VAR_EXTERNAL declarations naming them, and MATIEC's typed counters. Each fixture imports without
// false diagnostics, keeps every element, runs as MATIEC would and survives export → import.
import { describe, expect, it } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { trace } from '../engine/ladder';
import { validateProject } from '../../src/model/load';
import type { Project } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { connections, trace as randomTrace } from './behaviour';
import { canonical, imported, run } from './fixtures';


function roundTrip(project: Project): Project {
  const again = importPlcopen(exportPlcopen(project, { now: new Date('2026-01-01T00:00:00Z') }));
  if (!again.ok) throw new Error(JSON.stringify(again.errors));
  expect(again.report.warnings).toEqual([]);
  return again.project;
}

const elementKinds = (p: Project) =>
  p.pous.map((pou) => [
    pou.name,
    pou.networks.flatMap((n) =>
      n.elements
        .filter((e) => e.kind !== 'link')
        .map((e) =>
          e.kind === 'box'
            ? `${e.blockType} ${e.instance ?? ''} ${JSON.stringify(e.inputs)} ${JSON.stringify(e.outputs)}`
            : `${e.kind} ${'variable' in e ? e.variable : ''}`,
        )
        .sort(),
    ),
  ]);

describe('configuration and resource globals, used through VAR_EXTERNAL', () => {
  const { project, report } = imported('names-globals.xml');

  it('imports the globals with location, type, initial value, CONSTANT, RETAIN and where they were declared', () => {
    expect(report.warnings).toEqual([]);
    expect(project.globals).toEqual([
      {
        name: 'Limit',
        type: 'INT',
        varClass: 'local',
        initial: '3',
        retain: false,
        constant: true,
        comment: 'counter limit',
      },
      {
        name: 'Lamp',
        type: 'BOOL',
        varClass: 'local',
        location: '%QX0.0',
        retain: false,
        comment: '',
        scope: 'resource',
      },
      { name: 'Count', type: 'INT', varClass: 'local', retain: false, comment: '', scope: 'resource' },
      {
        name: 'Total',
        type: 'DINT',
        varClass: 'local',
        initial: '100',
        retain: true,
        comment: '',
        scope: 'resource',
      },
    ]);
    expect(validateProject(JSON.parse(JSON.stringify(project))).ok).toBe(true);
  });

  it('has no diagnostics and drops nothing', () => {
    expect(checkProject(project)).toEqual([]);
    expect(elementKinds(project)).toEqual([
      [
        'Main',
        ['CTU C1 {"PV":"Limit"} {"CV":"Count"}', 'coil Lamp', 'contact Clear', 'contact Pulse'].sort(),
      ],
      ['Tally', ['ADD  {"IN1":"Total","IN2":"1"} {"OUT":"Total"}', 'contact Lamp'].sort()],
    ]);
  });

  it('Main counts to the configuration constant and lights the resource global at %QX0.0', () => {
    const plc = run(project, 'Main');
    const on = { Pulse: true };
    const off = { Pulse: false };
    expect(trace(plc, [on, off, on, off, on, off, { Clear: true }], ['Count', 'Lamp', '%QX0.0'])).toEqual([
      [1, 0, 0],
      [1, 0, 0],
      [2, 0, 0],
      [2, 0, 0],
      [3, 1, 1],
      [3, 1, 1],
      [0, 0, 0],
    ]);
  });

  it('Tally adds to the RETAIN global (initial 100) while the global Lamp is ON', () => {
    const plc = run(project, 'Tally');
    expect(trace(plc, [{}, { Lamp: true }, {}, { Lamp: false }], ['Total'])).toEqual([
      [100],
      [101],
      [102],
      [102],
    ]);
  });

  it('export puts each global back in its resource or configuration, and the round trip is exact', () => {
    const xml = exportPlcopen(project);
    const resource = xml.slice(xml.indexOf('<resource'), xml.indexOf('</resource>'));
    const configuration = xml.slice(xml.indexOf('</resource>'), xml.indexOf('</configuration>'));
    expect(resource).toMatch(/<globalVars>[\s\S]*name="Lamp" address="%QX0.0"[\s\S]*name="Count"/);
    expect(resource).toMatch(/<globalVars retain="true">[\s\S]*name="Total"/);
    expect(configuration).toMatch(/<globalVars constant="true">[\s\S]*name="Limit"/);
    expect(xml).toMatch(/<externalVars constant="true">\s*<variable name="Limit">/);
    const again = roundTrip(project);
    expect(canonical(again)).toBe(canonical(project));
    expect(connections(again)).toEqual(connections(project));
    for (const pou of ['Main', 'Tally']) expect(randomTrace(again, pou)).toEqual(randomTrace(project, pou));
  });
});

describe('VAR_EXTERNAL without a matching global', () => {
  const { project, report } = imported('names-external-missing.xml');

  it('the import report and the check name them, located: Motor runs as a global declared outside the file, Speed is an error', () => {
    expect(report.notes.map((w) => [w.line, w.pou, w.message])).toEqual([
      [
        10,
        'Main',
        'Motor is declared outside the file (VAR_EXTERNAL of Main); the simulator keeps it as a global BOOL, and export writes the file back without it',
      ],
    ]);
    expect(report.warnings.map((w) => [w.line, w.pou, w.message])).toEqual([
      [11, 'Main', 'VAR_EXTERNAL "Speed" of POU "Main" is DINT but the global variable is INT'],
    ]);
    const found = checkProject(project).filter((d) => d.rule === 'LD-E16' || d.rule === 'LD-W16');
    expect(found.map((d) => [d.rule, d.severity, d.pou, d.network, d.message])).toEqual([
      [
        'LD-W16',
        'warning',
        'Main',
        -1,
        'Motor is declared outside the project (VAR_EXTERNAL, no global of that name: MATIEC on its own refuses that, "the external variable does not match with any global variable", unless the build declares it, as OpenPLC\'s board builds do); the simulator keeps it as a global BOOL, which you can write and force in the watch table',
      ],
      [
        'LD-E16',
        'error',
        'Main',
        -1,
        'the VAR_EXTERNAL "Speed" is declared DINT but the global variable "Speed" is INT',
      ],
    ]);
  });
});

describe('typed counters CTU_DINT and CTUD_ULINT', () => {
  const { project, report } = imported('names-typed-counters.xml');

  it('import without diagnostics and keep both blocks and every wire', () => {
    expect(report.warnings).toEqual([]);
    expect(checkProject(project)).toEqual([]);
    const boxes = project.pous[0]!.networks.flatMap((n) => n.elements.filter((e) => e.kind === 'box'));
    expect(boxes.map((b) => [b.blockType, b.instance, b.inputs, b.outputs])).toEqual([
      ['CTU_DINT', 'C1', { PV: '100000' }, { CV: 'Big' }],
      ['CTUD_ULINT', 'C2', { PV: 'Preset' }, { CV: 'Huge' }],
    ]);
    const fed = connections(project)
      .filter((c) => /box:CTU/.test(c))
      .map((c) => c.replace(/box:(CTUD?_[A-Z]+):C\d:\{[^}]*\}:\{[^}]*\}/, '$1'));
    expect(fed).toEqual(
      [
        'Main CTU_DINT.CU <- contact:NO:Up.out',
        'Main CTU_DINT.R <- contact:NO:Rst.out',
        'Main coil:COIL:Done.in <- CTU_DINT.Q',
        'Main CTUD_ULINT.CU <- contact:NO:Up.out',
        'Main CTUD_ULINT.CD <- contact:NO:Down.out',
        'Main CTUD_ULINT.R <- contact:NO:Rst.out',
        'Main CTUD_ULINT.LD <- contact:NO:Load.out',
        'Main coil:COIL:High.in <- CTUD_ULINT.QU',
        'Main coil:COIL:Low.in <- CTUD_ULINT.QD',
      ].sort(),
    );
  });

  it('run as MATIEC: CTU_DINT with a PV beyond INT, CTUD_ULINT with 64-bit CV', () => {
    const plc = run(project, 'Main');
    const steps: Record<string, boolean>[] = [
      { Up: true },
      { Up: false },
      { Up: true },
      { Up: false },
      { Down: true },
      { Down: false, Load: true },
      { Load: false, Rst: true },
    ];
    expect(trace(plc, steps, ['Big', 'Done', 'Huge', 'High', 'Low'])).toEqual([
      [1, 0, 1n, 0, 0],
      [1, 0, 1n, 0, 0],
      [2, 0, 2n, 1, 0],
      [2, 0, 2n, 1, 0],
      [2, 0, 1n, 0, 0],
      [2, 0, 2n, 1, 0],
      [0, 0, 0n, 0, 1],
    ]);
  });

  it('round trip: the same project, wiring and trace', () => {
    const again = roundTrip(project);
    expect(canonical(again)).toBe(canonical(project));
    expect(connections(again)).toEqual(connections(project));
    expect(randomTrace(again, 'Main')).toEqual(randomTrace(project, 'Main'));
  });
});
