// Wiring shapes the graph-to-grid layout once drew wrongly (issue 12 §1), as graphs. The fixtures
// tests/fixtures/plcopen/layout-<name>.xml are these graphs written by ldXml (regenerate with
// `npx tsx tests/plcopen/layoutCases.ts`); layoutExact.test.ts checks that each imports exactly.
import { writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { ldXml, type LdNetwork, type LdVar } from './ldXml';

export interface LayoutCase {
  readonly name: string;
  readonly about: string;
  readonly vars: LdVar[];
  readonly networks: LdNetwork[];
  /** The grid routes some wire through a connector/continuation pair (it cannot route it directly). */
  readonly connectors?: boolean;
}

const bools = (...n: string[]): LdVar[] => n.map((name) => ({ name, type: 'BOOL' }));

export const CASES: LayoutCase[] = [
  {
    name: 'ctud-outputs',
    about: 'CTUD with QU to two coils in parallel, QD to a coil, CV to a variable (CV was joined to QD)',
    vars: [
      ...bools('Up', 'Down', 'Rst', 'Load', 'A', 'B', 'C'),
      { name: 'Count', type: 'INT' },
      { name: 'C1', type: 'CTUD' },
    ],
    networks: [
      {
        objects: [
          { id: 1, kind: 'contact', v: 'Up', in: ['rail'] },
          { id: 2, kind: 'contact', v: 'Down', in: ['rail'] },
          { id: 3, kind: 'contact', v: 'Rst', in: ['rail'] },
          { id: 4, kind: 'contact', v: 'Load', in: ['rail'] },
          {
            id: 5,
            kind: 'block',
            type: 'CTUD',
            instance: 'C1',
            inputs: { CU: ['1'], CD: ['2'], R: ['3'], LD: ['4'], PV: ['=3'] },
            outputs: ['QU', 'QD', 'CV'],
            assign: { CV: 'Count' },
          },
          { id: 6, kind: 'coil', v: 'A', in: ['5.QU'] },
          { id: 7, kind: 'coil', v: 'B', in: ['5.QU'] },
          { id: 8, kind: 'coil', v: 'C', in: ['5.QD'] },
        ],
        toRail: [6, 7, 8],
      },
    ],
  },
  {
    name: 'nested-or',
    about:
      '(I0 OR (I3 AND (I4 OR I5)) OR I6) -> Q7 (I6 split the inner OR, a contact was fed from its right)',
    vars: bools('I0', 'I3', 'I4', 'I5', 'I6', 'Q7'),
    networks: [
      {
        objects: [
          { id: 1, kind: 'contact', v: 'I0', in: ['rail'] },
          { id: 2, kind: 'contact', v: 'I3', in: ['rail'] },
          { id: 3, kind: 'contact', v: 'I4', in: ['2'] },
          { id: 4, kind: 'contact', v: 'I5', in: ['2'] },
          { id: 5, kind: 'contact', v: 'I6', in: ['rail'] },
          { id: 6, kind: 'coil', v: 'Q7', in: ['1', '3', '4', '5'] },
        ],
        toRail: [6],
      },
    ],
  },
  {
    name: 'fanout-block-inputs',
    connectors: true,
    about: 'one contact feeding a TON, a CTU and a coil; a second contact feeding the CTU reset',
    vars: [...bools('A', 'R', 'X', 'Y', 'Z'), { name: 'T1', type: 'TON' }, { name: 'K1', type: 'CTU' }],
    networks: [
      {
        objects: [
          { id: 1, kind: 'contact', v: 'A', in: ['rail'] },
          { id: 2, kind: 'contact', v: 'R', in: ['rail'] },
          {
            id: 3,
            kind: 'block',
            type: 'TON',
            instance: 'T1',
            inputs: { IN: ['1'], PT: ['=T#30ms'] },
            outputs: ['Q', 'ET'],
          },
          {
            id: 4,
            kind: 'block',
            type: 'CTU',
            instance: 'K1',
            inputs: { CU: ['1'], R: ['2'], PV: ['=2'] },
            outputs: ['Q', 'CV'],
          },
          { id: 5, kind: 'coil', v: 'X', in: ['3.Q'] },
          { id: 6, kind: 'coil', v: 'Y', in: ['4.Q'] },
          { id: 7, kind: 'coil', v: 'Z', in: ['1'] },
        ],
        toRail: [5, 6, 7],
      },
    ],
  },
  {
    name: 'coils-after-block',
    about: 'TON.Q into two coils in series and a set coil in parallel',
    vars: [...bools('A', 'P', 'Q', 'S'), { name: 'T1', type: 'TON' }],
    networks: [
      {
        objects: [
          { id: 1, kind: 'contact', v: 'A', in: ['rail'] },
          {
            id: 2,
            kind: 'block',
            type: 'TON',
            instance: 'T1',
            inputs: { IN: ['1'], PT: ['=T#20ms'] },
            outputs: ['Q', 'ET'],
          },
          { id: 3, kind: 'coil', v: 'P', in: ['2.Q'] },
          { id: 4, kind: 'coil', v: 'Q', in: ['3'] },
          { id: 5, kind: 'coil', v: 'S', storage: 'set', in: ['2.Q'] },
        ],
        toRail: [4, 5],
      },
    ],
  },
  {
    name: 'block-output-two-contacts',
    connectors: true,
    about: "a TON's Q feeding two contacts, each into its own coil, and a CTU's Q ORed with one of them",
    vars: [...bools('A', 'B', 'C', 'X', 'Y'), { name: 'T1', type: 'TON' }, { name: 'K1', type: 'CTU' }],
    networks: [
      {
        objects: [
          { id: 1, kind: 'contact', v: 'A', in: ['rail'] },
          {
            id: 2,
            kind: 'block',
            type: 'TON',
            instance: 'T1',
            inputs: { IN: ['1'], PT: ['=T#20ms'] },
            outputs: ['Q', 'ET'],
          },
          { id: 3, kind: 'contact', v: 'B', in: ['2.Q'] },
          { id: 4, kind: 'contact', v: 'C', neg: true, in: ['2.Q'] },
          {
            id: 5,
            kind: 'block',
            type: 'CTU',
            instance: 'K1',
            inputs: { CU: ['3'], R: ['rail'], PV: ['=5'] },
            outputs: ['Q', 'CV'],
          },
          { id: 6, kind: 'coil', v: 'X', in: ['3', '5.Q'] },
          { id: 7, kind: 'coil', v: 'Y', in: ['4'] },
        ],
        toRail: [6, 7],
      },
    ],
  },
  {
    name: 'output-into-two-ors',
    connectors: true,
    about: "one TON's Q into two different ORs: X := T1.Q OR B, Y := T1.Q OR C (vertical links are one-way)",
    vars: [...bools('A', 'B', 'C', 'X', 'Y'), { name: 'T1', type: 'TON' }],
    networks: [
      {
        objects: [
          { id: 1, kind: 'contact', v: 'A', in: ['rail'] },
          {
            id: 2,
            kind: 'block',
            type: 'TON',
            instance: 'T1',
            inputs: { IN: ['1'], PT: ['=T#20ms'] },
            outputs: ['Q', 'ET'],
          },
          { id: 3, kind: 'contact', v: 'B', in: ['rail'] },
          { id: 4, kind: 'contact', v: 'C', in: ['rail'] },
          { id: 5, kind: 'coil', v: 'X', in: ['2.Q', '3'] },
          { id: 6, kind: 'coil', v: 'Y', in: ['2.Q', '4'] },
        ],
        toRail: [5, 6],
      },
    ],
  },
  {
    name: 'contact-into-two-ors',
    about: 'an edge contact whose output joins two different ORs and a coil alone (X := A OR B, Y := A, Z := A OR C): drawn once per coil',
    vars: bools('A', 'B', 'C', 'X', 'Y', 'Z'),
    networks: [
      {
        objects: [
          { id: 1, kind: 'contact', v: 'A', edge: 'rising', in: ['rail'] },
          { id: 2, kind: 'contact', v: 'B', in: ['rail'] },
          { id: 3, kind: 'contact', v: 'C', in: ['rail'] },
          { id: 4, kind: 'coil', v: 'X', in: ['1', '2'] },
          { id: 5, kind: 'coil', v: 'Y', in: ['1'] },
          { id: 6, kind: 'coil', v: 'Z', in: ['1', '3'] },
        ],
        toRail: [4, 5, 6],
      },
    ],
  },
  {
    name: 'or-reset-from-block-below',
    connectors: true,
    about:
      'a CTU whose R is T1.Q OR a falling-edge contact, T1 drawn below and left of it and also driving a coil, PV from a variable (R and PV were joined: a false LD-R10)',
    vars: [...bools('A', 'B', 'C', 'X', 'Y'), { name: 'T1', type: 'TON' }, { name: 'K1', type: 'CTU' }],
    networks: [
      {
        objects: [
          { id: 1, kind: 'contact', v: 'A', in: ['rail'] },
          { id: 2, kind: 'contact', v: 'B', edge: 'falling', in: ['rail'] },
          { id: 3, kind: 'contact', v: 'C', in: ['rail'] },
          { id: 4, kind: 'block', type: 'TON', instance: 'T1', inputs: { IN: ['3'], PT: ['=T#50ms'] }, outputs: ['Q', 'ET'] },
          { id: 5, kind: 'block', type: 'CTU', instance: 'K1', inputs: { CU: ['1'], R: ['4.Q', '2'], PV: ['=3'] }, outputs: ['Q', 'CV'] },
          { id: 6, kind: 'coil', v: 'X', in: ['5.Q'] },
          { id: 7, kind: 'coil', v: 'Y', in: ['4.Q'] },
        ],
        toRail: [6, 7],
        pos: {
          1: { x: 100, y: 40 },
          2: { x: 100, y: 60 },
          3: { x: 50, y: 180 },
          4: { x: 80, y: 150 },
          5: { x: 200, y: 20 },
          6: { x: 400, y: 40 },
          7: { x: 400, y: 180 },
        },
      },
    ],
  },
  {
    name: 'or-set-above-wired-reset',
    connectors: true,
    about:
      'an SR whose S1 is F1.Q OR a contact (F1 drawn below-left, also in an OR with another contact into a coil) and whose R has a contact of its own (S1 and R were joined: R read S1\'s sources)',
    vars: [...bools('A', 'B', 'C', 'D', 'X', 'Y'), { name: 'F1', type: 'TOF' }, { name: 'S1', type: 'SR' }],
    networks: [
      {
        objects: [
          { id: 1, kind: 'contact', v: 'A', in: ['rail'] },
          { id: 2, kind: 'contact', v: 'B', in: ['rail'] },
          { id: 3, kind: 'contact', v: 'C', in: ['rail'] },
          { id: 4, kind: 'contact', v: 'D', in: ['rail'] },
          { id: 5, kind: 'block', type: 'TOF', instance: 'F1', inputs: { IN: ['4'], PT: ['=T#30ms'] }, outputs: ['Q', 'ET'] },
          { id: 6, kind: 'block', type: 'SR', instance: 'S1', inputs: { S1: ['5.Q', '2'], R: ['3'] }, outputs: ['Q1'] },
          { id: 7, kind: 'coil', v: 'X', in: ['6.Q1'] },
          { id: 8, kind: 'coil', v: 'Y', in: ['5.Q', '1'] },
        ],
        toRail: [7, 8],
        pos: {
          1: { x: 60, y: 40 },
          2: { x: 200, y: 60 },
          3: { x: 200, y: 80 },
          4: { x: 40, y: 190 },
          5: { x: 110, y: 160 },
          6: { x: 300, y: 40 },
          7: { x: 480, y: 60 },
          8: { x: 480, y: 180 },
        },
      },
    ],
  },
  {
    name: 'shared-contact-last-or',
    connectors: true,
    about:
      'a contact feeding a counter alone and, OR-ed with a timer drawn below, a coil; the timer also feeds the counter reset OR-ed with another contact (the contact was copied for both uses, its original left feeding nothing)',
    vars: [...bools('A', 'B', 'C', 'X', 'Y', 'Z'), { name: 'T1', type: 'TON' }, { name: 'K1', type: 'CTU' }],
    networks: [
      {
        objects: [
          { id: 1, kind: 'contact', v: 'A', in: ['rail'] },
          { id: 2, kind: 'contact', v: 'B', edge: 'falling', in: ['rail'] },
          { id: 3, kind: 'contact', v: 'C', in: ['rail'] },
          { id: 4, kind: 'block', type: 'TON', instance: 'T1', inputs: { IN: ['3'], PT: ['=T#50ms'] }, outputs: ['Q', 'ET'] },
          { id: 5, kind: 'block', type: 'CTU', instance: 'K1', inputs: { CU: ['1'], R: ['4.Q', '2'], PV: ['=3'] }, outputs: ['Q', 'CV'] },
          { id: 6, kind: 'coil', v: 'X', in: ['5.Q'] },
          { id: 7, kind: 'coil', v: 'Y', in: ['4.Q'] },
          { id: 8, kind: 'coil', v: 'Z', in: ['4.Q', '1'] },
        ],
        toRail: [6, 7, 8],
        pos: {
          1: { x: 100, y: 40 },
          2: { x: 100, y: 60 },
          3: { x: 50, y: 180 },
          4: { x: 80, y: 150 },
          5: { x: 200, y: 20 },
          6: { x: 400, y: 40 },
          7: { x: 400, y: 180 },
          8: { x: 400, y: 220 },
        },
      },
    ],
  },
];

if (process.argv[1] === fileURLToPath(import.meta.url))
  for (const c of CASES)
    writeFileSync(
      fileURLToPath(new URL(`../fixtures/plcopen/layout-${c.name}.xml`, import.meta.url)),
      ldXml(c.vars, c.networks).replace(
        '<types>',
        `<!-- Hand-written layout case: ${c.about} -->\n  <types>`,
      ),
    );
