// Escape in a name field (inline editor, inspector, variable table, network header) leaves it at
// once and gives the keyboard back to the ladder canvas, so the next key is a canvas shortcut.

/** Focuses the ladder canvas (without scrolling); without one, the field just loses focus. */
export function focusCanvas(from?: HTMLElement): void {
  const canvas = document.querySelector<HTMLElement>('.rs-canvas');
  if (canvas) canvas.focus({ preventScroll: true });
  else from?.blur();
}
