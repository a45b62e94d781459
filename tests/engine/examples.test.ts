import { describe, expect, test } from 'vitest';
import { EXAMPLES } from '../../src/model/examples';
import { checkProject } from '../../src/engine/check';
import { formatDiagnostic } from '../../src/engine/compile/report';
import { validateProject } from '../../src/model/load';
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { Plc } from '../../src/engine/api';

const plcFor = (id: string): Plc => {
  const example = EXAMPLES.find((e) => e.id === id)!;
  const { program } = compileProgram(example.build());
  return createPlc(program!, { cycleMs: 100 });
};

describe('example projects', () => {
  test.each(EXAMPLES.map((e) => [e.id, e] as const))(
    '%s loads and checks with no error and no warning',
    (_id, example) => {
      const project = example.build();
      expect(validateProject(JSON.parse(JSON.stringify(project)))).toMatchObject({ ok: true });
      expect(checkProject(project).map(formatDiagnostic)).toEqual([]);
    },
  );

  test('the four promised examples are offered', () => {
    expect(EXAMPLES.map((e) => e.id)).toEqual([
      'motor-start-stop',
      'traffic-light',
      'parts-counter',
      'jump-label',
    ]);
  });

  test('motor start/stop: Start seals the motor in, Stop drops it', () => {
    const plc = plcFor('motor-start-stop');
    plc.setInputs({ '%IX0.0': true });
    plc.scan();
    expect(plc.outputs()).toEqual({ '%QX0.0': true });
    plc.setInputs({ '%IX0.0': false });
    plc.scans(3);
    expect(plc.outputs()['%QX0.0']).toBe(true);
    plc.setInputs({ '%IX0.1': true });
    plc.scan();
    expect(plc.outputs()['%QX0.0']).toBe(false);
    plc.setInputs({ '%IX0.1': false });
    plc.scan();
    expect(plc.outputs()['%QX0.0']).toBe(false);
  });

  test('traffic light: red 5 s, green 4 s, yellow 1 s, then red again (100 ms scans)', () => {
    const plc = plcFor('traffic-light');
    const lamps = () => (['Red', 'Green', 'Yellow'] as const).filter((l) => plc.read(l) === true).join('+');
    const seen: string[] = [];
    for (let k = 1; k <= 240; k++) {
      plc.scan();
      seen.push(`${plc.timeMs}:${lamps()}`);
    }
    const at = (ms: number) => seen.find((s) => s.startsWith(`${ms}:`))!.split(':')[1];
    expect(at(0)).toBe('Red');
    expect(at(4900)).toBe('Red');
    expect(at(5000)).toBe('Green');
    expect(at(8900)).toBe('Green');
    expect(at(9000)).toBe('Yellow');
    expect(at(9900)).toBe('Yellow');
    expect(at(10000)).toBe('Yellow'); // YellowTime.Q is ON; the chain resets in the next scan
    expect(at(10100)).toBe('Red');
    // The red timer restarts one scan later (its IN was OFF for one scan): 10200 + 5000.
    expect(at(15100)).toBe('Red');
    expect(at(15200)).toBe('Green');
    // Exactly one lamp at any time.
    expect(seen.every((s) => ['Red', 'Green', 'Yellow'].includes(s.split(':')[1]!))).toBe(true);
  });

  test('parts counter: Done after 10 parts, Reset clears the count', () => {
    const plc = plcFor('parts-counter');
    for (let part = 1; part <= 10; part++) {
      plc.setInputs({ '%IX0.0': true });
      plc.scan();
      plc.setInputs({ '%IX0.0': false });
      plc.scan();
      expect(plc.read('PartCount')).toBe(part);
      expect(plc.outputs()['%QX0.0']).toBe(part >= 10);
    }
    plc.setInputs({ '%IX0.1': true });
    plc.scan();
    expect(plc.read('PartCount')).toBe(0);
    expect(plc.outputs()['%QX0.0']).toBe(false);
  });

  test('jump-label: in maintenance the conveyor network is skipped and keeps its output', () => {
    const plc = plcFor('jump-label');
    plc.setInputs({ '%IX0.1': true });
    plc.scan();
    expect(plc.read('Conveyor')).toBe(true);
    plc.setInputs({ '%IX0.0': true, '%IX0.1': false });
    plc.scan();
    expect(plc.read('Conveyor')).toBe(true);
    expect(plc.read('MaintenanceLamp')).toBe(true);
    expect(plc.snapshot().networks.map((n) => n.executed)).toEqual([true, false, true]);
    plc.setInputs({ '%IX0.0': false });
    plc.scan();
    expect(plc.read('Conveyor')).toBe(false);
  });
});
