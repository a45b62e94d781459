// The class of a variable typed in its field: the first letters of the class name pick it, the
// likeliest first (`in` is VAR_INPUT, `in_` VAR_IN_OUT), with or without the VAR_ prefix.
import { expect, test } from 'vitest';
import { classForTyped } from '../../src/editor/variables/tableKeys';

test('typed letters pick the class they begin', () => {
  expect(classForTyped('i')).toBe('input');
  expect(classForTyped('in')).toBe('input');
  expect(classForTyped('in_')).toBe('inOut');
  expect(classForTyped('ino')).toBe('inOut');
  expect(classForTyped('o')).toBe('output');
  expect(classForTyped('v')).toBe('local');
  expect(classForTyped('var_i')).toBe('input');
  expect(classForTyped('VAR_IN_')).toBe('inOut');
  expect(classForTyped('var_t')).toBe('temp');
  expect(classForTyped('e')).toBe('external');
  expect(classForTyped('t')).toBe('temp');
  expect(classForTyped('static')).toBe('local');
});

test('letters no class begins with pick nothing', () => {
  expect(classForTyped('x')).toBeUndefined();
  expect(classForTyped('c')).toBeUndefined();
  expect(classForTyped('')).toBeUndefined();
});
