// Going to a find hit or a cross-reference use: show its POU, scroll to it, select the element
// (or the network when the hit is its title, comment or label).
import type { ElementId, NetworkId, PouId } from '../../model/ids';
import type { EditorContext } from '../commands/editorActions';
import { revealNetwork } from '../outline/goTo';

export function revealPlace(
  ctx: EditorContext,
  p: { pou: PouId; network: NetworkId; element?: ElementId; row?: number; col?: number },
) {
  revealNetwork(ctx, p.pou, p.network, { row: p.row ?? 0, col: p.col ?? 0 });
  if (p.element) ctx.ui.getState().select(p.network, [p.element]);
  else ctx.ui.getState().selectNetworks([p.network]);
}

export const placeName = (p: { pouName: string; networkIndex: number }) => `${p.pouName} · Network ${p.networkIndex + 1}`;
