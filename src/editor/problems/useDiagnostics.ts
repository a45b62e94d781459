// Live diagnostics of the open project: checkProject runs shortly after the document stops
// changing, never while a stroke is being drawn, and one result is shared by every caller
// (problems list, canvas markers) for the same project version.
import { useEffect, useMemo, useState } from 'react';
import type { Diagnostic } from '../../engine/api';
import { checkProject } from '../../engine/check';
import type { Project } from '../../model/project';
import { selectProject, useDocument } from '../../store/documentStore';

/** Wait after the last change before checking again, ms. */
export const CHECK_DELAY_MS = 200;

const cache = new WeakMap<Project, readonly Diagnostic[]>();

/** The diagnostics of a project version, computed once. A checker failure is reported, not thrown. */
export function diagnosticsOf(project: Project): readonly Diagnostic[] {
  const hit = cache.get(project);
  if (hit) return hit;
  let result: readonly Diagnostic[];
  try {
    result = checkProject(project);
  } catch (e) {
    result = [
      {
        severity: 'error',
        rule: 'LD-E000',
        pou: project.pous[0]?.name ?? '',
        network: -1,
        message: `The checker stopped on this program (${(e as Error).message}); please report it with the project file.`,
      },
    ];
  }
  cache.set(project, result);
  return result;
}

/** The current diagnostics (of the project as it was CHECK_DELAY_MS after its last change). */
export function useDiagnostics(): readonly Diagnostic[] {
  const project = useDocument(selectProject);
  const [checked, setChecked] = useState<{ project: Project | undefined; diagnostics: readonly Diagnostic[] }>({
    project: undefined,
    diagnostics: [],
  });
  useEffect(() => {
    if (checked.project === project) return undefined;
    const timer = setTimeout(() => setChecked({ project, diagnostics: diagnosticsOf(project) }), cache.has(project) ? 0 : CHECK_DELAY_MS);
    return () => clearTimeout(timer);
  }, [project, checked.project]);
  return checked.diagnostics;
}

/** Diagnostics of one POU grouped by network index, for cell markers on the canvas. */
export function useDiagnosticsByNetwork(pouName: string | undefined): ReadonlyMap<number, readonly Diagnostic[]> {
  const diagnostics = useDiagnostics();
  return useMemo(() => {
    const byNetwork = new Map<number, Diagnostic[]>();
    for (const d of diagnostics) {
      if (d.pou !== pouName || d.network < 0) continue;
      const list = byNetwork.get(d.network);
      if (list) list.push(d);
      else byNetwork.set(d.network, [d]);
    }
    return byNetwork;
  }, [diagnostics, pouName]);
}
