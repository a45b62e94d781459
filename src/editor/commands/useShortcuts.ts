// Global keyboard shortcuts from the command registry. Typing in a field never triggers them.
import { useEffect } from 'react';
import { parseClip } from '../../store/clipboard';
import { parseNetworkClip } from '../../store/networkUnits';
import { copyText, latestCopyInPageOnly, pasteInPage, pasteText } from './clipboardActions';
import type { EditorContext } from './editorActions';
import { matches, parseKeys } from './keys';
import { FILE_MENU_COMMANDS } from '../files/FileMenu';
import { COMMANDS } from './registry';
import { isModalOpen } from '../layout/useModal';

interface Bound {
  readonly id: string;
  readonly keys?: readonly string[];
  run(ctx: EditorContext): void;
  enabled?(ctx: EditorContext): boolean;
}

const BINDINGS = [...COMMANDS, ...(FILE_MENU_COMMANDS as readonly Bound[])].flatMap((command: Bound) =>
  (command.keys ?? []).map((k) => ({ spec: parseKeys(k), command })),
);

export function isTypingTarget(target: EventTarget | null): boolean {
  if (!(target instanceof HTMLElement)) return false;
  const tag = target.tagName;
  return tag === 'INPUT' || tag === 'TEXTAREA' || tag === 'SELECT' || target.isContentEditable;
}

/**
 * Commands whose keys also work in a code editor (the ST editor, a CodeMirror view): saving,
 * opening, Run and Stop. Its own keys (undo, find, indent...) are handled before they get here.
 */
const CODE_EDITOR_COMMANDS: ReadonlySet<string> = new Set(['file.save', 'file.open', 'sim.run', 'sim.stop']);

const inCodeEditor = (target: EventTarget | null): boolean =>
  target instanceof HTMLElement && target.closest('.cm-editor') !== null;

export function useShortcuts(ctx: EditorContext) {
  useEffect(() => {
    // Ctrl+V: the browser follows the key with a paste event carrying the system clipboard;
    // when it does not (no permission), paste the in-page copy instead.
    let pendingPaste: ReturnType<typeof setTimeout> | undefined;

    const onKeyDown = (e: KeyboardEvent) => {
      if (e.defaultPrevented || isModalOpen()) return;
      const codeEditor = inCodeEditor(e.target);
      if (isTypingTarget(e.target) && !codeEditor) return;
      const ui = ctx.ui.getState();
      if (ui.editing || ui.blockPicker || ui.pastePrompt) return;
      const binding = BINDINGS.find((b) => matches(b.spec, e));
      if (!binding) return;
      if (codeEditor && !CODE_EDITOR_COMMANDS.has(binding.command.id)) return;
      if (binding.command.id === 'edit.paste') {
        if (pendingPaste) clearTimeout(pendingPaste);
        pendingPaste = setTimeout(() => {
          pendingPaste = undefined;
          pasteInPage(ctx);
        }, 50);
        return;
      }
      if (binding.command.enabled && !binding.command.enabled(ctx)) return;
      e.preventDefault();
      ui.setStatus('');
      binding.command.run(ctx);
    };

    const onPaste = (e: ClipboardEvent) => {
      if (isTypingTarget(e.target) || isModalOpen()) return;
      if (pendingPaste) clearTimeout(pendingPaste);
      pendingPaste = undefined;
      const text = e.clipboardData?.getData('text/plain');
      e.preventDefault();
      if (!latestCopyInPageOnly() && text && (parseClip(text) || parseNetworkClip(text))) pasteText(ctx, text);
      else pasteInPage(ctx);
    };

    const onCopy = (e: ClipboardEvent) => {
      if (isTypingTarget(e.target) || isModalOpen()) return;
      const text = copyText(ctx);
      if (text && e.clipboardData) {
        e.clipboardData.setData('text/plain', text);
        e.preventDefault();
      }
    };

    window.addEventListener('keydown', onKeyDown);
    document.addEventListener('paste', onPaste);
    document.addEventListener('copy', onCopy);
    return () => {
      if (pendingPaste) clearTimeout(pendingPaste);
      window.removeEventListener('keydown', onKeyDown);
      document.removeEventListener('paste', onPaste);
      document.removeEventListener('copy', onCopy);
    };
  }, [ctx]);
}
