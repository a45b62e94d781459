// Located variables bind to gateway points by address; mismatches are reported before Run.
import { describe, expect, it } from 'vitest';
import { checkBindings, IO_RULES } from '../../src/bridge/mapping';
import { fromWire, toWire } from '../../src/bridge/wireValues';
import { newPou, newProject, variable } from '../../src/model/factory';
import type { Variable } from '../../src/model/project';
import type { PointInfo } from '../../src/protocol/points';

const points: PointInfo[] = [
  { address: '%IX0.0', type: 'BOOL', dir: 'in', device: 'sim' },
  { address: '%IX0.1', type: 'BOOL', dir: 'in', device: 'sim' },
  { address: '%QX0.0', type: 'BOOL', dir: 'out', device: 'sim' },
  { address: '%IW0', type: 'WORD', dir: 'in', device: 'sim' },
  { address: '%QW0', type: 'INT', dir: 'out', device: 'plant' },
];

const project = (vars: readonly Variable[], globals: readonly Variable[] = []) =>
  newProject('Test', { pous: [newPou('Main', { variables: vars })], globals });

describe('checkBindings', () => {
  it('binds located inputs and outputs of the program and the globals to the points at those addresses', () => {
    const report = checkBindings(
      project([variable('Start', 'BOOL', { location: '%ix0.0' }), variable('Motor', 'BOOL', { location: '%QX0.0' }), variable('Level', 'INT', { location: '%IW0' })], [
        variable('Stop', 'BOOL', { location: '%IX0.1' }),
      ]),
      points,
    );
    expect(report.problems).toEqual([]);
    expect(report.bindings.map((b) => `${b.pou || 'global'}.${b.variable}@${b.address}`)).toEqual([
      'global.Stop@%IX0.1',
      'Main.Start@%IX0.0',
      'Main.Motor@%QX0.0',
      'Main.Level@%IW0',
    ]);
  });

  it('reports an address the gateway does not have, naming the POU, the variable and the address', () => {
    const report = checkBindings(project([variable('Alarm', 'BOOL', { location: '%QX7.3' }), variable('Flow', 'DINT', { location: '%ID4' })]), points);
    expect(report.problems).toEqual([
      expect.objectContaining({ severity: 'error', rule: IO_RULES.missing, pou: 'Main', network: -1, message: expect.stringContaining('Main.Alarm AT %QX7.3') }),
      expect.objectContaining({ severity: 'error', rule: IO_RULES.missing, message: expect.stringContaining('Main.Flow AT %ID4') }),
    ]);
    expect(report.bindings).toEqual([]);
  });

  it('reports a type that does not fit the point (BOOL on a word, a 16-bit point for a DINT)', () => {
    const report = checkBindings(project([variable('Level', 'BOOL', { location: '%IW0' }), variable('Set', 'REAL', { location: '%QW0' })]), points);
    expect(report.problems.map((p) => [p.rule, p.message])).toEqual([
      [IO_RULES.type, 'Main.Level AT %IW0 is BOOL, but the gateway point is WORD (use WORD, INT or UINT)'],
      [IO_RULES.type, 'Main.Set AT %QW0 is REAL, but the gateway point is INT (use WORD, INT or UINT)'],
    ]);
  });

  it('warns when a signed variable reads an unsigned point or the reverse, and ignores %M memory', () => {
    const report = checkBindings(project([variable('Out', 'UINT', { location: '%QW0' }), variable('Mem', 'INT', { location: '%MW3' })]), points);
    expect(report.problems).toEqual([expect.objectContaining({ severity: 'warning', rule: IO_RULES.sign })]);
    expect(report.bindings).toHaveLength(1);
  });
});

describe('wire values', () => {
  it('wraps program values to the 16 bits of a register point as an I/O card would', () => {
    expect(toWire('WORD', -1)).toBe(65535);
    expect(toWire('INT', 40000)).toBe(40000 - 65536);
    expect(toWire('UINT', 70000n)).toBe(70000 - 65536);
    expect(toWire('BOOL', 1)).toBe(true);
    expect(fromWire('INT', 65535)).toBe(-1);
    expect(fromWire('WORD', 65535)).toBe(65535);
    expect(fromWire('BOOL', true)).toBe(true);
  });
});
