// Pasting a symbol table from a spreadsheet: reading TSV/CSV with or without a header (CODESYS,
// TIA Portal, German spellings), S7 addresses in IEC spelling or refused with the reason, and the
// preview's verdict per row (added, renamed, replaced, refused) before one undo step writes it.
import { expect, test } from 'vitest';
import { newPou, newProject, variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { createDocumentStore } from '../../src/store/documentStore';
import {
  applySymbolPaste,
  importAddress,
  parseSymbolTable,
  planCounts,
  planSymbolPaste,
  type ClashChoice,
} from '../../src/store/symbolPaste';

function plant(): Project {
  return newProject('Bottles', {
    globals: [
      variable('Start', 'BOOL', { location: '%IX0.0', comment: 'start button' }),
      variable('Count', 'INT'),
    ],
    pous: [{ ...newPou('Main'), variables: [variable('Busy', 'BOOL', { varClass: 'output' })] }],
  });
}

test('a TSV copied from a spreadsheet without header: name, type, address, initial value, comment', () => {
  const t = parseSymbolTable('Motor\tBOOL\t%QX0.0\tFALSE\tconveyor motor\nSpeed\tINT\t%QW1\t100\t\n');
  expect(t.delimiter).toBe('\t');
  expect(t.header).toBe(false);
  expect(t.rows).toEqual([
    {
      line: 1,
      cells: { name: 'Motor', type: 'BOOL', address: '%QX0.0', initial: 'FALSE', comment: 'conveyor motor' },
    },
    { line: 2, cells: { name: 'Speed', type: 'INT', address: '%QW1', initial: '100', comment: '' } },
  ]);
});

test('header rows in CODESYS, TIA Portal and German spellings find their columns in any order; other columns are ignored', () => {
  const codesys = parseSymbolTable(
    'Scope\tName\tAddress\tData type\tInitialization\tComment\nVAR_GLOBAL\tLamp\t%QX0.1\tBOOL\tTRUE\tlamp\n',
  );
  expect(codesys.header).toBe(true);
  expect(codesys.rows[0]!.cells).toEqual({
    class: 'VAR_GLOBAL',
    name: 'Lamp',
    address: '%QX0.1',
    type: 'BOOL',
    initial: 'TRUE',
    comment: 'lamp',
  });
  const tia = parseSymbolTable(
    'Name\tPath\tData Type\tLogical Address\tComment\tHmi Visible\nFill valve\tDefault tag table\tBool\t%Q0.3\tvalve\tTrue\n',
  );
  expect(tia.header).toBe(true);
  expect(tia.rows[0]!.cells).toEqual({
    name: 'Fill valve',
    type: 'Bool',
    address: '%Q0.3',
    comment: 'valve',
  });
  const german = parseSymbolTable('Symbol;Adresse;Datentyp;Kommentar\nPumpe;%A0.0;Bool;Hauptpumpe\n');
  expect(german.delimiter).toBe(';');
  expect(german.rows[0]!.cells).toEqual({
    name: 'Pumpe',
    address: '%A0.0',
    type: 'Bool',
    comment: 'Hauptpumpe',
  });
});

test('CSV with quoted fields: commas, doubled quotes and a line break inside a comment; blank rows skipped', () => {
  const t = parseSymbolTable(
    'Name,Type,Address,Initial,Comment\r\n"Level",REAL,%ID4,"1.5","tank level, in m"\r\n,,,,\r\nNote,STRING,,"\'a\'","says ""hi""\nsecond line"\r\n',
  );
  expect(t.delimiter).toBe(',');
  expect(t.rows.map((r) => r.cells)).toEqual([
    { name: 'Level', type: 'REAL', address: '%ID4', initial: '1.5', comment: 'tank level, in m' },
    { name: 'Note', type: 'STRING', address: '', initial: "'a'", comment: 'says "hi"\nsecond line' },
  ]);
});

test('S7 addresses become IEC ones; those without an IEC equivalent are refused with the reason', () => {
  expect(importAddress('%IX0.0')).toEqual({ address: '%IX0.0' });
  expect(importAddress('%I0.0')).toEqual({ address: '%IX0.0', note: 'address %I0.0 read as %IX0.0' });
  expect(importAddress('Q 4.1')).toMatchObject({ address: '%QX4.1' });
  expect(importAddress('%IW64')).toEqual({ address: '%IW64' });
  expect(importAddress('%md10')).toMatchObject({ address: '%MD10' });
  expect(importAddress('E0.7')).toMatchObject({ address: '%IX0.7' });
  expect(importAddress('%A1.0')).toMatchObject({ address: '%QX1.0' });
  expect(importAddress('%DB1.DBX0.0')).toMatchObject({ refused: expect.stringContaining('data block') });
  expect(importAddress('T5')).toMatchObject({ refused: expect.stringContaining('timer or counter') });
  expect(importAddress('%IW64:P')).toMatchObject({ refused: expect.stringContaining('peripheral') });
  expect(importAddress('%I3')).toMatchObject({ refused: expect.stringContaining('%IX3.0') });
  expect(importAddress('%I0.8')).toMatchObject({ refused: expect.stringContaining('bits 0 to 7') });
  expect(importAddress('somewhere')).toMatchObject({ refused: expect.stringContaining('not an address') });
});

test('the preview: added, renamed on a clash, refused with every reason; nothing changes until applied', () => {
  const project = plant();
  const table = parseSymbolTable(
    [
      'Name\tData Type\tAddress\tInitial\tComment',
      'Motor\tBool\t%Q0.0\t\tmotor', // added; TIA spelling read as BOOL at %QX0.0
      'Start\tBOOL\t%IX0.1\t\tsecond start', // clashes with the global Start: renamed
      '2Fast\tBOOL\t\t\t', // bad name
      'Level\tFLOAT\t\t\t', // unknown type
      'Lamp\tBOOL\t%IX0.0\t\t', // address used by Start
      'Word1\tINT\t%QX0.5\t\t', // address cannot hold INT
      'MaxFill\tINT\t\tabc\t', // bad initial value
      'Motor\tBOOL\t\t\ttwice', // pasted twice: renamed
      'Valve\tBOOL\t%Q0.0\t\t', // same address as the first row
    ].join('\n'),
  );
  const plan = planSymbolPaste(project, 'globals', table);
  expect(plan.map((r) => [r.given, r.action, r.variable?.name])).toEqual([
    ['Motor', 'add', 'Motor'],
    ['Start', 'rename', 'Start_2'],
    ['2Fast', 'refuse', '2Fast'],
    ['Level', 'refuse', 'Level'],
    ['Lamp', 'refuse', 'Lamp'],
    ['Word1', 'refuse', 'Word1'],
    ['MaxFill', 'refuse', 'MaxFill'],
    ['Motor', 'rename', 'Motor_2'],
    ['Valve', 'refuse', 'Valve'],
  ]);
  expect(plan[0]!.variable).toMatchObject({ type: 'BOOL', location: '%QX0.0', comment: 'motor' });
  expect(plan[0]!.notes).toEqual(['address %Q0.0 read as %QX0.0']);
  expect(plan[1]).toMatchObject({ clash: 'Start', canReplace: true });
  expect(plan[2]!.reasons[0]).toMatch(/not an IEC identifier/);
  expect(plan[3]!.reasons).toEqual(['type: unknown type "FLOAT"']);
  expect(plan[4]!.reasons[0]).toMatch(/%IX0\.0 is already used by "Start"/);
  expect(plan[5]!.reasons[0]).toMatch(/does not fit type INT/);
  expect(plan[6]!.reasons[0]).toMatch(/^initial value: /);
  expect(plan[7]).toMatchObject({ clash: 'Motor', canReplace: false });
  expect(plan[8]!.reasons[0]).toMatch(/%QX0\.0 is already used by "Motor"/);
  expect(planCounts(plan)).toMatchObject({ add: 1, rename: 2, refuse: 6 });
  expect(project.globals.map((g) => g.name)).toEqual(['Start', 'Count']);
});

test('replace keeps the existing variable (its place, class and references) with the pasted fields; skip leaves it', () => {
  const project = plant();
  const main = project.pous[0]!;
  const table = parseSymbolTable('Busy\tBOOL\t%QX1.0\tTRUE\tbusy lamp\nIdle\tBOOL\t\t\t\n');
  const choices = new Map<number, ClashChoice>([[0, 'replace']]);
  const plan = planSymbolPaste(project, main.id, table, choices);
  expect(plan.map((r) => r.action)).toEqual(['replace', 'add']);
  expect(plan[0]!.variable).toMatchObject({
    name: 'Busy',
    varClass: 'output',
    location: '%QX1.0',
    initial: 'TRUE',
  });
  expect(planSymbolPaste(project, main.id, table, new Map([[0, 'skip' as const]]))[0]!.action).toBe('skip');
});

test('a class column: VAR_INPUT in a POU, VAR_GLOBAL CONSTANT in the globals; the wrong list refuses it', () => {
  const project = plant();
  const main = project.pous[0]!;
  const table = parseSymbolTable('Class,Name,Type,Initial\nVAR_INPUT,Enable,BOOL,\nVAR_GLOBAL,Other,BOOL,\n');
  const inPou = planSymbolPaste(project, main.id, table);
  expect(inPou[0]).toMatchObject({ action: 'add', variable: { varClass: 'input' } });
  expect(inPou[1]).toMatchObject({
    action: 'refuse',
    reasons: [expect.stringContaining('global variables')],
  });
  const consts = parseSymbolTable('Scope\tName\tType\tInitial\nVAR_GLOBAL CONSTANT\tMaxBottles\tINT\t24\n');
  expect(planSymbolPaste(project, 'globals', consts)[0]).toMatchObject({
    action: 'add',
    variable: { name: 'MaxBottles', constant: true, initial: '24' },
  });
});

test('applying a plan is one undo step: undo removes every pasted row and restores the replaced one', () => {
  const doc = createDocumentStore(plant());
  const table = parseSymbolTable(
    'Name\tType\tAddress\nMotor\tBOOL\t%QX0.0\nStart\tBOOL\t%IX0.2\nCount\tDINT\t\nbad name\tBOOL\t\n',
  );
  const plan = planSymbolPaste(doc.getState().project, 'globals', table, new Map([[2, 'replace' as const]]));
  expect(plan.map((r) => r.action)).toEqual(['add', 'rename', 'replace', 'refuse']);
  expect(applySymbolPaste(doc.getState(), 'globals', plan)).toBe(3);
  const after = doc.getState().project.globals;
  expect(after.map((g) => `${g.name}:${g.type}:${g.location ?? ''}`)).toEqual([
    'Start:BOOL:%IX0.0',
    'Count:DINT:',
    'Motor:BOOL:%QX0.0',
    'Start_2:BOOL:%IX0.2',
  ]);
  doc.getState().undo();
  expect(doc.getState().project.globals.map((g) => `${g.name}:${g.type}`)).toEqual([
    'Start:BOOL',
    'Count:INT',
  ]);
});

test('an unclosed quote gives a reason, not an exception', () => {
  const t = parseSymbolTable('Name,Type\n"Motor,BOOL\n');
  // csv-parse with relaxed quotes reads it or says why; either way no row is invented.
  expect(t.error === undefined ? t.rows.every((r) => r.cells.name !== 'Motor') : t.error.length > 0).toBe(
    true,
  );
});

test('replacing a variable frees its old address for a later row; a row at an address the list holds is refused', () => {
  const project = plant();
  const table = parseSymbolTable('Start\tBOOL\t%IX0.5\nSpare\tBOOL\t%IX0.0\nOther\tBOOL\t%IX0.5\n');
  const plan = planSymbolPaste(project, 'globals', table, new Map([[0, 'replace' as const]]));
  expect(plan.map((r) => r.action)).toEqual(['replace', 'add', 'refuse']);
  expect(plan[2]!.reasons).toEqual(['address: %IX0.5 is already used by "Start"']);
});
