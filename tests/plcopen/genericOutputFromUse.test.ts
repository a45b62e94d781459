// A generic function whose output type is its own (LEN, FIND: ANY_INT) takes the type of the block
// input its line goes to, as MATIEC types the call from its use (found by the differential fuzzer,
// docs/fuzz.md; reference trace: tests/fixtures/reference/fz-generic-output-from-use).
import { describe, expect, it } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { run } from './fixtures';
import { ldXml, type LdVar } from './ldXml';

const vars: LdVar[] = [
  { name: 'Text', type: 'STRING' },
  { name: 'W', type: 'INT' },
  { name: 'Size', type: 'DINT' },
  { name: 'Offset', type: 'INT' },
  { name: 'Big', type: 'DINT' },
];

function load(xml: string) {
  const r = importPlcopen(xml);
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return r.project;
}
const errors = (xml: string) =>
  checkProject(load(xml))
    .filter((d) => d.severity === 'error')
    .map((d) => `${d.rule} ${d.message}`);

describe('a generic output typed by the input it is wired to', () => {
  const lenToDint = ldXml(vars, [
    {
      objects: [
        { id: 1, kind: 'block', type: 'LEN', inputs: { IN: ['=Text'] }, outputs: ['OUT'] },
        {
          id: 2,
          kind: 'block',
          type: 'INT_TO_DINT',
          inputs: { IN: ['1.OUT'] },
          outputs: ['OUT'],
          assign: { OUT: 'Size' },
        },
      ],
    },
  ]);
  const findMinusInt = ldXml(vars, [
    {
      objects: [
        { id: 1, kind: 'block', type: 'FIND', inputs: { IN1: ['=Text'], IN2: ["='ve'"] }, outputs: ['OUT'] },
        {
          id: 2,
          kind: 'block',
          type: 'SUB',
          inputs: { IN1: ['1.OUT'], IN2: ['=W'] },
          outputs: ['OUT'],
          assign: { OUT: 'Offset' },
        },
      ],
    },
  ]);

  it('LEN into INT_TO_DINT is an INT (no "needs INT but its line carries DINT")', () => {
    expect(errors(lenToDint)).toEqual([]);
    const project = load(lenToDint);
    const plc = run(project, 'Main');
    plc.write('Text', 'conveyor');
    plc.scan();
    expect(plc.read('Size')).toBe(8);
  });

  it('FIND into SUB beside an INT variable is an INT, so SUB writes an INT', () => {
    expect(errors(findMinusInt)).toEqual([]);
    const plc = run(load(findMinusInt), 'Main');
    plc.write('Text', 'conveyor');
    plc.write('W', 7);
    plc.scan();
    expect(plc.read('Offset')).toBe(-3);
  });

  it('a typed mismatch further on is still an error (FIND into SUB beside a DINT, written to an INT)', () => {
    const xml = ldXml(vars, [
      {
        objects: [
          {
            id: 1,
            kind: 'block',
            type: 'FIND',
            inputs: { IN1: ['=Text'], IN2: ["='ve'"] },
            outputs: ['OUT'],
          },
          {
            id: 2,
            kind: 'block',
            type: 'SUB',
            inputs: { IN1: ['1.OUT'], IN2: ['=Big'] },
            outputs: ['OUT'],
            assign: { OUT: 'Offset' },
          },
        ],
      },
    ]);
    expect(errors(xml).join('\n')).toMatch(/LD-R11 .*SUB.* gives DINT but "Offset" is INT/);
  });
});
