// The tooltip of the cell under the pointer: the element's full name and kind (the canvas draws
// names whole too, in columns as wide as they need) and the problems marked on that cell.
import type { LdElement } from '../../model/elements';
import type { Network } from '../../model/project';
import { partnerWords } from '../../store/connectors';
import { elementTitle } from '../inspector/elementWords';
import type { CellMarker } from './drawNetwork';

function elementText(el: LdElement, network: Network | undefined): string | undefined {
  switch (el.kind) {
    case 'link':
      return undefined;
    case 'contact':
    case 'coil':
      return `${el.variable || '(no variable yet)'}: ${elementTitle(el)}`;
    case 'box':
      return el.instance ? `${el.instance}: ${elementTitle(el)}` : elementTitle(el);
    case 'connector':
    case 'continuation':
      return network ? partnerWords(network, el) : elementTitle(el);
    case 'jump':
    case 'return':
      return elementTitle(el);
  }
}

/** `network`: the element's network, for the partners of a connector or continuation. */
export function hoverText(
  el: LdElement | undefined,
  problems: readonly CellMarker[],
  network?: Network,
): string | undefined {
  const lines = [el && elementText(el, network), ...problems.map((m) => m.text)].filter((l): l is string =>
    Boolean(l),
  );
  return lines.length > 0 ? lines.join('\n') : undefined;
}
