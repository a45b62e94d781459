// Issue 22, section 2 item 11: in a configuration, a short name typed into the watch (Filling)
// resolves to its instance path when one instance has it, and the instance paths are offered as
// completions while typing.
import { describe, expect, test } from 'vitest';
import { resolveWatchName } from '../../src/sim/watchNames';

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
