// Resolving a function call from its argument types: the shared poly type, widening, untyped
// literals, arity, and refusals worded for a PLC programmer.
import { describe, expect, it } from 'vitest';
import { PROFILE_DIFFERENCES } from '../../../src/engine/library/profiles';
import { callFunction, resolveFunction } from '../../../src/engine/library/functions';
import { FUNCTION_SIGNATURES_BASE } from '../../../src/model/blocks';
import { resolved } from './fnHelpers';

const refusal = (name: string, types: Parameters<typeof resolveFunction>[1]): string => {
  const r = resolveFunction(name, types, 'iec');
  if (r.ok) throw new Error(`${name} resolved`);
  return r.message;
};

describe('resolveFunction', () => {
  it('widens mixed arguments to the narrowest type covering them', () => {
    const add = resolved('ADD', ['INT', 'DINT']);
    expect(add.argTypes).toEqual(['DINT', 'DINT']);
    expect(add.outType).toBe('DINT');
    expect(resolved('ADD', ['INT', 'UINT']).outType).toBe('DINT');
    expect(resolved('MUL', ['SINT', 'REAL']).outType).toBe('REAL');
    expect(resolved('GT', ['INT', 'LINT']).argTypes).toEqual(['LINT', 'LINT']);
  });

  it('gives untyped literals the type of the typed arguments, else the output hint, else INT', () => {
    expect(resolved('ADD', ['REAL', undefined]).argTypes).toEqual(['REAL', 'REAL']);
    expect(resolved('ADD', [undefined, undefined], 'iec', 'LINT').outType).toBe('LINT');
    expect(resolved('ADD', [undefined, undefined]).outType).toBe('INT');
    expect(resolved('AND', [undefined, undefined]).outType).toBe('BOOL');
    expect(resolved('SHL', ['WORD', undefined]).argTypes).toEqual(['WORD', 'INT']);
    // A comparison's BOOL output says nothing about the type of its inputs.
    expect(resolved('GT', [undefined, undefined], 'iec', 'BOOL').argTypes).toEqual(['INT', 'INT']);
  });

  it('expands extensible inputs and names them', () => {
    expect(resolved('ADD', ['INT', 'INT', 'INT']).inputNames).toEqual(['IN1', 'IN2', 'IN3']);
    expect(resolved('MUX', ['INT', 'REAL', 'REAL', 'REAL']).inputNames).toEqual(['K', 'IN0', 'IN1', 'IN2']);
    expect(resolved('MUX', ['USINT', 'REAL', 'REAL']).argTypes).toEqual(['USINT', 'REAL', 'REAL']);
  });

  it('offers array-free fast paths for one and two inputs', () => {
    const add = resolved('ADD', ['INT', 'INT']);
    expect(add.impl2?.({ error: false }, 2, 3)).toBe(5);
    const conv = resolved('INT_TO_REAL', ['INT']);
    expect(conv.impl1?.({ error: false }, 2)).toBe(2);
    expect(resolved('ADD', ['INT', 'INT', 'INT']).impl2).toBeDefined(); // same step, folded by impl
    expect(callFunction(resolved('GT', ['INT', 'INT', 'INT']), [3, 2, 1]).value).toBe(true);
  });

  it('is case-insensitive and accepts a widened input to a conversion', () => {
    expect(resolved('add', ['INT', 'INT']).name).toBe('ADD');
    expect(resolved('INT_TO_REAL', ['SINT']).argTypes).toEqual(['INT']);
  });

  it.each<[string, Parameters<typeof resolveFunction>[1], string]>([
    ['ADD', ['BOOL', 'INT'], 'ADD cannot add BOOL and INT'],
    ['ADD', ['BOOL', 'BOOL'], 'ADD cannot add BOOL'],
    ['MUL', ['TIME', 'TIME'], 'MUL cannot multiply TIME values'],
    ['MOD', ['REAL', 'REAL'], 'MOD cannot take the remainder of REAL'],
    ['AND', ['INT', 'INT'], 'AND cannot combine INT'],
    ['NOT', ['REAL'], 'NOT cannot invert REAL'],
    ['NEG', ['UINT'], 'NEG cannot negate UINT: it is unsigned'],
    ['SUB', ['INT', 'INT', 'INT'], 'SUB takes 2 inputs (IN1, IN2), not 3'],
    ['ADD', ['INT'], 'ADD takes 2 to 16 inputs IN1.., not 1'],
    ['MUX', ['INT', 'INT'], 'MUX takes K and 2 to 16 inputs IN0.., not 1'],
    ['SEL', ['INT', 'INT', 'INT'], 'SEL input G needs BOOL, not INT'],
    ['SHL', ['WORD', 'REAL'], 'SHL input N needs an integer (ANY_INT), not REAL'],
    ['INT_TO_REAL', ['DINT'], 'INT_TO_REAL input IN needs INT, not DINT'],
    ['TON', ['BOOL', 'TIME'], 'TON is not a standard function'],
    ['FOO', [], 'FOO is not a standard function'],
    ['GT', ['INT', 'WORD'], 'GT cannot compare INT and WORD'],
  ])('%s %j is refused: %s', (name, types, message) => {
    expect(refusal(name, types)).toBe(message);
  });

  it('resolves every non-conversion standard function for a typical type', () => {
    for (const sig of FUNCTION_SIGNATURES_BASE) {
      const types = sig.inputs.map((p) => (p.name === 'G' ? 'BOOL' : p.name === 'K' || p.name === 'N' ? 'INT' : ['AND', 'OR', 'XOR', 'NOT', 'SHL', 'SHR', 'ROL', 'ROR'].includes(sig.name) ? 'WORD' : 'INT')) as Parameters<typeof resolveFunction>[1];
      const r = resolveFunction(sig.name, types, 'iec');
      expect(r.ok, `${sig.name}: ${r.ok ? '' : r.message}`).toBe(true);
    }
  });
});

describe('PROFILE_DIFFERENCES', () => {
  it('documents each difference with distinct ids and both behaviours', () => {
    const ids = PROFILE_DIFFERENCES.map((d) => d.id);
    expect(new Set(ids).size).toBe(ids.length);
    expect(ids).toEqual(expect.arrayContaining(['counter-up-limit', 'counter-down-limit', 'time-conversion-unit']));
    for (const d of PROFILE_DIFFERENCES) expect(d.iec).not.toBe(d.openplc);
  });
});
