// Language services of the ST editor (src/engine/st/services): diagnostics, completion, hover,
// go to definition and rename, on a project with ST and LD POUs calling each other.
import { describe, expect, it } from 'vitest';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { LdElement } from '../../src/model/elements';
import type { Pou, Project, Variable } from '../../src/model/project';
import { checkProject } from '../../src/engine/check';
import {
  planStRename,
  stCompletions,
  stDefinition,
  stDiagnostics,
  stHover,
  stRenameEdits,
} from '../../src/engine/st/services';
import { createDocumentStore } from '../../src/store/documentStore';
import { renameVariable } from '../../src/store/renameVariable';

const v = variable;
const st = (
  name: string,
  kind: Pou['kind'],
  variables: Variable[],
  source: string,
  returnType?: string,
): Pou =>
  newPou(name, {
    kind,
    variables,
    networks: [],
    language: 'ST',
    source,
    ...(returnType ? { returnType } : {}),
  });

const SCALE = 'Scale := Lo + In * (Hi - Lo);\n';
const HYST = 'IF X > Limit THEN\n  Q := TRUE;\nELSIF X < Limit - 1.0 THEN\n  Q := FALSE;\nEND_IF;\n';
const MAIN = [
  'Motor1(IN := Start, PT := T#5s);',
  'Level := Scale(In := Raw, Lo := 0.0, Hi := 100.0);',
  'H1(X := Level, Limit := 80.0);',
  'Alarm := H1.Q AND Motor1.Q;',
  'Pt.X := 3;',
  'State := Color#GREEN;',
  '',
].join('\n');

function makeProject(main = MAIN): Project {
  let k = 0;
  const id = () => `e${k++}` as ElementId;
  const ladder: LdElement[] = [
    { kind: 'contact', contact: 'NO', variable: 'H2.Q', id: id(), row: 0, col: 0 },
    {
      kind: 'box',
      blockType: 'Hyst',
      instance: 'H2',
      executionControl: true,
      id: id(),
      row: 0,
      col: 1,
      inputs: { X: 'Level2', Limit: '50.0' },
      outputs: {},
    },
    { kind: 'coil', coil: 'COIL', variable: 'Lamp', id: id(), row: 0, col: 6 },
  ];
  return newProject('Plant', {
    dataTypes: [
      {
        name: 'Point',
        def: {
          kind: 'struct',
          members: [
            { name: 'X', type: 'INT' },
            { name: 'Y', type: 'INT' },
          ],
        },
        comment: '',
      },
      { name: 'Color', def: { kind: 'enum', values: ['RED', 'GREEN', 'BLUE'] }, comment: '' },
    ],
    globals: [v('Alarm', 'BOOL', { comment: 'horn on the panel' })],
    pous: [
      st(
        'Main',
        'PROGRAM',
        [
          v('Motor1', 'TON', { comment: 'start delay of the pump' }),
          v('Start', 'BOOL', { varClass: 'input', location: '%IX0.0' }),
          v('Raw', 'REAL'),
          v('Level', 'REAL', { initial: '1.5', comment: 'tank level in %' }),
          v('H1', 'Hyst'),
          v('Pt', 'Point'),
          v('State', 'Color'),
        ],
        main,
      ),
      st(
        'Scale',
        'FUNCTION',
        [
          v('In', 'REAL', { varClass: 'input', comment: 'raw value' }),
          v('Lo', 'REAL', { varClass: 'input' }),
          v('Hi', 'REAL', { varClass: 'input' }),
        ],
        SCALE,
        'REAL',
      ),
      st(
        'Hyst',
        'FUNCTION_BLOCK',
        [
          v('X', 'REAL', { varClass: 'input' }),
          v('Limit', 'REAL', { varClass: 'input', comment: 'switch-on level' }),
          v('Q', 'BOOL', { varClass: 'output' }),
        ],
        HYST,
      ),
      newPou('Ladder', {
        variables: [v('H2', 'Hyst'), v('Level2', 'REAL'), v('Lamp', 'BOOL')],
        networks: [newNetwork({ elements: ladder })],
      }),
    ],
  });
}

const pouId = (p: Project, name: string) => p.pous.find((x) => x.name === name)!.id;
/** The offset just after the first occurrence of `marker` (or at `|` inside it). */
function at(text: string, marker: string): number {
  const bar = marker.indexOf('|');
  const plain = marker.replace('|', '');
  const i = text.indexOf(plain);
  if (i < 0) throw new Error(`no "${plain}" in the text`);
  return i + (bar < 0 ? plain.length : bar);
}

describe('ST diagnostics', () => {
  it('a correct body has none, and the project check agrees', () => {
    const p = makeProject();
    expect(stDiagnostics(p, pouId(p, 'Main')).located).toEqual([]);
    expect(checkProject(p).filter((d) => d.severity === 'error')).toEqual([]);
  });

  it('locates a type error to its line and column, with its rule id and the POU, as the compiler reports it', () => {
    const p = makeProject();
    const text = `${MAIN}Start2 := 1;\nLevel := Start;\n`;
    const { located } = stDiagnostics(p, pouId(p, 'Main'), text);
    expect(located.map((d) => [d.rule, d.line, d.col, d.endLine, d.endCol])).toEqual([
      ['LD-E50', 7, 1, 7, 7],
      ['LD-E50', 8, 10, 8, 15],
    ]);
    expect(located[0]!.message).toMatch(/^the ST body of Main does not compile: line 7 col 1: /);
    expect(located[0]!.detail).toMatch(/Start2/);
    expect(located[1]!.detail).toMatch(/REAL is needed and the value is BOOL/);
    // The project check (Problems list, Run, `rungsmith check`) has the same findings, located.
    const committed = { ...p, pous: p.pous.map((x) => (x.name === 'Main' ? { ...x, source: text } : x)) };
    const project = checkProject(committed).filter((d) => d.pou === 'Main' && d.severity === 'error');
    expect(project.map((d) => [d.rule, d.line, d.col, d.message])).toEqual(
      located.map((d) => [d.rule, d.line, d.col, d.message]),
    );
  });

  it('a syntax error is located where the parser stopped, and a pragma is a located warning', () => {
    const p = makeProject();
    const syntax = stDiagnostics(p, pouId(p, 'Main'), 'IF Start THEN\n  Level := 2.0\nEND_IF;\n').located;
    expect(syntax).toHaveLength(1);
    expect(syntax[0]).toMatchObject({ severity: 'error', rule: 'LD-E50', line: 3, col: 1 });
    expect(syntax[0]!.detail).toMatch(/expected ";"/);
    const pragma = stDiagnostics(p, pouId(p, 'Main'), '{ printf("x"); }\nLevel := 2.0;\n').located;
    expect(pragma).toMatchObject([{ severity: 'warning', rule: 'LD-W50', line: 1, col: 1 }]);
  });

  it('an array index out of bounds keeps its own rule id', () => {
    const p = makeProject();
    const main = p.pous[0]!;
    const q = {
      ...p,
      pous: [{ ...main, variables: [...main.variables, v('A', 'ARRAY[1..3] OF INT')] }, ...p.pous.slice(1)],
    };
    const d = stDiagnostics(q, main.id, 'A[4] := 1;\n').located;
    expect(d.map((x) => [x.rule, x.line])).toEqual([['LD-E62', 1]]);
  });
});

describe('ST completion', () => {
  const labels = (r: ReturnType<typeof stCompletions>) => r?.options.map((o) => o.label) ?? [];

  it('after "Motor1." lists the TON pins (outputs first) with their types', () => {
    const p = makeProject();
    const text = `${MAIN}Alarm := Motor1.`;
    const r = stCompletions(p, pouId(p, 'Main'), text, text.length)!;
    expect(r.explicit).toBe(true);
    expect(labels(r)).toEqual(['Q', 'ET', 'IN', 'PT']);
    expect(r.options[1]).toMatchObject({ kind: 'member', detail: 'TIME — output of TON' });
  });

  it('lists the pins of a user FB and the members of a struct, from a word already begun', () => {
    const p = makeProject();
    const fb = `${MAIN}x := H1.Li`;
    const r = stCompletions(p, pouId(p, 'Main'), fb, fb.length)!;
    expect(r.from).toBe(fb.length - 2);
    expect(labels(r)).toEqual(['Q', 'X', 'Limit']);
    expect(r.options.find((o) => o.label === 'Limit')!.info).toBe('switch-on level');
    const struct = `${MAIN}Pt.`;
    expect(labels(stCompletions(p, pouId(p, 'Main'), struct, struct.length))).toEqual(['X', 'Y']);
  });

  it('lists enum values after Type#', () => {
    const p = makeProject();
    const text = `${MAIN}State := Color#`;
    expect(labels(stCompletions(p, pouId(p, 'Main'), text, text.length))).toEqual(['RED', 'GREEN', 'BLUE']);
  });

  it('offers variables in scope (globals too), functions and FBs with signatures, and snippets at a statement start', () => {
    const p = makeProject();
    const text = `${MAIN}`;
    const r = stCompletions(p, pouId(p, 'Main'), text, text.length)!;
    const by = (l: string) => r.options.find((o) => o.label === l);
    expect(by('Level')).toMatchObject({ kind: 'variable', detail: 'REAL' });
    expect(by('Level')!.info).toContain('tank level in %');
    expect(by('Alarm')).toMatchObject({ kind: 'variable', detail: 'BOOL' });
    expect(by('Scale')).toMatchObject({
      kind: 'function',
      detail: 'Scale(In : REAL, Lo : REAL, Hi : REAL) : REAL',
    });
    expect(by('Hyst')!.detail).toBe('Hyst(X : REAL, Limit : REAL) => (Q : BOOL)');
    expect(by('TON')!.detail).toBe('TON(IN : BOOL, PT : TIME) => (Q : BOOL, ET : TIME)');
    expect(by('LIMIT')!.kind).toBe('function');
    expect(by('GREEN')).toMatchObject({ kind: 'enum', detail: 'Color' });
    expect(by('IF')!.kind).toBe('snippet');
    // Inside an expression, no statement snippets.
    const expr = `${MAIN}Level := `;
    expect(
      stCompletions(p, pouId(p, 'Main'), expr, expr.length)!.options.some((o) => o.kind === 'snippet'),
    ).toBe(false);
  });

  it('inside a call, offers its parameters by name (those not given yet)', () => {
    const p = makeProject();
    const text = `${MAIN}H1(X := Level, `;
    const r = stCompletions(p, pouId(p, 'Main'), text, text.length)!;
    const params = r.options.filter((o) => o.kind === 'parameter').map((o) => o.label);
    expect(params).toEqual(['Limit :=', 'Q =>']);
    const fn = `${MAIN}Level := Scale(`;
    expect(
      stCompletions(p, pouId(p, 'Main'), fn, fn.length)!
        .options.filter((o) => o.kind === 'parameter')
        .map((o) => o.apply),
    ).toEqual(['In := ', 'Lo := ', 'Hi := ']);
  });

  it('reads the statement around the cursor: comments and strings before it (with ";" inside) do not confuse it', () => {
    const p = makeProject();
    const text = `${MAIN}(* a; b *) s := 'x;(*'; // c;\nIF Start THEN x := Motor1.`;
    expect(labels(stCompletions(p, pouId(p, 'Main'), text, text.length))).toEqual(['Q', 'ET', 'IN', 'PT']);
    const call = `${MAIN}H1(X := Level,\n   Limit := 80.0);\n`;
    expect(stHover(p, pouId(p, 'Main'), call, at(call, 'Lim|it := 80'))!.title).toBe('Limit : REAL');
  });

  it('offers nothing inside a comment or a string, or in a number', () => {
    const p = makeProject();
    for (const text of [`${MAIN}(* Mot`, `${MAIN}// Mot`, `${MAIN}s := 'Mot`, `${MAIN}x := 12`])
      expect(stCompletions(p, pouId(p, 'Main'), text, text.length)).toBeUndefined();
  });
});

describe('ST hover and go to definition', () => {
  it('hover shows the declaration, class and comment of a variable', () => {
    const p = makeProject();
    const h = stHover(p, pouId(p, 'Main'), MAIN, at(MAIN, 'Lev|el := S'))!;
    expect(h.title).toBe('Level : REAL := 1.5');
    expect(h.lines).toEqual(['VAR — variable of Main', 'tank level in %']);
    expect(MAIN.slice(h.from, h.to)).toBe('Level');
    const start = stHover(p, pouId(p, 'Main'), MAIN, at(MAIN, 'St|art'))!;
    expect(start.title).toBe('Start AT %IX0.0 : BOOL');
    expect(start.lines[0]).toBe('VAR_INPUT — variable of Main');
    const g = stHover(p, pouId(p, 'Main'), MAIN, at(MAIN, 'Ala|rm'))!;
    expect(g.lines).toEqual(['VAR_GLOBAL — global variable', 'horn on the panel']);
    const inst = stHover(p, pouId(p, 'Main'), MAIN, at(MAIN, 'Mot|or1('))!;
    expect(inst.lines).toEqual([
      'VAR — variable of Main',
      'instance of TON(IN : BOOL, PT : TIME) => (Q : BOOL, ET : TIME)',
      'start delay of the pump',
    ]);
  });

  it('hover on a pin, a parameter and a function shows its type and signature', () => {
    const p = makeProject();
    const pin = stHover(p, pouId(p, 'Main'), MAIN, at(MAIN, 'Motor1.|Q'))!;
    expect(pin).toMatchObject({ title: 'Q : BOOL', lines: ['output of TON'] });
    const param = stHover(p, pouId(p, 'Main'), MAIN, at(MAIN, 'Scale(I|n'))!;
    expect(param.title).toBe('In : REAL');
    expect(param.lines).toEqual(['input of Scale(In : REAL, Lo : REAL, Hi : REAL) : REAL', 'raw value']);
    const fn = stHover(p, pouId(p, 'Main'), MAIN, at(MAIN, 'Sc|ale'))!;
    expect(fn.title).toBe('Scale(In : REAL, Lo : REAL, Hi : REAL) : REAL');
    expect(fn.lines[0]).toBe('function of this project');
    expect(stHover(p, pouId(p, 'Main'), MAIN, at(MAIN, 'Color#GR|EEN'))!.title).toBe('Color#GREEN');
    expect(stHover(p, pouId(p, 'Main'), '(* Level *)', 4)).toBeUndefined();
  });

  it('go to definition: a variable (own or global), a user FB pin, a user function', () => {
    const p = makeProject();
    const main = pouId(p, 'Main');
    expect(stDefinition(p, main, MAIN, at(MAIN, 'Lev|el :='))).toEqual({
      kind: 'variable',
      scope: main,
      name: 'Level',
    });
    expect(stDefinition(p, main, MAIN, at(MAIN, 'Ala|rm'))).toEqual({
      kind: 'variable',
      scope: 'globals',
      name: 'Alarm',
    });
    expect(stDefinition(p, main, MAIN, at(MAIN, 'H1.|Q'))).toEqual({
      kind: 'variable',
      scope: pouId(p, 'Hyst'),
      name: 'Q',
    });
    expect(stDefinition(p, main, MAIN, at(MAIN, 'Limit| :='))).toEqual({
      kind: 'variable',
      scope: pouId(p, 'Hyst'),
      name: 'Limit',
    });
    expect(stDefinition(p, main, MAIN, at(MAIN, 'Sca|le('))).toEqual({
      kind: 'pou',
      pouId: pouId(p, 'Scale'),
    });
    expect(stDefinition(p, main, MAIN, at(MAIN, 'Pt.|X'))).toEqual({ kind: 'dataType', name: 'Point' });
    expect(stDefinition(p, main, MAIN, at(MAIN, 'Motor1.|Q'))).toBeUndefined();
  });
});

describe('ST rename', () => {
  it('plans a rename from the body and refuses names that clash, with the reason', () => {
    const p = makeProject();
    const main = pouId(p, 'Main');
    expect(planStRename(p, main, MAIN, at(MAIN, 'Lev|el :='), 'TankLevel')).toEqual({
      ok: true,
      scope: main,
      from: 'Level',
      to: 'TankLevel',
      bodies: 1,
    });
    const refuse = (marker: string, to: string) => {
      const r = planStRename(p, main, MAIN, at(MAIN, marker), to);
      return r.ok ? 'ok' : r.reason;
    };
    expect(refuse('Lev|el :=', 'Raw')).toBe('"Raw" is already declared in Main');
    expect(refuse('Lev|el :=', 'Alarm')).toBe(
      '"Alarm" would hide the global variable Alarm in Main (LD-W05)',
    );
    expect(refuse('Lev|el :=', 'END_IF')).toBe('"END_IF" is a keyword of IEC 61131-3');
    expect(refuse('Lev|el :=', '2x')).toMatch(/not a valid name/);
    expect(refuse('Lev|el :=', 'Scale')).toBe('"Scale" is the name of the function Scale');
    expect(refuse('Lev|el :=', 'TON')).toBe('"TON" is the standard function block TON');
    expect(refuse('Lev|el :=', 'GREEN')).toBe('"GREEN" is a value of the enumeration Color');
    expect(refuse('Motor1.|Q', 'Done')).toMatch(/belongs to TON, which is not a POU of this project/);
    expect(refuse('Sca|le(', 'Scale2')).toMatch(/rename it in the project tree/);
  });

  it('renames the uses of a variable in its body only: not members, not parameter names, not comments', () => {
    const p = makeProject('In := 1.0; (* In *) x := Scale(In := In, Lo := 0.0, Hi := 1.0); y := H1.In;\n');
    const main = p.pous[0]!;
    const q = {
      ...p,
      pous: [{ ...main, variables: [...main.variables, v('In', 'REAL')] }, ...p.pous.slice(1)],
    };
    const edits = stRenameEdits(q, main.id, v('In', 'REAL'), 'Inp');
    expect(edits.map((e) => e.after)).toEqual([
      'Inp := 1.0; (* In *) x := Scale(In := Inp, Lo := 0.0, Hi := 1.0); y := H1.In;\n',
    ]);
  });

  it('renaming an input of a FUNCTION_BLOCK renames its body, `Inst.Pin` and named arguments in callers', () => {
    const p = makeProject(`${MAIN}y := H1.Limit;\n`);
    const edits = stRenameEdits(p, pouId(p, 'Hyst'), p.pous[2]!.variables[1]!, 'Level_On');
    const after = new Map(edits.map((e) => [p.pous.find((x) => x.id === e.pou)!.name, e.after]));
    expect(after.get('Hyst')).toBe(HYST.replaceAll('Limit', 'Level_On'));
    expect(after.get('Main')).toContain('H1(X := Level, Level_On := 80.0);');
    expect(after.get('Main')).toContain('y := H1.Level_On;');
  });

  it('through the document store: body, declaration and LD callers change as one undo step', () => {
    const p = makeProject();
    const doc = createDocumentStore(p);
    const hyst = pouId(p, 'Hyst');
    const r = renameVariable(doc, 'X', 'Value', [hyst]);
    expect(r).toEqual({ ok: true });
    const now = doc.getState().project;
    const by = (n: string) => now.pous.find((x) => x.name === n)!;
    expect(by('Hyst').variables[0]!.name).toBe('Value');
    expect(by('Hyst').source).toBe(HYST.replaceAll('X ', 'Value '));
    expect(by('Main').source).toContain('H1(Value := Level, Limit := 80.0);');
    const box = by('Ladder').networks[0]!.elements.find((e) => e.kind === 'box');
    expect(box && box.kind === 'box' && box.inputs).toEqual({ Value: 'Level2', Limit: '50.0' });
    expect(checkProject(now).filter((d) => d.severity === 'error')).toEqual([]);
    doc.getState().undo();
    expect(doc.getState().project.pous.map((x) => x.source)).toEqual(p.pous.map((x) => x.source));
    expect(doc.getState().project.pous[2]!.variables[0]!.name).toBe('X');
  });

  it('a global renamed from an ST body follows in every POU that does not hide it', () => {
    const p = makeProject();
    const doc = createDocumentStore(p);
    const plan = planStRename(p, pouId(p, 'Main'), MAIN, at(MAIN, 'Ala|rm'), 'Horn');
    expect(plan).toMatchObject({ ok: true, scope: 'globals', from: 'Alarm' });
    if (!plan.ok) return;
    renameVariable(doc, plan.from, plan.to, [plan.scope]);
    const now = doc.getState().project;
    expect(now.globals[0]!.name).toBe('Horn');
    expect(now.pous[0]!.source).toContain('Horn := H1.Q AND Motor1.Q;');
  });
});
