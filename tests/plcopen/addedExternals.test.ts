// Export for OpenPLC/MATIEC: every LD program and FB declares the globals it uses as VAR_EXTERNAL
// (MATIEC refuses an undeclared global), schema-valid; the import drops exactly those again, so the
// project comes back as it was. Other profiles export the POUs' declarations as they are.
import { expect, test } from 'vitest';
import { newPou, newProject } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { missingExternals } from '../../src/plcopen/addedExternals';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { ladder, vars } from '../engine/ladder';
import { io } from '../engine/userBlocksHelpers';
import { schemaErrors } from './xsd';

function plant(profile: Project['profile']): Project {
  // Main: a local Stop hides the global Stop; Word.3 names the global Word; the FB's box reads the constant Speed.
  const main = newPou('Main', {
    variables: [...vars('Stop BOOL', 'Conv1 Conveyor')],
    networks: [
      ladder(['[Start] [/Stop] [Word.3] (Motor)']),
      ladder(['[Motor] (Lamp)'], {
        boxes: [{ row: 1, col: 1, type: 'Conveyor', instance: 'Conv1', inputs: { Run: 'Motor', Top: 'Speed' } }],
      }),
    ],
  });
  const conveyor = newPou('Conveyor', {
    kind: 'FUNCTION_BLOCK',
    variables: io('input', 'Run BOOL', 'Top INT'),
    networks: [ladder(['[Run] [EStop] (Belt)'])],
  });
  const scale = newPou('Scale', {
    kind: 'FUNCTION',
    returnType: 'BOOL',
    variables: io('input', 'X BOOL'),
    networks: [ladder(['[X] [EStop] (Scale)'])],
  });
  return newProject('Plant', {
    profile,
    pous: [main, conveyor, scale],
    globals: [...vars('Start BOOL %IX0.0', 'Stop BOOL', 'Motor BOOL %QX0.0', 'Lamp BOOL', 'Word WORD', 'EStop BOOL', 'Belt BOOL'), { ...vars('Speed INT := 10')[0]!, constant: true }],
    tasks: [{ name: 'MainTask', cycleMs: 10, priority: 1, programs: [{ instance: 'MainInst', pou: 'Main' }] }],
  });
}

const externalsOf = (xml: string, pou: string): string[] => {
  const body = new RegExp(`<pou name="${pou}"[\\s\\S]*?</pou>`).exec(xml)?.[0] ?? '';
  const lists = [...body.matchAll(/<externalVars[^>]*>([\s\S]*?)<\/externalVars>/g)].map((m) => m[1]!).join('');
  return [...lists.matchAll(/<variable name="([^"]+)"/g)].map((m) => m[1]!);
};

test('the globals a POU uses and does not declare; none for a FUNCTION', () => {
  const p = plant('openplc');
  const [main, conveyor, scale] = p.pous;
  expect(missingExternals(main!, p.globals).map((v) => `${v.name}:${v.type}${v.constant ? ' CONSTANT' : ''}`)).toEqual([
    'Start:BOOL',
    'Word:WORD',
    'Motor:BOOL',
    'Lamp:BOOL',
    'Speed:INT CONSTANT',
  ]);
  expect(missingExternals(conveyor!, p.globals).map((v) => v.name)).toEqual(['EStop', 'Belt']);
  expect(missingExternals(scale!, p.globals)).toEqual([]);
});

test('openplc: VAR_EXTERNAL in the program and the FB, schema-valid; import gives the project back', async () => {
  const p = plant('openplc');
  const xml = exportPlcopen(p);
  expect(await schemaErrors(xml)).toEqual([]);
  expect(externalsOf(xml, 'Main')).toEqual(['Start', 'Word', 'Motor', 'Lamp', 'Speed']);
  expect(externalsOf(xml, 'Conveyor')).toEqual(['EStop', 'Belt']);
  expect(externalsOf(xml, 'Scale')).toEqual([]);
  // A CONSTANT global is named by a VAR_EXTERNAL CONSTANT (MATIEC checks it).
  expect(xml).toMatch(/<externalVars constant="true">[\s\S]*?<variable name="Speed">/);
  const back = importPlcopen(xml);
  if (!back.ok) throw new Error(JSON.stringify(back.errors));
  // (The export writes a called FB before its caller: compare by name.)
  const decl = (q: Project) =>
    q.pous
      .map((x) => [x.name, x.variables.map((v) => `${v.varClass} ${v.name} ${v.type}`)] as const)
      .sort((a, b) => a[0].localeCompare(b[0]));
  expect(decl(back.project)).toEqual(decl(p));
  expect(back.project.globals.map((g) => g.name)).toEqual(p.globals.map((g) => g.name));
  // Exported again, the imported project declares the same VAR_EXTERNALs (none twice).
  const again = exportPlcopen(back.project);
  for (const pou of ['Main', 'Conveyor', 'Scale']) expect(externalsOf(again, pou)).toEqual(externalsOf(xml, pou));
});

test('a VAR_EXTERNAL the project declares itself stays on import; iec exports the declarations as they are', () => {
  const p = plant('openplc');
  const own: Project = {
    ...p,
    pous: p.pous.map((x) => (x.name === 'Main' ? { ...x, variables: [...x.variables, ...io('external', 'Start BOOL')] } : x)),
  };
  const xml = exportPlcopen(own);
  expect(externalsOf(xml, 'Main')).toEqual(['Start', 'Word', 'Motor', 'Lamp', 'Speed']);
  const back = importPlcopen(xml);
  if (!back.ok) throw new Error(JSON.stringify(back.errors));
  expect(back.project.pous.find((x) => x.name === 'Main')!.variables.filter((v) => v.varClass === 'external').map((v) => v.name)).toEqual(['Start']);
  expect(externalsOf(exportPlcopen(plant('iec')), 'Main')).toEqual([]);
});
