// Keys of the shell commands (shellCommands.ts). Like the editor's shortcuts, never while typing in
// a field; Ctrl+P replaces the browser's print of the whole editor with the Print dialog.
import { useEffect } from 'react';
import type { EditorContext } from '../commands/editorActions';
import { matches, parseKeys } from '../commands/keys';
import { isTypingTarget } from '../commands/useShortcuts';
import { SHELL_COMMANDS } from './shellCommands';
import { isModalOpen } from './useModal';

const BINDINGS = SHELL_COMMANDS.flatMap((command) =>
  (command.keys ?? []).map((k) => ({ spec: parseKeys(k), command })),
);

export function useShellKeys(ctx: EditorContext) {
  useEffect(() => {
    const onKeyDown = (e: KeyboardEvent) => {
      if (e.defaultPrevented || isModalOpen()) return;
      const binding = BINDINGS.find((b) => matches(b.spec, e));
      // Ctrl+P works from a field too: the browser would print the editor's screen otherwise.
      if (!binding || (isTypingTarget(e.target) && binding.command.id !== 'file.print')) return;
      e.preventDefault();
      binding.command.run(ctx);
    };
    window.addEventListener('keydown', onKeyDown);
    return () => window.removeEventListener('keydown', onKeyDown);
  }, [ctx]);
}
