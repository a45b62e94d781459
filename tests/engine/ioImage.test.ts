// Plc.ioImage (issue 26): the input and output images by index, for a caller that reads and writes
// many points every scan (a machine in closed loop): what it writes is what setInputs would have
// written (converted, counted as an input change, latched at the next scan, a force still wins).
import { describe, expect, test } from 'vitest';
import { ladder, plcOf, project, vars } from './ladder';

const seal = () =>
  project(vars('Start BOOL %IX0.0', 'Stop BOOL %IX0.1', 'Speed INT %IW0', 'Motor BOOL %QX0.0', 'Lamp BOOL %QX0.1'), [
    ladder(['[Start] + [/Stop] (Motor)', '[Motor] + . .']),
    ladder(['[Motor] - - (Lamp)']),
  ]);

describe('the I/O image by index', () => {
  test('indices by location; inputs latched at the next scan; the output image as the scan left it', () => {
    const plc = plcOf(seal());
    const io = plc.ioImage!();
    expect(plc.ioImage!()).toBe(io);
    const start = io.input('%IX0.0');
    const motor = io.output('%QX0.0');
    const stop = io.input('%IX0.1');
    expect([start, stop, motor].every((i) => i >= 0)).toBe(true);
    expect(stop).not.toBe(start);
    // An output is not an input and the other way round; nothing declared there: -1.
    expect([io.input('%QX0.0'), io.output('%IX0.0'), io.input('%IX7.7')]).toEqual([-1, -1, -1]);
    io.write(start, true);
    expect(io.inputs[start]).toBe(true);
    expect(plc.read('Start')).toBe(false);
    plc.scan();
    expect(plc.read('Start')).toBe(true);
    expect(io.outputs[motor]).toBe(true);
    expect(io.outputs[io.output('%QX0.1')]).toBe(true);
  });

  test('a write is converted to the variable’s type and counted as an input change; a forced input keeps its force', () => {
    const plc = plcOf(seal());
    const io = plc.ioImage!();
    const meters = plc.probe!().meters;
    const before = meters[0]!;
    io.write(io.input('%IW0'), 1234);
    expect(meters[0]).toBe(before + 1);
    expect(() => io.write(io.input('%IW0'), 'fast' as never)).toThrow();
    plc.force('Start', false);
    io.write(io.input('%IX0.0'), true);
    plc.scan();
    expect(plc.read('Start')).toBe(false);
    expect(plc.read('Speed')).toBe(1234);
    plc.unforce('Start');
    plc.scan();
    expect(plc.read('Start')).toBe(true);
  });
});
