// Connectors and continuations (IEC 61131-3 connections; PLCopen connector/continuation): a
// connector `>C>` ends a line, every continuation `>C>` of the network carries it on, as one wire.
import { describe, expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import type { Network } from '../../src/model/project';
import { ladder, plcOf, project, trace, vars } from './ladder';

const VARS = vars('A BOOL', 'B BOOL', 'X BOOL', 'Y BOOL', 'N1 INT', 'N2 INT');
const build = (networks: Network[]) => project(VARS, networks);
const diags = (networks: Network[]) =>
  checkProject(build(networks)).map((d) => `${d.severity} ${d.rule} ${d.message}`);

describe('connectors and continuations', () => {
  test('a connector carries the power flow to its continuation on another row, as a wire would', () => {
    const nets = [ladder(['[A] >C>| . .', '|>C> [B] - (X)', '|>C> - - (Y)'])];
    expect(diags(nets)).toEqual([]);
    const steps = [
      { A: false, B: true },
      { A: true, B: false },
      { A: true, B: true },
    ];
    expect(trace(plcOf(build(nets)), steps, ['X', 'Y'])).toEqual([
      [0, 0],
      [0, 1],
      [1, 1],
    ]);
  });

  test('a continuation left of its connector still reads the value written in the same scan (no feedback error)', () => {
    const nets = [ladder(['|>C> - (X)', '[A] - >C>|'])];
    expect(diags(nets).filter((d) => d.startsWith('error'))).toEqual([]);
    expect(trace(plcOf(build(nets)), [{ A: true }, { A: false }], ['X'])).toEqual([[1], [0]]);
  });

  test('a continuation with no connector of its name is an error naming it (LD-R14)', () => {
    const nets = [ladder(['[A] >C>| .', '|>D> - (X)'])];
    const d = diags(nets);
    expect(d).toContain('error LD-R14 the continuation ">D>" at R2C1 has no connector of its name in this network: it carries nothing');
    expect(d).toContain('warning LD-R14 the connector ">C>" has no continuation of its name in this network: its value goes nowhere');
  });

  test('two connectors of one name are refused (LD-R14); names compare case-insensitively', () => {
    const nets = [ladder(['[A] >C>| .', '[B] >c>| .', '|>C> - (X)'])];
    expect(diags(nets).filter((d) => d.startsWith('error'))).toEqual([
      'error LD-R14 the connector ">c>" has the same name as the connector at R1C2; a connector name is used once per network',
    ]);
  });
});
