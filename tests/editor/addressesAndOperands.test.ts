import { describe, expect, test } from 'vitest';
import { newPou, newProject, variable } from '../../src/model/factory';
import { nextFreeAddress } from '../../src/editor/variables/addresses';
import {
  candidatesFor,
  describeLiteral,
  rankCandidates,
  resolveName,
} from '../../src/editor/inspector/operands';
import { declareChoices, suggestedType } from '../../src/editor/inspector/declareOffer';

const withVars = (vars: Parameters<typeof variable>[]) => {
  const pou = newPou('Main', { variables: vars.map((v) => variable(...v)) });
  return { project: newProject('p', { pous: [pou] }), pou };
};

describe('next free address', () => {
  test('takes the first unused bit, then moves to the next byte', () => {
    const { project } = withVars([
      ['a', 'BOOL', { location: '%IX0.0' }],
      ['b', 'BOOL', { location: '%IX0.1' }],
    ]);
    expect(nextFreeAddress(project, 'I', 'BOOL')).toBe('%IX0.2');
    const full = withVars(
      Array.from(
        { length: 8 },
        (_, i) => [`i${i}`, 'BOOL', { location: `%QX0.${i}` }] as Parameters<typeof variable>,
      ),
    );
    expect(nextFreeAddress(full.project, 'Q', 'BOOL')).toBe('%QX1.0');
  });
  test('picks words for 16-bit types and ignores other areas', () => {
    const { project } = withVars([
      ['w', 'INT', { location: '%MW0' }],
      ['x', 'INT', { location: '%IW1' }],
    ]);
    expect(nextFreeAddress(project, 'M', 'INT')).toBe('%MW1');
    expect(nextFreeAddress(project, 'Q', 'INT')).toBe('%QW0');
    expect(nextFreeAddress(project, 'I', 'TON')).toBeUndefined();
  });
});

describe('completion', () => {
  const { project, pou } = withVars([
    ['Start', 'BOOL', { location: '%IX0.0' }],
    ['Stop', 'BOOL'],
    ['Count', 'INT'],
    ['T1', 'TON'],
    ['Restart', 'BOOL'],
  ]);
  test('contacts are offered BOOL variables and BOOL pins of FB instances', () => {
    const names = candidatesFor(project, pou, { kind: 'contact' }).map((c) => c.text);
    expect(names).toEqual(['Start', 'Stop', 'T1.IN', 'T1.Q', 'Restart']);
  });
  test('coils are not offered FB outputs', () => {
    expect(candidatesFor(project, pou, { kind: 'coil' }).map((c) => c.text)).not.toContain('T1.Q');
  });
  test('an FB box is offered instances of its type only', () => {
    expect(candidatesFor(project, pou, { kind: 'instance', blockType: 'TON' }).map((c) => c.text)).toEqual([
      'T1',
    ]);
  });
  test('names starting with the typed text come before names containing it', () => {
    const ranked = rankCandidates('st', candidatesFor(project, pou, { kind: 'contact' })).map((c) => c.text);
    expect(ranked).toEqual(['Stop', 'Start', 'Restart']);
  });
  test('resolves plain names, FB pins and word bits', () => {
    const words = withVars([
      ['Status', 'WORD'],
      ['T1', 'TON'],
    ]);
    expect(resolveName(words.project, words.pou, 'status')).toEqual({ status: 'declared', type: 'WORD' });
    expect(resolveName(words.project, words.pou, 'T1.q')).toEqual({ status: 'declared', type: 'BOOL' });
    expect(resolveName(words.project, words.pou, 'Status.15')).toEqual({ status: 'declared', type: 'BOOL' });
    expect(resolveName(words.project, words.pou, 'Status.16')).toMatchObject({ status: 'other' });
    expect(resolveName(words.project, words.pou, 'Pump')).toEqual({ status: 'undeclared', name: 'Pump' });
  });
});

describe('declare it?', () => {
  const { project } = withVars([['Start', 'BOOL', { location: '%IX0.0' }]]);
  test('a contact offers BOOL, an input at the next free bit, or memory', () => {
    const choices = declareChoices(project, 'Stop', { kind: 'contact' });
    expect(choices.map((c) => c.label)).toEqual([
      'BOOL',
      'BOOL input at %IX0.1',
      'BOOL memory at %MX0.0',
      'BOOL global (VAR_GLOBAL)',
      'BOOL global at %IX0.1 (VAR_GLOBAL)',
    ]);
    expect(choices[1]?.variable).toMatchObject({
      name: 'Stop',
      type: 'BOOL',
      location: '%IX0.1',
      varClass: 'local',
    });
  });
  test('a coil offers an output address', () => {
    expect(declareChoices(project, 'Motor', { kind: 'coil' }).map((c) => c.label)).toContain(
      'BOOL output at %QX0.0',
    );
  });
  test('an FB instance is declared with the block type', () => {
    expect(suggestedType({ kind: 'instance', blockType: 'ctu' })).toBe('CTU');
    expect(declareChoices(project, 'C1', { kind: 'instance', blockType: 'CTU' }).map((c) => c.label)).toEqual(
      ['CTU'],
    );
  });
  test('no offer for a name that cannot be declared', () => {
    expect(declareChoices(project, '2x', { kind: 'contact' })).toEqual([]);
  });
});

describe('literal operands on pins', () => {
  test('a literal of the pin type is accepted and named', () => {
    expect(describeLiteral('T#5s', 'TIME')).toEqual({ ok: true, text: 'literal TIME' });
    expect(describeLiteral('10', 'INT')).toEqual({ ok: true, text: 'literal INT' });
  });
  test('a wrong or malformed literal says why', () => {
    expect(describeLiteral('5', 'TIME')).toMatchObject({
      ok: false,
      text: expect.stringMatching(/not a TIME .*T#5s/),
    });
    expect(describeLiteral('300', 'SINT')).toMatchObject({
      ok: false,
      text: expect.stringMatching(/does not fit SINT/),
    });
    expect(describeLiteral('TRUE', 'ANY_NUM')).toMatchObject({
      ok: false,
      text: expect.stringMatching(/BOOL literal; this pin takes ANY_NUM/),
    });
  });
  test('names are left to the variable lookup', () => {
    expect(describeLiteral('Preset', 'INT')).toBeUndefined();
    expect(describeLiteral('T1.ET', 'TIME')).toBeUndefined();
  });
});
