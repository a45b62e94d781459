// Issue 22, section 2 item 11: in a configuration, a short name typed into the watch (Filling)
// resolves to its instance path when one instance has it, and the instance paths are offered as
// completions while typing.
import { describe, expect, test } from 'vitest';
import { completeWatchName, resolveWatchName } from '../../src/sim/watchNames';

const NAMES = ['MainInstance.Filling', 'MainInstance.Fill_Time', 'MainInstance.Start', 'MainInstance.T1.Q', 'Rinse.Start', 'Rinse.Done', 'Lamp'];
const INSTANCES = ['MainInstance', 'Rinse'];

describe('a short name in a configuration', () => {
  test('resolves to the one instance path that ends in it (any case)', () => {
    expect(resolveWatchName('Filling', NAMES, INSTANCES)).toEqual({ name: 'MainInstance.Filling', choices: ['MainInstance.Filling'] });
    expect(resolveWatchName(' filling ', NAMES, INSTANCES).name).toBe('MainInstance.Filling');
    expect(resolveWatchName('t1.q', NAMES, INSTANCES).name).toBe('MainInstance.T1.Q');
  });

  test('a name two instances have is not guessed: both paths are offered', () => {
    expect(resolveWatchName('Start', NAMES, INSTANCES)).toEqual({ choices: ['MainInstance.Start', 'Rinse.Start'] });
  });

  test('a full path or a global is taken as typed', () => {
    expect(resolveWatchName('rinse.done', NAMES, INSTANCES)).toEqual({ name: 'Rinse.Done', choices: [] });
    expect(resolveWatchName('Lamp', NAMES, INSTANCES)).toEqual({ name: 'Lamp', choices: [] });
  });

  test('while typing, the instance paths whose short name starts with the text are offered', () => {
    expect(resolveWatchName('Fil', NAMES, INSTANCES)).toEqual({ choices: ['MainInstance.Fill_Time', 'MainInstance.Filling'] });
    expect(resolveWatchName('Fill', NAMES, INSTANCES, 1).choices).toEqual(['MainInstance.Fill_Time']);
  });

  test('outside a configuration (no instances) nothing is guessed', () => {
    expect(resolveWatchName('Filling', ['Filling'], [])).toEqual({ name: 'Filling', choices: [] });
    expect(resolveWatchName('Fil', ['Filling'], [])).toEqual({ choices: [] });
    expect(resolveWatchName('', NAMES, INSTANCES)).toEqual({ choices: [] });
  });
});

describe('completion as a name is typed (issue 24)', () => {
  const READABLE = ['Start', 'Start2', 'Stop', 'Conv1.Motor', 'Conv1.Speed', 'Conv1.T1.ET', 'Conv1.T1.Q', 'Conv2.Motor', 'Buf[1]', 'Buf[2]', 'Buf[10]', 'T1.PT', 'T1.ET', 'MotorLamp'];

  test('an instance path lists its members, the direct ones first, then the nested ones', () => {
    expect(completeWatchName('conv1.', READABLE)).toEqual(['Conv1.Motor', 'Conv1.Speed', 'Conv1.T1.ET', 'Conv1.T1.Q']);
    expect(completeWatchName('Conv1.T', READABLE)).toEqual(['Conv1.T1.ET', 'Conv1.T1.Q']);
  });

  test('names starting with the text first, then a member named so in any instance, then names containing it', () => {
    expect(completeWatchName('Mot', READABLE)).toEqual(['MotorLamp', 'Conv1.Motor', 'Conv2.Motor']);
    expect(completeWatchName('eed', READABLE)).toEqual(['Conv1.Speed']);
  });

  test('array elements in index order; the typed name itself is not offered; a limit', () => {
    expect(completeWatchName('Buf', READABLE)).toEqual(['Buf[1]', 'Buf[2]', 'Buf[10]']);
    expect(completeWatchName('Start', READABLE)).toEqual(['Start2']);
    expect(completeWatchName('S', READABLE, 2)).toEqual(['Start', 'Start2']);
    expect(completeWatchName('  ', READABLE)).toEqual([]);
  });
});

describe("a machine's names that differ only by case", () => {
  const names = ['Pump', 'tank.level', 'tank.pump', 'tank.Pump', 'tank.HighLevel'];
  test('completion offers both spellings, and the exact one resolves to itself', () => {
    expect(completeWatchName('tank.p', names)).toEqual(['tank.pump', 'tank.Pump']);
    expect(completeWatchName('tank.pump', names)).toEqual(['tank.Pump']);
    expect(resolveWatchName('tank.Pump', names, []).name).toBe('tank.Pump');
    expect(resolveWatchName('tank.pump', names, []).name).toBe('tank.pump');
    expect(completeWatchName('tank.', names)).toEqual(['tank.HighLevel', 'tank.level', 'tank.pump', 'tank.Pump']);
  });
});
