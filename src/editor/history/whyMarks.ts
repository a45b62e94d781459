// "Why?" on the canvas: the elements an explanation names get a tag over them (the marker channel
// the canvas draws for device values): what blocked the power, the path that carried it, who wrote.
import { useMemo } from 'react';
import type { MarkRole } from '../../engine/explain';
import type { ElementId } from '../../model/ids';
import type { Network } from '../../model/project';
import type { SimState } from '../../store/simState';
import { useSim } from '../sim/simContext';

const WORDS: Record<MarkRole, string> = {
  subject: 'why?',
  blocking: 'why: blocks',
  path: 'why: power path',
  writer: 'why: wrote last',
  'other-writer': 'why: also writes',
};

const selectExplanation = (s: SimState) => s.explanation;

/** Tags of the shown explanation for one network (by element id), or undefined. */
export function useNetworkWhyMarks(network: Network): ReadonlyMap<ElementId, string> | undefined {
  const explanation = useSim(selectExplanation);
  return useMemo(() => {
    if (!explanation) return undefined;
    const ids = new Set(network.elements.map((e) => e.id as string));
    const out = new Map<ElementId, string>();
    for (const m of explanation.marks) {
      if (!ids.has(m.elementId)) continue;
      const prev = out.get(m.elementId as ElementId);
      if (!prev || m.role === 'blocking') out.set(m.elementId as ElementId, WORDS[m.role]);
    }
    return out.size ? out : undefined;
  }, [explanation, network]);
}
