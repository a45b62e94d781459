// PLCopen export of a project that controls a machine (issue 26, docs/PLANTS.md): the machine and
// the addresses the user changed travel in the project's addData (Rungsmith's namespace,
// handleUnknown="discard", so other tools ignore them), the file stays schema-valid, and importing
// it gives the project back with its machine and its I/O map, as saving and opening does.
import { describe, expect, test } from 'vitest';
import type { Project } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { extrasText } from '../../src/plcopen/importSummary';
import { tankReference } from '../../src/plant/exercises';
import { schemaErrors } from './xsd';

const withMap = (): Project => ({
  ...tankReference(),
  plant: { id: 'tank', map: { Pump: '%QX1.0', Level: '%IW2' } },
});

describe('PLCopen export of the machine a project controls', () => {
  test('the machine and its changed addresses are in the project addData; the file is schema-valid', async () => {
    const xml = exportPlcopen(withMap(), { now: new Date('2026-11-28T12:00:00Z') });
    expect(await schemaErrors(xml)).toEqual([]);
    expect(xml).toMatch(/<data name="https:\/\/rungsmith.dev\/plcopen\/plant" handleUnknown="discard">/);
    expect(xml).toMatch(/<plant xmlns="https:\/\/rungsmith.dev\/plcopen" id="tank">/);
    expect(xml).toMatch(/<point name="Pump" address="%QX1.0"\/>/);
  });

  test('importing the export gives the machine and its I/O map back, without a warning about the addData', () => {
    const imported = importPlcopen(exportPlcopen(withMap()));
    expect(imported.ok).toBe(true);
    if (!imported.ok) return;
    expect(imported.project.plant).toEqual({ id: 'tank', map: { Pump: '%QX1.0', Level: '%IW2' } });
    expect(extrasText(imported.project)).toBe('1 test scenario. Machine: tank.');
    expect(imported.report.warnings.filter((w) => /addData/.test(w.message))).toEqual([]);
    // The exercise's scenario came back too (it names the machine).
    expect(imported.project.scenarios?.map((s) => s.csv.split('\n')[0])).toEqual(['# plant: tank']);
  });

  test('a machine with the default map comes back with no map; a project without a machine gets none', () => {
    const plain = importPlcopen(exportPlcopen(tankReference()));
    expect(plain.ok && plain.project.plant).toEqual({ id: 'tank' });
    const { plant: _p, ...none } = tankReference();
    const back = importPlcopen(exportPlcopen(none));
    expect(back.ok && back.project.plant).toBe(undefined);
  });

  test('export and import again give the same file (once the import has laid the program out)', () => {
    const now = new Date('2026-11-28T12:00:00Z');
    const first = importPlcopen(exportPlcopen(withMap(), { now }));
    if (!first.ok) throw new Error('import failed');
    const twice = exportPlcopen(first.project, { now });
    const second = importPlcopen(twice);
    if (!second.ok) throw new Error('import failed');
    expect(exportPlcopen(second.project, { now })).toBe(twice);
    expect(twice).toMatch(/<point name="Level" address="%IW2"\/>/);
  });
});
