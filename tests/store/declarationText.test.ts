// An edited declaration text applied to the document (src/store/declarationText.ts): one undo step,
// a rename renames the uses, the text's order becomes the list's order, an FB's calls follow.
import { expect, test } from 'vitest';
import { parseDeclarations, printDeclarations } from '../../src/engine/st/declarations';
import type { LdElement } from '../../src/model/elements';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Project } from '../../src/model/project';
import { applyDeclarationText, EDIT_DECLARATIONS } from '../../src/store/declarationText';
import { createDocumentStore } from '../../src/store/documentStore';

let k = 0;
const id = () => `d${k++}` as ElementId;
const contact = (name: string): LdElement => ({ kind: 'contact', contact: 'NO', variable: name, id: id(), row: 0, col: 0 });
const coil = (name: string): LdElement => ({ kind: 'coil', coil: 'COIL', variable: name, id: id(), row: 0, col: 6 });

function plant(): Project {
  return newProject('p', {
    globals: [variable('Alarm', 'BOOL', { scope: 'resource' })],
    pous: [
      {
        ...newPou('Main'),
        variables: [
          variable('Start', 'BOOL', { varClass: 'input', location: '%IX0.0' }),
          variable('Motor', 'BOOL', { varClass: 'output' }),
          variable('Count', 'INT', { initial: '5' }),
        ],
        networks: [newNetwork({ elements: [contact('Start'), coil('Motor')] })],
      },
    ],
    scenarios: [{ name: 's', csv: 'scan,Start,expect Motor\n1,1,1\n' }],
  });
}

const parse = (text: string, section: 'pou' | 'globals' = 'pou') => {
  const r = parseDeclarations(text, section);
  if (!r.ok) throw new Error(JSON.stringify(r.problems));
  return r.variables;
};
const main = (p: Project) => p.pous[0]!;

test('a new declaration typed in the VAR_INPUT block lands there, as one undo step', () => {
  const doc = createDocumentStore(plant());
  const before = doc.getState().project;
  const text = printDeclarations(main(before).variables, 'pou').replace(
    '\tStart AT %IX0.0 : BOOL;\n',
    '\tStart AT %IX0.0 : BOOL;\n\tStop AT %IX0.1 : BOOL := TRUE; (* stop button, NC *)\n',
  );
  expect(applyDeclarationText(doc, main(before).id, parse(text))).toEqual({ ok: true, changed: true });
  const vars = main(doc.getState().project).variables;
  expect(vars.map((v) => v.name)).toEqual(['Start', 'Stop', 'Motor', 'Count']);
  expect(vars[1]).toMatchObject({ varClass: 'input', location: '%IX0.1', initial: 'TRUE', comment: 'stop button, NC' });
  expect(printDeclarations(vars, 'pou')).toBe(text);
  expect(doc.getState().undoName).toBe(EDIT_DECLARATIONS);
  expect(doc.getState().history.undo).toHaveLength(1);
  doc.getState().undo();
  expect(doc.getState().project).toEqual(before);
});

test('one name changed in place is a rename: contacts, coils and scenario columns follow', () => {
  const doc = createDocumentStore(plant());
  const pou = main(doc.getState().project);
  const text = printDeclarations(pou.variables, 'pou').replace('Motor :', 'Pump :');
  expect(applyDeclarationText(doc, pou.id, parse(text)).ok).toBe(true);
  const after = doc.getState().project;
  expect(main(after).variables.map((v) => v.name)).toEqual(['Start', 'Pump', 'Count']);
  expect(main(after).networks[0]!.elements.map((e) => (e.kind === 'coil' ? e.variable : ''))).toContain('Pump');
  expect(after.scenarios![0]!.csv).toContain('expect Pump');
  expect(doc.getState().history.undo).toHaveLength(1);
});

test('two names changed in place in one edit are two renames: the contact and the coil follow, one undo step', () => {
  const doc = createDocumentStore(plant());
  const before = doc.getState().project;
  const pou = main(before);
  const text = printDeclarations(pou.variables, 'pou').replace('Start AT', 'StartBtn AT').replace('Motor :', 'Pump :');
  expect(applyDeclarationText(doc, pou.id, parse(text))).toEqual({ ok: true, changed: true });
  const after = doc.getState().project;
  expect(main(after).variables.map((v) => v.name)).toEqual(['StartBtn', 'Pump', 'Count']);
  expect(main(after).networks[0]!.elements.map((e) => (e.kind === 'contact' || e.kind === 'coil' ? e.variable : ''))).toEqual(['StartBtn', 'Pump']);
  expect(after.scenarios![0]!.csv).toBe('scan,StartBtn,expect Pump\n1,1,1\n');
  expect(doc.getState().history.undo).toHaveLength(1);
  doc.getState().undo();
  expect(doc.getState().project).toEqual(before);
});

test('a field dropped from the text is dropped from the variable; an unchanged text changes nothing', () => {
  const doc = createDocumentStore(plant());
  const pou = main(doc.getState().project);
  expect(applyDeclarationText(doc, pou.id, parse(printDeclarations(pou.variables, 'pou')))).toEqual({ ok: true, changed: false });
  const text = printDeclarations(pou.variables, 'pou').replace('Start AT %IX0.0 : BOOL;', 'Start : BOOL;').replace(' := 5', '');
  applyDeclarationText(doc, pou.id, parse(text));
  const vars = main(doc.getState().project).variables;
  expect(vars[0]!.location).toBeUndefined();
  expect(vars[2]!.initial).toBeUndefined();
});

test('globals: names gone are deleted, new ones added, a kept global keeps where it is declared', () => {
  const doc = createDocumentStore(plant());
  const text = 'VAR_GLOBAL\n\tAlarm : BOOL; (* horn *)\n\tLevel AT %IW0 : INT;\nEND_VAR\n';
  applyDeclarationText(doc, 'globals', parse(text, 'globals'));
  expect(doc.getState().project.globals).toEqual([
    { ...variable('Alarm', 'BOOL', { comment: 'horn', scope: 'resource' }), location: undefined, initial: undefined, constant: undefined },
    variable('Level', 'INT', { location: '%IW0' }),
  ]);
  applyDeclarationText(doc, 'globals', parse('VAR_GLOBAL\nEND_VAR', 'globals'));
  expect(doc.getState().project.globals).toEqual([]);
});

test("an FB's new input in the text gives its calls the pin (the interface follows)", () => {
  const fb = { ...newPou('Conveyor'), kind: 'FUNCTION_BLOCK' as const, variables: [variable('Run', 'BOOL', { varClass: 'input' as const })] };
  const call: LdElement = { kind: 'box', blockType: 'Conveyor', instance: 'C1', id: id(), row: 0, col: 1, inputs: { Run: 'Go' }, outputs: {} };
  const project = newProject('p', {
    pous: [
      { ...newPou('Main'), variables: [variable('Go', 'BOOL'), variable('C1', 'Conveyor')], networks: [newNetwork({ elements: [call] })] },
      fb,
    ],
  });
  const doc = createDocumentStore(project);
  applyDeclarationText(doc, fb.id, parse('VAR_INPUT\n\tRun : BOOL;\n\tSpeed : INT;\nEND_VAR\n'));
  expect(doc.getState().project.pous[1]!.variables.map((v) => v.name)).toEqual(['Run', 'Speed']);
  expect(doc.getState().history.undo).toHaveLength(1);
  doc.getState().undo();
  expect(doc.getState().project).toEqual(project);
});

test("the text's order becomes the list's order (one step with the other changes)", () => {
  const doc = createDocumentStore(plant());
  const pou = main(doc.getState().project);
  applyDeclarationText(doc, pou.id, parse('VAR\n\tCount : INT := 5;\nEND_VAR\nVAR_OUTPUT\n\tMotor : BOOL;\nEND_VAR\nVAR_INPUT\n\tStart AT %IX0.0 : BOOL;\n\tReset : BOOL;\nEND_VAR\n'));
  expect(main(doc.getState().project).variables.map((v) => v.name)).toEqual(['Count', 'Motor', 'Start', 'Reset']);
  expect(doc.getState().history.undo).toHaveLength(1);
  doc.getState().undo();
  expect(main(doc.getState().project).variables.map((v) => v.name)).toEqual(['Start', 'Motor', 'Count']);
});
