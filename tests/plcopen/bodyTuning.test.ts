// Reading a body in batches and sharing layouts between networks of one shape are speed-ups
// only: the imported project and the findings must not depend on them.
import { readdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import type { Project } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import type { BodyTuning } from '../../src/plcopen/importBody';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import type { ImportReport } from '../../src/plcopen/types';
import { bool, box, coil, contact, links, net, pou, project, vlink } from './build';
import { canonical, fixture } from './fixtures';

function load(xml: string, tuning?: BodyTuning): { project: Project; report: ImportReport } {
  const r = importPlcopen(xml, tuning);
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return r;
}

const files = [
  ...readdirSync(fileURLToPath(new URL('../fixtures/plcopen', import.meta.url))).filter((f) =>
    f.endsWith('.xml'),
  ),
  ...readdirSync(fileURLToPath(new URL('../fixtures/plcopen/corpus', import.meta.url)))
    .filter((f) => f.endsWith('.xml'))
    .map((f) => `corpus/${f}`),
];

describe('batches and shared layouts change nothing', () => {
  it.each(files)('%s imports the same in batches of 3 objects and without shared layouts', (name) => {
    const xml = fixture(name);
    const base = load(xml);
    for (const tuning of [
      { batchObjects: 3 },
      { shareLayouts: false },
      { batchObjects: 1, shareLayouts: false },
    ]) {
      const other = load(xml, tuning);
      expect(canonical(other.project), JSON.stringify(tuning)).toBe(canonical(base.project));
      expect(other.report.warnings).toEqual(base.report.warnings);
    }
  });

  it('a wide network after many narrow ones leaves them narrow, in every batch', () => {
    const narrow = (i: number) => net(1, 3, [contact(0, 0, `A${i}`), ...links(0, 1, 2), coil(0, 2, `Q${i}`)]);
    // Six contacts in series: the widest network comes last.
    const wide = net(1, 8, [
      ...Array.from({ length: 6 }, (_, k) => contact(0, k, `B${k}`)),
      ...links(0, 6, 7),
      coil(0, 7, 'W'),
    ]);
    const vars = [
      ...Array.from({ length: 20 }, (_, i) => [bool(`A${i}`), bool(`Q${i}`)]).flat(),
      ...Array.from({ length: 6 }, (_, k) => bool(`B${k}`)),
      bool('W'),
    ];
    const xml = exportPlcopen(
      project([pou('Main', vars, [...Array.from({ length: 20 }, (_, i) => narrow(i)), wide])]),
    );
    const base = load(xml);
    const batched = load(xml, { batchObjects: 4 });
    const nets = batched.project.pous[0]!.networks;
    expect(nets).toHaveLength(21);
    expect(nets.slice(0, 20).map((n) => n.cols)).toEqual(Array.from({ length: 20 }, () => 3));
    expect(nets[20]!.cols).toBe(7);
    expect(canonical(batched.project)).toBe(canonical(base.project));
  });

  it('networks of one shape share a layout but keep their own variables and instances', () => {
    const timer = (i: number) =>
      net(2, 5, [
        contact(0, 0, `S${i}`),
        box(0, 1, 'TON', { PT: `T#${i + 1}s` }, {}, `T${i}`),
        ...links(0, 3, 4),
        coil(0, 4, `Q${i}`),
      ]);
    const sealIn = (i: number) =>
      net(
        2,
        4,
        [
          contact(0, 0, `S${i}`),
          contact(0, 1, `X${i}`, 'NC'),
          ...links(0, 2, 3),
          coil(0, 3, `Q${i}`),
          contact(1, 0, `Q${i}`),
        ],
        [vlink(0, 1)],
      );
    const vars = Array.from({ length: 4 }, (_, i) => [
      bool(`S${i}`),
      bool(`X${i}`),
      bool(`Q${i}`),
      { ...bool(`T${i}`), type: 'TON' },
    ]).flat();
    const xml = exportPlcopen(project([pou('Main', vars, [timer(0), sealIn(1), timer(2), sealIn(3)])]));
    const shared = load(xml);
    expect(canonical(shared.project)).toBe(canonical(load(xml, { shareLayouts: false }).project));
    const nets = shared.project.pous[0]!.networks;
    const variables = (i: number) =>
      nets[i]!.elements.flatMap((e) =>
        'variable' in e ? [e.variable] : 'instance' in e ? [e.instance, e.inputs.PT] : [],
      );
    expect(variables(0)).toEqual(expect.arrayContaining(['S0', 'T0', 'T#1s', 'Q0']));
    expect(variables(2)).toEqual(expect.arrayContaining(['S2', 'T2', 'T#3s', 'Q2']));
    expect(variables(3)).toEqual(expect.arrayContaining(['S3', 'X3', 'Q3']));
    // Same cells, fresh ids.
    const cells = (i: number) => nets[i]!.elements.map((e) => `${e.kind}@${e.row},${e.col}`);
    expect(cells(2)).toEqual(cells(0));
    expect(cells(3)).toEqual(cells(1));
    const ids = nets.flatMap((n) => n.elements.map((e) => e.id));
    expect(new Set(ids).size).toBe(ids.length);
  });
});

/** Two networks drawn on one left rail and one right rail (as some editors write them). */
const sharedRails = `<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Main" pouType="program">
      <interface><localVars>
        <variable name="A"><type><BOOL/></type></variable><variable name="B"><type><BOOL/></type></variable>
        <variable name="X"><type><BOOL/></type></variable><variable name="Y"><type><BOOL/></type></variable>
      </localVars></interface>
      <body><LD>
        <leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/><connectionPointOut formalParameter=""/></leftPowerRail>
        <contact localId="2"><position x="20" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>A</variable></contact>
        <coil localId="3"><position x="80" y="10"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>X</variable></coil>
        <contact localId="4"><position x="20" y="60"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>B</variable></contact>
        <coil localId="5"><position x="80" y="60"/><connectionPointIn><connection refLocalId="4"/></connectionPointIn><connectionPointOut/><variable>Y</variable></coil>
        <rightPowerRail localId="6"><position x="120" y="0"/><connectionPointIn><connection refLocalId="3"/></connectionPointIn><connectionPointIn><connection refLocalId="5"/></connectionPointIn></rightPowerRail>
      </LD></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>`;

describe('batches of a body with shared rails and broken references', () => {
  it('rails shared by networks in different batches serve each of them', () => {
    const base = load(sharedRails);
    const batched = load(sharedRails, { batchObjects: 1 });
    expect(batched.project.pous[0]!.networks).toHaveLength(2);
    expect(canonical(batched.project)).toBe(canonical(base.project));
  });

  it('a wire to a missing localId is dropped with a warning naming it, in batches too', () => {
    const r = importPlcopen(
      sharedRails.replace(
        '<connection refLocalId="4"/></connectionPointIn><connectionPointOut/><variable>Y',
        '<connection refLocalId="44"/></connectionPointIn><connectionPointOut/><variable>Y',
      ),
      { batchObjects: 1 },
    );
    expect(r.ok).toBe(true);
    if (r.ok)
      expect(r.report.warnings.map((w) => w.message)).toContainEqual(
        expect.stringMatching(/localId 5 is connected to localId 44, which does not exist; that wire is dropped/),
      );
  });

  it('a localId used twice is still an error, even when the two objects are far apart', () => {
    const r = importPlcopen(
      sharedRails
        .replace('<coil localId="5">', '<coil localId="2">')
        .replace('refLocalId="5"', 'refLocalId="2"'),
      { batchObjects: 1 },
    );
    expect(r.ok).toBe(false);
    if (!r.ok) expect(r.errors[0]!.message).toMatch(/localId 2 is used twice/);
  });
});
