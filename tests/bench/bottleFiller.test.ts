// The generated bottle filler (bench/bottleFiller.ts) is a valid, runnable program, and its copies
// are renumbered as the editor's paste renumbers them.
import { describe, expect, it } from 'vitest';
import { bottleFiller, bottleFillerProject } from '../../bench/bottleFiller';
import { checkProject } from '../../src/engine/check';
import { compileProgram, createPlc } from '../../src/engine/plc';

describe('bench bottle filler', () => {
  it('is the issue 24 station: 13 networks, FB Conveyor twice, 15 addressed globals, two tasks, no problem', () => {
    const p = bottleFiller();
    const main = p.pous[0]!;
    expect(main.networks).toHaveLength(13);
    expect(p.globals).toHaveLength(15);
    expect(p.globals.every((g) => g.location && g.comment)).toBe(true);
    expect(p.tasks).toHaveLength(2);
    const boxes = main.networks.flatMap((n) => n.elements.filter((e) => e.kind === 'box'));
    expect(boxes.map((b) => b.kind === 'box' && b.blockType).sort()).toEqual(['CTU', 'Conveyor', 'Conveyor', 'TON']);
    expect(main.networks.flatMap((n) => n.elements.filter((e) => e.kind === 'jump'))).toHaveLength(2);
    expect(checkProject(p)).toEqual([]);
  });

  it('runs: Start seals the line in and the infeed conveyor runs until a bottle is under the nozzle', () => {
    const { program } = compileProgram(bottleFiller());
    const plc = createPlc(program!, { cycleMs: 10, maxScanMs: 60_000 });
    plc.write('Start', true);
    plc.scan();
    plc.write('Start', false);
    plc.scan();
    expect(plc.read('Running')).toBe(true);
    expect(plc.read('InfeedMotor')).toBe(true);
    plc.write('BottleAtFill', true);
    plc.scan();
    expect(plc.read('InfeedMotor')).toBe(false);
    expect(plc.read('FillValve')).toBe(true);
  });

  it('50 copies are 650 networks with their own instances and labels, and check clean', () => {
    const p = bottleFillerProject(50);
    const main = p.pous[0]!;
    expect(main.networks).toHaveLength(650);
    expect(main.networks.filter((n) => n.label).map((n) => n.label).slice(-2)).toEqual(['MAINT50', 'DONE50']);
    expect(main.variables.map((v) => v.name)).toContain('InfeedConv50');
    expect(checkProject(p)).toEqual([]);
    expect(compileProgram(p).program).toBeDefined();
  });
});
