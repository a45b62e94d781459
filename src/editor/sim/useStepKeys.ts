// Debugger keys (as CODESYS and most IDEs): F10 steps over the next network, F11 steps into a call.
// Not in text fields; ignored while running or faulted (the buttons are disabled then too).
import { useEffect, useRef } from 'react';
import type { SimCommands } from '../hardware/useHardwareStepping';
import { isModalOpen } from '../layout/useModal';

export function useStepKeys(commands: SimCommands, disabled: boolean): void {
  const state = useRef({ commands, disabled });
  state.current = { commands, disabled };
  useEffect(() => {
    const onKey = (e: KeyboardEvent) => {
      if ((e.key !== 'F10' && e.key !== 'F11') || e.ctrlKey || e.metaKey || e.altKey || e.shiftKey || isModalOpen()) return;
      const t = e.target as HTMLElement | null;
      if (t && (t.tagName === 'INPUT' || t.tagName === 'TEXTAREA' || t.tagName === 'SELECT' || t.isContentEditable)) return;
      // F11 would otherwise toggle the browser's full screen.
      e.preventDefault();
      if (state.current.disabled) return;
      state.current.commands.step({ kind: 'network', ...(e.key === 'F11' ? { into: true } : {}) });
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, []);
}
