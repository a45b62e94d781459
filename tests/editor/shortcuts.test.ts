// Every element the palette places can be placed from the keyboard, and no two commands share a key.
import { expect, test } from 'vitest';
import { COMMANDS } from '../../src/editor/commands/registry';
import { FILE_MENU_COMMANDS } from '../../src/editor/files/FileMenu';
import { PALETTE_ITEMS } from '../../src/editor/palette/paletteItems';

test('every contact, coil, wire and control element in the palette has a shortcut', () => {
  expect(PALETTE_ITEMS.filter((item) => !item.keys).map((item) => item.label)).toEqual([]);
});

test('no two commands are bound to the same key', () => {
  const owners = new Map<string, string[]>();
  for (const c of [...COMMANDS, ...FILE_MENU_COMMANDS]) {
    for (const k of c.keys ?? []) owners.set(k, [...(owners.get(k) ?? []), c.id]);
  }
  expect([...owners].filter(([, ids]) => ids.length > 1)).toEqual([]);
});
