// The tooltip of the cell under the pointer: the element's full name and kind (names longer than
// a cell are shortened on the canvas) and the problems marked on that cell.
import type { LdElement } from '../../model/elements';
import { elementTitle } from '../inspector/elementWords';
import type { CellMarker } from './drawNetwork';

function elementText(el: LdElement): string | undefined {
  switch (el.kind) {
    case 'link':
      return undefined;
    case 'contact':
    case 'coil':
      return `${el.variable || '(no variable yet)'}: ${elementTitle(el)}`;
    case 'box':
      return el.instance ? `${el.instance}: ${elementTitle(el)}` : elementTitle(el);
    case 'jump':
    case 'return':
    case 'connector':
    case 'continuation':
      return elementTitle(el);
  }
}

export function hoverText(el: LdElement | undefined, problems: readonly CellMarker[]): string | undefined {
  const lines = [el && elementText(el), ...problems.map((m) => m.text)].filter((l): l is string =>
    Boolean(l),
  );
  return lines.length > 0 ? lines.join('\n') : undefined;
}
