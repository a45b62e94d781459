// The one behaviour every modal dialog of the editor shares (ModalDialog, the print preview, the
// hardware-stepping confirmation, the paste prompt): while it is open it keeps the focus and the
// keys. Tab cycles through its controls; when its focused field is committed or re-rendered and the
// focus falls to the page, the focus goes back to the dialog; a key pressed while the focus is
// outside it never reaches the editor behind it (no Ctrl+A / Delete on the rungs under a dialog);
// Escape closes the topmost dialog from anywhere. Global shortcut handlers also ask isModalOpen().
import { useCallback, useLayoutEffect, useRef, type KeyboardEvent as ReactKeyboardEvent, type RefCallback } from 'react';

interface OpenModal {
  element: HTMLElement | null;
  close: () => void;
}

const stack: OpenModal[] = [];

/** True while a modal dialog is open: editor shortcuts do nothing then. */
export function isModalOpen(): boolean {
  return stack.length > 0;
}

const FOCUSABLE =
  'button:not(:disabled), input:not(:disabled):not([type="hidden"]), select:not(:disabled), textarea:not(:disabled), a[href], [tabindex]:not([tabindex="-1"])';

function focusables(root: HTMLElement): HTMLElement[] {
  return [...root.querySelectorAll<HTMLElement>(FOCUSABLE)].filter((el) => el.getClientRects().length > 0);
}

function top(): OpenModal | undefined {
  return stack[stack.length - 1];
}

/** Puts the focus back into the dialog: its autofocus control, its first control, or the dialog itself. */
function refocus(modal: OpenModal): void {
  const el = modal.element;
  if (!el || el.contains(document.activeElement)) return;
  const target = el.querySelector<HTMLElement>('[autofocus], [data-autofocus]') ?? focusables(el)[0] ?? el;
  target.focus({ preventScroll: true });
}

const inside = (modal: OpenModal, node: EventTarget | null) => node instanceof Node && !!modal.element?.contains(node);

// Keys whose target is outside the topmost dialog (the focus fell to the page): Escape closes the
// dialog, Tab brings the focus back, every other key is swallowed.
function onWindowKeyDown(e: KeyboardEvent): void {
  const modal = top();
  if (!modal || inside(modal, e.target)) return;
  e.stopImmediatePropagation();
  e.preventDefault();
  if (e.key === 'Escape') modal.close();
  else refocus(modal);
}

// A click or script that moves the focus behind the dialog brings it back.
function onFocusIn(e: FocusEvent): void {
  const modal = top();
  if (modal && !inside(modal, e.target)) refocus(modal);
}

// A committed field that blurs itself (Enter) or is replaced leaves the focus on the page: bring it back.
function onFocusOut(e: FocusEvent): void {
  const modal = top();
  if (!modal || !inside(modal, e.target) || inside(modal, e.relatedTarget)) return;
  setTimeout(() => {
    if (top() === modal && (!document.activeElement || document.activeElement === document.body)) refocus(modal);
  }, 0);
}

function install(): void {
  window.addEventListener('keydown', onWindowKeyDown, true);
  document.addEventListener('focusin', onFocusIn, true);
  document.addEventListener('focusout', onFocusOut, true);
}

function uninstall(): void {
  window.removeEventListener('keydown', onWindowKeyDown, true);
  document.removeEventListener('focusin', onFocusIn, true);
  document.removeEventListener('focusout', onFocusOut, true);
}

export interface ModalProps {
  /** Set on the dialog element. */
  readonly ref: RefCallback<HTMLElement>;
  /** So the dialog itself can hold the focus when it has no control to give it to. */
  readonly tabIndex: -1;
  readonly onKeyDown: (e: ReactKeyboardEvent) => void;
}

/**
 * Makes the element the returned props are spread on a modal dialog: it takes the focus when it opens
 * (unless a control in it took it with autoFocus), keeps it, swallows keys for the editor behind,
 * closes on Escape, and gives the focus back to where it was when it closes.
 */
export function useModal(onClose: () => void): ModalProps {
  const entry = useRef<OpenModal | null>(null);
  // Where the focus was before the dialog: read at its first render, before a control of the dialog
  // takes it with autoFocus (React focuses those before this hook's layout effect runs).
  const opener = useRef<HTMLElement | null | undefined>(undefined);
  if (opener.current === undefined) opener.current = document.activeElement instanceof HTMLElement ? document.activeElement : null;
  if (!entry.current) entry.current = { element: null, close: onClose };
  entry.current.close = onClose;

  useLayoutEffect(() => {
    const modal = entry.current!;
    const before = opener.current ?? null;
    stack.push(modal);
    if (stack.length === 1) install();
    refocus(modal);
    return () => {
      const i = stack.indexOf(modal);
      if (i >= 0) stack.splice(i, 1);
      if (stack.length === 0) uninstall();
      const next = top();
      if (next) refocus(next);
      else if (before && before.isConnected && before !== document.body) before.focus({ preventScroll: true });
    };
  }, []);

  const ref = useCallback((el: HTMLElement | null) => {
    entry.current!.element = el;
  }, []);

  const onKeyDown = useCallback((e: ReactKeyboardEvent) => {
    // No editor shortcut acts behind the dialog.
    e.stopPropagation();
    const modal = entry.current!;
    if (e.key === 'Escape') {
      if (e.defaultPrevented) return;
      e.preventDefault();
      modal.close();
      return;
    }
    if (e.key !== 'Tab' || !modal.element) return;
    const list = focusables(modal.element);
    const first = list[0];
    const last = list[list.length - 1];
    if (!first || !last) {
      e.preventDefault();
      return;
    }
    const active = document.activeElement;
    if (e.shiftKey && (active === first || active === modal.element)) {
      e.preventDefault();
      last.focus();
    } else if (!e.shiftKey && (active === last || active === modal.element)) {
      e.preventDefault();
      first.focus();
    }
  }, []);

  return { ref, tabIndex: -1, onKeyDown };
}
