// Names a user can pick for the watch table and trend: the loaded program's, or the document's
// first PROGRAM before anything ran.
import { useMemo } from 'react';
import { useDocument, selectProject } from '../../store/documentStore';
import type { SimState } from '../../store/simStore';
import { readableNames } from '../../sim/layout';
import type { SimVariable } from '../../sim/protocol';
import { useSim } from './simContext';

const selectLayout = (s: SimState) => s.layout;

export function useWatchCandidates(): readonly SimVariable[] {
  const layout = useSim(selectLayout);
  const project = useDocument(selectProject);
  return useMemo(() => {
    if (layout) return layout.variables;
    const pou = project.pous.find((p) => p.kind === 'PROGRAM');
    return pou ? readableNames(project, pou) : [];
  }, [layout, project]);
}
