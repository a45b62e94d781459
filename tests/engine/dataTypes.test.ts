import { describe, expect, it } from 'vitest';
import type { DataType, Pou, Project, Variable } from '../../src/model/project';
import { ladder, plcOf, project, trace, vars } from './ladder';
import { io, stErrors, stPlc, stProject, textPou } from './stHelpers';
import { checkProject } from '../../src/engine/check';
import { formatDiagnostic } from '../../src/engine/compile/report';

const TYPES: DataType[] = [
  { name: 'Color', def: { kind: 'enum', values: ['RED', 'GREEN', 'BLUE'] }, initial: 'GREEN' },
  {
    name: 'Valve',
    def: {
      kind: 'struct',
      members: [
        { name: 'Open', type: 'BOOL' },
        { name: 'Cmd', type: 'BOOL' },
        { name: 'Pos', type: 'INT', initial: '5' },
      ],
    },
  },
  { name: 'Grid', def: { kind: 'array', dims: [{ lower: 1, upper: 2 }, { lower: 1, upper: 3 }], of: 'BOOL' } },
  { name: 'Percent', def: { kind: 'subrange', base: 'INT', lower: 0, upper: 100 } },
];

const withTypes = (p: Project, types: readonly DataType[] = TYPES): Project => ({ ...p, dataTypes: types });

describe('data types in LD', () => {
  it('contacts, coils and pins name struct members and array elements with constant indexes', () => {
    const p = withTypes(
      project(vars('V Valve', 'G Grid', 'Lamp BOOL'), [
        ladder(['[V.Cmd] - (V.Open)']),
        ladder(['[G[2,3]] - (Lamp)']),
      ]),
    );
    const plc = plcOf(p);
    expect(plc.read('V.Pos')).toBe(5);
    expect(trace(plc, [{}, { 'V.Cmd': true }, { 'G[2,3]': true }], ['V.Open', 'Lamp'])).toEqual([
      [0, 0],
      [1, 0],
      [1, 1],
    ]);
  });
});

const POINT: DataType = {
  name: 'Point',
  def: { kind: 'struct', members: [{ name: 'X', type: 'INT' }, { name: 'Y', type: 'INT', initial: '2' }] },
};
const ST_TYPES: DataType[] = [
  ...TYPES,
  POINT,
  { name: 'Row', def: { kind: 'array', dims: [{ lower: 1, upper: 10 }], of: 'INT' } },
  { name: 'Poly', def: { kind: 'struct', members: [{ name: 'Pts', type: 'ARRAY[1..3] OF Point' }, { name: 'N', type: 'INT' }] } },
];

const stTyped = (source: string, variables: readonly Variable[], others: readonly Pou[] = []): Project =>
  ({ ...stProject([textPou('Main', 'PROGRAM', variables, source), ...others]), dataTypes: ST_TYPES });

describe('data types in ST', () => {
  it('reads and writes members, copies whole structures and sums an array in a loop with a variable index', () => {
    const plc = stPlc(
      stTyped(
        `FOR i := 1 TO 10 DO A[i] := i * i; END_FOR;
         Sum := 0;
         FOR i := 1 TO 10 DO Sum := Sum + A[i]; END_FOR;
         P1.X := P1.X + 1;
         P2 := P1;
         Pg.Pts[2] := P1;
         Pg.Pts[i - 9].Y := 7;
         Pg.N := Pg.Pts[2].X + Pg.Pts[1].Y;`,
        vars('A Row', 'i INT', 'Sum INT', 'P1 Point', 'P2 Point', 'Pg Poly'),
      ),
    );
    plc.scan();
    plc.scan();
    expect(['Sum', 'A[10]', 'P1.X', 'P2.X', 'P2.Y', 'Pg.Pts[2].X', 'Pg.Pts[2].Y', 'Pg.Pts[2].Y', 'Pg.N'].map((n) => plc.read(n))).toEqual([
      385, 100, 2, 2, 2, 2, 7, 7, 4,
    ]);
  });

  it('faults naming the POU, the line and the index when a variable index leaves the array (LD-E62)', () => {
    const plc = stPlc(stTyped('i := i + 1;\nA[i] := 1;', vars('A Row', 'i INT := 8')));
    expect(plc.scan().fault).toBeUndefined();
    expect(plc.scan().fault).toBeUndefined();
    const r = plc.scan();
    expect(r.fault).toMatchObject({ kind: 'runtime', pou: 'Main' });
    expect(r.fault!.message).toMatch(/^LD-E62 line 2: the index 11 of A is outside 1\.\.10; .*MATIEC does not check array bounds.* in Main$/);
    expect(stErrors(stTyped('A[11] := 1;', vars('A Row')))[0]).toMatch(/LD-E62 .*the index 11 of A is outside 1\.\.10/);
  });

  it('enum values as Color#RED or RED, compared and used as CASE labels', () => {
    const plc = stPlc(
      stTyped(
        `CASE C OF
           RED: C := Color#GREEN;
           GREEN: C := BLUE;
         ELSE C := RED; n := n + 1;
         END_CASE;
         IsBlue := C = BLUE;`,
        vars('C Color', 'n INT', 'IsBlue BOOL'),
      ),
    );
    expect(plc.read('C')).toBe(1); // GREEN, the type's initial value
    const seen = [0, 1, 2, 3].map(() => (plc.scan(), [plc.read('C'), plc.read('IsBlue')]));
    expect(seen).toEqual([[2, true], [0, false], [1, false], [2, true]]);
    expect(plc.read('n')).toBe(1);
    expect(stErrors(stTyped('C := Color#PINK;', vars('C Color')))[0]).toMatch(/PINK is not a value of Color \(RED, GREEN, BLUE\)/);
  });

  it('a literal outside a subrange is a compile error (LD-E61); computed values are not checked, as in MATIEC', () => {
    expect(stErrors(stTyped('P := 150;', vars('P Percent')))).toEqual([
      expect.stringMatching(/^error LD-E61 Main.* 150 is outside the subrange Percent \(0\.\.100\) of "P"/),
    ]);
    const plc = stPlc(stTyped('P := P + 60;', vars('P Percent')));
    plc.scan();
    plc.scan();
    expect(plc.read('P')).toBe(120);
  });

  it('a struct VAR_INPUT of a user FB is a copy of the argument', () => {
    const fb = textPou('Measure', 'FUNCTION_BLOCK', [...io('input', 'Pt Point'), ...io('output', 'Sum INT')], 'Sum := Pt.X + Pt.Y; Pt.X := 100;');
    const plc = stPlc(stTyped('P.X := 5; L1(Pt := P); s := L1.Sum;', vars('P Point', 'L1 Measure', 's INT'), [fb]));
    plc.scan();
    expect([plc.read('s'), plc.read('P.X'), plc.read('L1.Pt.X')]).toEqual([7, 5, 100]);
  });

  it('forcing an array element holds it against writes through a variable index', () => {
    const plc = stPlc(stTyped('FOR i := 1 TO 10 DO A[i] := 9; END_FOR;', vars('A Row', 'i INT')));
    plc.force('A[3]', 4);
    plc.scan();
    expect([plc.read('A[2]'), plc.read('A[3]')]).toEqual([9, 4]);
    plc.unforce('A[3]');
    plc.scan();
    expect(plc.read('A[3]')).toBe(9);
  });
});

describe('ST string literals', () => {
  it('reads $ escapes in STRING and WSTRING literals', () => {
    const plc = stPlc(stProject([textPou('Main', 'PROGRAM', vars('s STRING', 'w WSTRING', 'n INT'), `s := 'it$'s $$5$N$41$42'; w := "say $"hi$" $00e9"; n := LEN(s);`)]));
    plc.scan();
    expect([plc.read('s'), plc.read('w'), plc.read('n')]).toEqual(["it's $5\nAB", 'say "hi" é', 10]);
  });
});

describe('data type declarations', () => {
  it('reports broken type declarations (LD-E60) and variables of unknown types (LD-E15)', () => {
    const bad: DataType[] = [
      { name: 'Loop', def: { kind: 'struct', members: [{ name: 'Next', type: 'Loop' }] } },
      { name: 'Empty', def: { kind: 'subrange', base: 'INT', lower: 5, upper: 1 } },
    ];
    const p = withTypes(project(vars('A Nope', 'Lamp BOOL'), [ladder(['[Lamp] - (Lamp)'])]), bad);
    const errors = checkProject(p).filter((d) => d.severity === 'error').map(formatDiagnostic);
    expect(errors).toEqual([
      'error LD-E60 types/variables Loop: the data type Loop contains itself (LOOP -> LOOP)',
      'error LD-E60 types/variables Empty: the subrange Empty (5..1) is empty',
      expect.stringMatching(/^error LD-E15 Main\/variables .*"A" has the type "Nope", which cannot be used: "Nope" is not a type/),
    ]);
  });

  it('an alias of an elementary type (SVGHMI HMI_BOOL, HMI_INT) behaves as its base', () => {
    const p = project(vars('Count HMI_INT := 3', 'Run HMI_BOOL', 'Big BOOL'), [ladder(['[Run] - (Big)'])]);
    const plc = plcOf(p);
    expect(trace(plc, [{}, { Run: true }], ['Big', 'Count'])).toEqual([[0, 3], [1, 3]]);
  });
});
