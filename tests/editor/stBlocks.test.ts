// The ST editor's reading of blocks (keyword matching, folding) and of the model's text changes.
import { Text } from '@codemirror/state';
import { describe, expect, test } from 'vitest';
import { blockAt, stStructure } from '../../src/editor/st/stBlocks';
import { textDiff } from '../../src/editor/st/stModelSync';

const words = (text: string, b: { open: { word: string }; middles: readonly { word: string }[]; close?: { word: string } }) =>
  [b.open, ...b.middles, ...(b.close ? [b.close] : [])].map((w) => w.word).join(' ');

describe('stStructure', () => {
  test('nested blocks, their middle keywords and their ends', () => {
    const text = [
      'IF a THEN',
      '  FOR i := 1 TO 10 BY 2 DO x := x + i; END_FOR;',
      'ELSIF b THEN',
      '  CASE n OF 1: y := 1; ELSE y := 0; END_CASE;',
      'ELSE',
      '  REPEAT n := n - 1; UNTIL n = 0 END_REPEAT;',
      '  WHILE c DO c := FALSE; END_WHILE;',
      'END_IF;',
    ].join('\n');
    const s = stStructure(text);
    expect(s.blocks.map((b) => words(text, b))).toEqual([
      'IF THEN ELSIF THEN ELSE END_IF',
      'FOR TO BY DO END_FOR',
      'CASE OF ELSE END_CASE',
      'REPEAT UNTIL END_REPEAT',
      'WHILE DO END_WHILE',
    ]);
    expect(s.stray).toEqual([]);
    // The cursor on any keyword of a block finds that block, innermost first.
    expect(words(text, blockAt(s, text.indexOf('ELSIF') + 2)!.block)).toBe('IF THEN ELSIF THEN ELSE END_IF');
    expect(words(text, blockAt(s, text.indexOf('END_FOR'))!.block)).toBe('FOR TO BY DO END_FOR');
    expect(blockAt(s, text.indexOf('x := x'))).toBeUndefined();
  });

  test('keywords in comments, strings, pragmas and members are not keywords; unclosed and stray blocks are told', () => {
    const text = "(* IF x THEN *) s := 'END_IF'; {IF} // WHILE\nCfg.If := 1;\nIF a THEN\n  b := 1;\nEND_WHILE";
    const s = stStructure(text);
    expect(s.blocks.map((b) => words(text, b))).toEqual(['IF THEN']);
    expect(s.blocks[0]!.close).toBeUndefined();
    expect(s.stray.map((w) => w.word)).toEqual(['END_WHILE']);
    expect(s.comments.map((c) => text.slice(c.from, c.to))).toEqual(['(* IF x THEN *)', '{IF}']);
  });

  test('an unclosed comment runs to the end (text being typed)', () => {
    const text = 'x := 1;\n(* IF a THEN\nEND_IF';
    const s = stStructure(text);
    expect(s.blocks).toEqual([]);
    expect(s.comments).toEqual([{ from: 8, to: text.length }]);
  });

  test('declaration blocks and typed literals', () => {
    const text = 'VAR\n  t : TIME := T#1h2m;\n  a : ARRAY [0..3] OF INT;\nEND_VAR\nIF x = INT#5 THEN END_IF';
    expect(stStructure(text).blocks.map((b) => words(text, b))).toEqual(['VAR END_VAR', 'IF THEN END_IF']);
  });
});

describe('textDiff', () => {
  test('the change between two texts is the part between their common start and end', () => {
    const apply = (a: string, b: string) => textDiff(a, b).apply(Text.of(a.split('\n'))).toString();
    for (const [a, b] of [
      ['abc', 'abXc'],
      ['abc', 'c'],
      ['', 'x := 1;'],
      ['IF a THEN\nEND_IF', 'IF a THEN\n  b := 1;\nEND_IF'],
      ['aaa', 'aa'],
      ['same', 'same'],
    ])
      expect(apply(a!, b!)).toBe(b);
    expect(textDiff('same', 'same').empty).toBe(true);
  });
});
