// The shell's own keys (panels, print) are taken by no editor command.
import { expect, test } from 'vitest';
import { COMMANDS } from '../../src/editor/commands/registry';
import { FILE_MENU_COMMANDS } from '../../src/editor/files/FileMenu';
import { SHELL_COMMANDS } from '../../src/editor/layout/shellCommands';

test('Ctrl+B, Ctrl+Alt+B, Ctrl+J and Ctrl+P belong to the shell alone', () => {
  const shell = SHELL_COMMANDS.flatMap((c) => c.keys ?? []);
  expect(shell).toEqual(['mod+p', 'mod+b', 'mod+alt+b', 'mod+j']);
  const taken = new Set([...COMMANDS, ...FILE_MENU_COMMANDS].flatMap((c) => c.keys ?? []));
  expect(shell.filter((k) => taken.has(k))).toEqual([]);
});
