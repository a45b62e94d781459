import { expect, test } from 'vitest';
import type { LdElement } from '../../src/model/elements';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Project, Variable } from '../../src/model/project';
import { createDocumentStore } from '../../src/store/documentStore';
import {
  applyFindReplace,
  planFindReplace,
  renameInNames,
  renameInScenarioCsv,
  renameVariable,
  type ReplacePlan,
} from '../../src/store/renameVariable';

const v = (name: string, type: string): Variable => ({ name, type, varClass: 'local', retain: false, comment: '' });
let k = 0;
const id = () => `r${k++}` as ElementId;
const contact = (variable: string, col = 0, row = 0): LdElement => ({ kind: 'contact', contact: 'NO', variable, id: id(), row, col });
const coil = (variable: string, row = 0): LdElement => ({ kind: 'coil', coil: 'COIL', variable, id: id(), row, col: 6 });

function plant(): Project {
  return newProject('p', {
    globals: [v('Alarm', 'BOOL')],
    pous: [
      {
        ...newPou('Main'),
        variables: [v('Start', 'BOOL'), v('Motor', 'BOOL'), v('Motor2', 'BOOL'), v('T1', 'TON')],
        networks: [
          newNetwork({
            comment: 'Motor runs after T1',
            elements: [
              contact('Motor'),
              { kind: 'box', blockType: 'TON', instance: 'T1', id: id(), row: 0, col: 1, inputs: { IN: 'Motor', PT: 'T#5s' }, outputs: {} },
              coil('Motor2'),
            ],
          }),
          newNetwork({ elements: [contact('Start'), coil('Motor')] }),
        ],
      },
    ],
    scenarios: [{ name: 'runs', csv: '# cycle: 10ms\nscan,Start,expect Motor,expect T1.ET ~ 5ms\n1,1,1,0\n' }],
  });
}

const plan = (p: Project, text: string, by: string, mode: 'text' | 'word' = 'word') => {
  const r = planFindReplace(p, { text, mode }, by);
  if (typeof r === 'string') throw new Error(r);
  return r;
};
const main = (p: Project) => p.pous[0]!;
const names = (p: Project) =>
  main(p).networks.flatMap((n) =>
    n.elements.map((e) => (e.kind === 'contact' || e.kind === 'coil' ? e.variable : e.kind === 'box' ? `${e.instance}(${e.inputs.IN})` : '')),
  );

test("replacing a declared variable's whole name renames it: declaration, uses, scenario columns, one undo step", () => {
  const doc = createDocumentStore(plant());
  const original = doc.getState().project;
  const p: ReplacePlan = plan(original, 'Motor', 'Pump');
  expect(p.rename).toMatchObject({ from: 'Motor', to: 'Pump' });
  expect(p.undeclared).toEqual([]);
  expect(applyFindReplace(doc, p)).toEqual({ ok: true });
  const after = doc.getState().project;
  expect(main(after).variables.map((x) => x.name)).toEqual(['Start', 'Pump', 'Motor2', 'T1']);
  expect(names(after)).toEqual(['Pump', 'T1(Pump)', 'Motor2', 'Start', 'Pump']);
  expect(after.scenarios![0]!.csv).toBe('# cycle: 10ms\nscan,Start,expect Pump,expect T1.ET ~ 5ms\n1,1,1,0\n');
  expect(doc.getState().undoName).toBe('Rename Motor → Pump');
  doc.getState().undo();
  expect(doc.getState().project).toEqual(original);
  expect(main(doc.getState().project).variables.map((x) => x.name)).toEqual(['Start', 'Motor', 'Motor2', 'T1']);
  expect(names(doc.getState().project)).toEqual(['Motor', 'T1(Motor)', 'Motor2', 'Start', 'Motor']);
  expect(doc.getState().project.scenarios![0]!.csv).toContain('expect Motor,');
});

test('in text mode the rename comes with the other text replacements, which say what they leave undeclared', () => {
  const doc = createDocumentStore(plant());
  const p = plan(doc.getState().project, 'Motor', 'Pump', 'text');
  expect(p.rename?.from).toBe('Motor');
  // The comment and Motor2 (a substring) are text replacements; Pump2 is declared nowhere.
  expect(p.replacements.map((r) => r.after)).toEqual(['Pump runs after T1', 'Pump2']);
  expect(p.undeclared.map((u) => u.name)).toEqual(['Pump2']);
  applyFindReplace(doc, p);
  expect(main(doc.getState().project).variables.map((x) => x.name)).toEqual(['Start', 'Pump', 'Motor2', 'T1']);
  expect(names(doc.getState().project)).toEqual(['Pump', 'T1(Pump)', 'Pump2', 'Start', 'Pump']);
  doc.getState().undo();
  expect(names(doc.getState().project)).toEqual(['Motor', 'T1(Motor)', 'Motor2', 'Start', 'Motor']);
});

test('a replace that is not a whole declared name lists the names it would leave undeclared', () => {
  const p = plan(plant(), 'Star', 'Go', 'text');
  expect(p.rename).toBeUndefined();
  expect(p.undeclared.map((u) => [u.name, u.replacement.place.networkIndex])).toEqual([['Got', 1]]);
});

test('a rename to a name already declared is refused and changes nothing', () => {
  const doc = createDocumentStore(plant());
  const before = doc.getState().project;
  const r = applyFindReplace(doc, plan(before, 'Motor', 'Start'));
  expect(r).toEqual({ ok: false, reason: '"Start" is already declared in POU Main' });
  expect(doc.getState().project).toBe(before);
});

test('scenario headers, watch and trend names follow a rename', () => {
  expect(renameInScenarioCsv('scan,"motor",expect: MOTOR.Q~1\n1,1,1', 'Motor', 'Pump')).toBe('scan,Pump,expect: Pump.Q~1\n1,1,1');
  expect(renameInNames(['Motor', 'Main.Motor', 'Motor2', 'T1.Q'], 'Motor', 'Pump')).toEqual(['Pump', 'Main.Pump', 'Motor2', 'T1.Q']);
});

/** A global Start used directly in Main, through VAR_EXTERNAL in FB Other, and hidden by a VAR_INPUT Start in FB Conv. */
function externals(otherExtra: Variable[] = []): Project {
  return newProject('p', {
    globals: [{ ...v('Start', 'BOOL'), location: '%IX0.0' }],
    pous: [
      { ...newPou('Main'), variables: [v('Motor', 'BOOL')], networks: [newNetwork({ elements: [contact('Start'), coil('Motor')] })] },
      {
        ...newPou('Conv', { kind: 'FUNCTION_BLOCK' }),
        variables: [{ ...v('Start', 'BOOL'), varClass: 'input' }, { ...v('Out1', 'BOOL'), varClass: 'output' }],
        networks: [newNetwork({ elements: [contact('Start'), coil('Out1')] })],
      },
      {
        ...newPou('Other', { kind: 'FUNCTION_BLOCK' }),
        variables: [{ ...v('Start', 'BOOL'), varClass: 'external' }, { ...v('Out2', 'BOOL'), varClass: 'output' }, ...otherExtra],
        networks: [newNetwork({ elements: [contact('Start'), coil('Out2')] })],
      },
    ],
  });
}
const declaredAndUsed = (p: Project) =>
  p.pous.map((pou) => [pou.name, pou.variables.map((x) => `${x.varClass} ${x.name}`), pou.networks[0]!.elements.map((e) => (e.kind === 'contact' || e.kind === 'coil' ? e.variable : ''))]);

test("renaming a global renames the VAR_EXTERNAL declarations of it and their uses (not a POU's own variable of that name), one undo step", () => {
  const doc = createDocumentStore(externals());
  const original = doc.getState().project;
  expect(doc.getState().updateVariable('Start', { name: 'StartBtn' }, 'globals')).toBe(true);
  const p = doc.getState().project;
  expect(p.globals.map((g) => g.name)).toEqual(['StartBtn']);
  expect(declaredAndUsed(p)).toEqual([
    ['Main', ['local Motor'], ['StartBtn', 'Motor']],
    ['Conv', ['input Start', 'output Out1'], ['Start', 'Out1']],
    ['Other', ['external StartBtn', 'output Out2'], ['StartBtn', 'Out2']],
  ]);
  doc.getState().undo();
  expect(doc.getState().project).toEqual(original);
});

test('a global is not renamed to a name a POU declaring it VAR_EXTERNAL already uses', () => {
  const doc = createDocumentStore(externals([v('StartBtn', 'INT')]));
  const before = doc.getState().project;
  expect(doc.getState().updateVariable('Start', { name: 'StartBtn' }, 'globals')).toBe(false);
  expect(renameVariable(doc, 'Start', 'StartBtn', ['globals'])).toEqual({
    ok: false,
    reason: '"StartBtn" is already declared in POU Other, which uses the global Start as VAR_EXTERNAL',
  });
  expect(doc.getState().project).toBe(before);
});
