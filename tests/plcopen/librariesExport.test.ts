// PLCopen export of a project with a library and scenarios (docs/plcopen.md, "Libraries and
// scenarios"): the library's POUs and data types are ordinary POUs and types for other tools,
// marked in addData; the scenarios are in the project's addData; the export validates against the
// TC6 v2.01 schema; importing it gives the libraries (with their version) and the scenarios back.
import { readFileSync } from 'node:fs';
import { describe, expect, test } from 'vitest';
import { addLibrary } from '../../src/model/libraries';
import type { Project } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { extrasText } from '../../src/plcopen/importSummary';
import { readLibraryFile } from '../../src/plcopen/libraryFile';
import { ladder, plcOf, trace, vars, type BoxSpec } from '../engine/ladder';
import { multiProject, pou } from '../engine/userBlocksHelpers';
import { schemaErrors } from './xsd';

const fixture = (name: string) => readFileSync(new URL(`../fixtures/libraries/${name}`, import.meta.url), 'utf8');
const box = (type: string, row: number, col: number, extra: Partial<BoxSpec> = {}): BoxSpec => ({ row, col, type, ...extra });

const SCENARIOS = [
  { name: 'belt starts', csv: 'scan,Go,Halt,expect Moving\n1,TRUE,FALSE,TRUE\n2,FALSE,TRUE,FALSE\n' },
  { name: 'quotes & <angles>', csv: '# a "comment" with <, > and &\tand a tab\r\nscan,Go\n1,TRUE\n' },
];

async function project(): Promise<Project> {
  const read = await readLibraryFile('conveyors.xml', fixture('conveyors.xml'), new Date('2026-11-28T12:00:00Z'));
  if (!read.ok) throw new Error(read.errors.join('\n'));
  const main = pou('Main', 'PROGRAM', vars('Go BOOL', 'Halt BOOL', 'Moving BOOL', 'Raw INT', 'Scaled INT', 'Belt Conveyor', 'Speed BeltSpeed'), [
    ladder(['[Go] # # (Moving)', '. # # .', '. # # .'], { boxes: [box('Conveyor', 0, 1, { instance: 'Belt', inputs: { Stop: 'Halt' } })] }),
    ladder(['. # # .', '. # # .', '. # # .'], { boxes: [box('Scale', 0, 1, { inputs: { Value: 'Raw', Factor: '3' }, outputs: { OUT: 'Scaled' } })] }),
  ]);
  const added = addLibrary({ ...multiProject([main]), scenarios: SCENARIOS }, read.library);
  if (!added.ok) throw new Error(added.errors.join('\n'));
  return added.project;
}

describe('PLCopen export of libraries and scenarios', () => {
  test('the library POUs are ordinary POUs, marked; the export is schema-valid', async () => {
    const xml = exportPlcopen(await project(), { now: new Date('2026-11-28T12:00:00Z') });
    expect(await schemaErrors(xml)).toEqual([]);
    // Other tools see two more POUs and one more data type, in plain PLCopen.
    expect(xml).toMatch(/<pou name="Conveyor" pouType="functionBlock">/);
    expect(xml).toMatch(/<pou name="Scale" pouType="function">/);
    expect(xml).toMatch(/<dataType name="BeltSpeed">/);
    // Declared before use: the library's POUs come before Main.
    expect(xml.indexOf('<pou name="Conveyor"')).toBeLessThan(xml.indexOf('<pou name="Main"'));
    expect(xml).toMatch(/<data name="https:\/\/rungsmith.dev\/plcopen\/library" handleUnknown="discard"><library xmlns="https:\/\/rungsmith.dev\/plcopen" name="Conveyors"\/><\/data>/);
    expect(xml).toMatch(/<data name="https:\/\/rungsmith.dev\/plcopen\/scenarios" handleUnknown="discard">/);
  });

  test('importing the export gives the library back (not project POUs), with its version, and the scenarios', async () => {
    const original = await project();
    const imported = importPlcopen(exportPlcopen(original));
    expect(imported.ok).toBe(true);
    if (!imported.ok) return;
    const p = imported.project;
    expect(p.pous.map((x) => x.name)).toEqual(['Main']);
    expect(p.dataTypes).toBe(undefined);
    expect(p.libraries?.map((l) => [l.name, l.hash, l.sourceFile, l.addedAt, l.origin])).toEqual([
      ['Conveyors', original.libraries![0]!.hash, 'conveyors.xml', '2026-11-28T12:00:00.000Z', 'plcopen'],
    ]);
    const lib = p.libraries![0]!;
    expect(lib.pous.map((x) => [x.id, x.name, x.language, x.source])).toEqual(original.libraries![0]!.pous.map((x) => [x.id, x.name, x.language, x.source]));
    expect(lib.pous.map((x) => x.variables)).toEqual(original.libraries![0]!.pous.map((x) => x.variables));
    expect(lib.dataTypes).toEqual(original.libraries![0]!.dataTypes);
    expect(p.scenarios).toEqual(SCENARIOS);
    // The import report says so.
    expect(extrasText(p)).toBe('Libraries: Conveyors (2 blocks). 2 test scenarios.');
    // No warning about the Rungsmith addData (it is read, not dropped).
    expect(imported.report.warnings.filter((w) => /addData/.test(w.message))).toEqual([]);
    // And it runs as before.
    const rows = trace(plcOf(p), [{ Go: true, Raw: 2 }, { Halt: true }], ['Moving', 'Belt.Starts', 'Scaled']);
    expect(rows).toEqual([
      [1, 1, 6],
      [0, 1, 6],
    ]);
  });

  test('export and import again give the same file (once the import has laid Main out)', async () => {
    const now = new Date('2026-11-28T12:00:00Z');
    const cycle = (xml: string) => {
      const r = importPlcopen(xml);
      if (!r.ok) throw new Error(r.errors.map((e) => e.message).join('\n'));
      return exportPlcopen(r.project, { now });
    };
    const second = cycle(exportPlcopen(await project(), { now }));
    expect(cycle(second)).toBe(second);
    expect(second).toMatch(/<library name="Conveyors" hash="sha256:[0-9a-f]{64}" sourceFile="conveyors.xml" addedAt="2026-11-28T12:00:00.000Z" origin="plcopen">/);
  });

  test('a POU marked for a library the file does not list stays a POU of the project, with a warning', async () => {
    const xml = exportPlcopen(await project()).replace(/<data name="https:\/\/rungsmith.dev\/plcopen\/libraries"[\s\S]*?<\/data>/, '');
    const imported = importPlcopen(xml);
    expect(imported.ok && imported.project.pous.map((x) => x.name).sort()).toEqual(['Conveyor', 'Main', 'Scale']);
    expect(imported.ok && imported.report.warnings.map((w) => w.message)).toContain(
      'POU Conveyor is marked as a block of the library Conveyors, which the file does not list: imported as a POU of the project',
    );
  });
});
