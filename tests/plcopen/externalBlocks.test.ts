// Blocks of no known library (issue 12 part 5): the call imports with its wiring as an external
// block with the pins the file wires, the rest of the program runs, and the import says so. Calls
// of a shipped vendor block are named in the import report.
import { describe, expect, test } from 'vitest';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { checkProject } from '../../src/engine/check';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { ldXml } from './ldXml';

const vars = [
  { name: 'Start', type: 'BOOL' },
  { name: 'Lamp', type: 'BOOL' },
  { name: 'Level', type: 'INT' },
  { name: 'Reading', type: 'REAL' },
  { name: 'Ready', type: 'BOOL' },
  { name: 'Sensor1', type: 'ACME_SENSOR' },
  { name: 'Knob', type: 'ROTARY_SWITCH' },
];

describe('unknown and vendor blocks on import', () => {
  const xml = ldXml(vars, [
    {
      objects: [
        { id: 1, kind: 'contact', v: 'Start', in: ['rail'] },
        {
          id: 2,
          kind: 'block',
          type: 'ACME_SENSOR',
          instance: 'Sensor1',
          inputs: { ENABLE: ['1'], CHANNEL: ['=Level'] },
          outputs: ['READY', 'VALUE'],
          assign: { VALUE: 'Reading' },
        },
        { id: 3, kind: 'coil', v: 'Ready', in: ['2.READY'] },
      ],
      toRail: [3],
    },
    {
      objects: [
        { id: 4, kind: 'contact', v: 'Start', in: ['rail'] },
        { id: 5, kind: 'coil', v: 'Lamp', in: ['4'] },
      ],
      toRail: [5],
    },
    {
      objects: [
        { id: 6, kind: 'block', type: 'ROTARY_SWITCH', instance: 'Knob', inputs: {}, outputs: [] },
      ],
    },
  ]);

  test('an unknown FB becomes an external block with the wired pins and types; the program runs', () => {
    const r = importPlcopen(xml);
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    expect(r.project.externalBlocks).toEqual([
      expect.objectContaining({
        name: 'ACME_SENSOR',
        kind: 'FUNCTION_BLOCK',
        pins: [
          { name: 'ENABLE', dir: 'in', type: 'BOOL' },
          { name: 'CHANNEL', dir: 'in', type: 'INT' },
          { name: 'READY', dir: 'out', type: 'BOOL' },
          { name: 'VALUE', dir: 'out', type: 'REAL' },
        ],
      }),
    ]);
    const messages = r.report.warnings.map((w) => w.message);
    expect(messages.some((m) => /ACME_SENSOR .*external block with the pins the file wires \(ENABLE, CHANNEL, READY, VALUE\)/.test(m))).toBe(true);
    expect(messages.some((m) => /ROTARY_SWITCH \(OpenPLC .*\) is an external block/.test(m))).toBe(true);
    const box = r.project.pous[0]!.networks.flatMap((n) => n.elements).find((e) => e.kind === 'box' && e.blockType === 'ACME_SENSOR');
    expect(box).toMatchObject({ instance: 'Sensor1', inputs: { CHANNEL: 'Level' }, outputs: { VALUE: 'Reading' } });
    expect(checkProject(r.project).filter((d) => d.severity === 'error')).toEqual([]);
    const { program } = compileProgram(r.project);
    const plc = createPlc(program!, { cycleMs: 10 });
    plc.write('Start', true);
    plc.scan();
    // The rest of the program runs; the external block's outputs hold their initial values until set.
    expect(plc.read('Lamp')).toBe(true);
    expect(plc.read('Ready')).toBe(false);
    plc.force('Sensor1.READY', true);
    plc.scan();
    expect(plc.read('Ready')).toBe(true);
  });
});
