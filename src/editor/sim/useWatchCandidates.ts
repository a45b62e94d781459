// Names a user can pick for the watch table and trend: the loaded program's, or before anything
// ran, those of what Run will run (the task's program, or a configuration's program instances).
import { useMemo } from 'react';
import { useDocument, selectProject } from '../../store/documentStore';
import type { SimState } from '../../store/simState';
import { findPou, readableNames } from '../../sim/layout';
import { globalsWithOutside } from '../../model/outsideGlobals';
import { programInstances, runOptions } from '../../sim/runTarget';
import type { SimVariable } from '../../sim/protocol';
import { useSim } from './simContext';

const selectLayout = (s: SimState) => s.layout;

export function useWatchCandidates(): readonly SimVariable[] {
  const layout = useSim(selectLayout);
  const project = useDocument(selectProject);
  return useMemo(() => {
    if (layout) return layout.variables;
    // What Run will run: the task's program, or each program instance of a configuration by prefix.
    const target = runOptions(project);
    if (target.configuration) {
      const globals = new Set(globalsWithOutside(project).map((g) => g.name.toUpperCase()));
      const names = new Map<string, SimVariable>();
      for (const inst of programInstances(project)) {
        const pou = findPou(project, inst.pou);
        for (const v of pou ? readableNames(project, pou) : []) {
          const named = globals.has(v.name.split('.')[0]!.toUpperCase()) ? v : { ...v, name: `${inst.instance}.${v.name}` };
          names.set(named.name.toUpperCase(), named);
        }
      }
      return [...names.values()];
    }
    const pou = target.pou ? findPou(project, target.pou) : project.pous.find((p) => p.kind === 'PROGRAM');
    return pou ? readableNames(project, pou) : [];
  }, [layout, project]);
}

/** The program instances whose variables are named `Instance.Var` (a configuration runs); empty otherwise. */
export function useConfigurationInstances(): readonly string[] {
  const project = useDocument(selectProject);
  return useMemo(
    () => (runOptions(project).configuration ? programInstances(project).map((i) => i.instance) : []),
    [project],
  );
}
