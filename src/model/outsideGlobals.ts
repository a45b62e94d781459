// Globals declared outside the project: a VAR_EXTERNAL that names no global of the project (OpenPLC's
// Arduino_7_Segments shares `current_count` with the board's Arduino sketch, which declares it).
// Engine and simulator keep each such name as an implicit global of the type and initial value of
// its first VAR_EXTERNAL declaration (rule LD-W16); the project (and its export) stays as written.
import type { Project, Variable } from './project';

const memo = new WeakMap<readonly Variable[], { pous: Project['pous']; outside: readonly Variable[] }>();

/** The VAR_EXTERNALs of the project's POUs whose global the project does not declare, one per name (first declaration wins). */
export function outsideGlobals(project: Pick<Project, 'pous' | 'globals'>): readonly Variable[] {
  const hit = memo.get(project.globals);
  if (hit && hit.pous === project.pous) return hit.outside;
  const declared = new Set(project.globals.map((g) => g.name.trim().toUpperCase()));
  const outside: Variable[] = [];
  for (const pou of project.pous)
    for (const v of pou.variables) {
      const key = v.name.trim().toUpperCase();
      if (v.varClass !== 'external' || !key || declared.has(key)) continue;
      declared.add(key);
      outside.push({ ...v, varClass: 'local', comment: v.comment || `declared outside the project (VAR_EXTERNAL of ${pou.name})` });
    }
  memo.set(project.globals, { pous: project.pous, outside });
  return outside;
}

/** The project's globals followed by those declared outside it (outsideGlobals). */
export function globalsWithOutside(project: Pick<Project, 'pous' | 'globals'>): readonly Variable[] {
  const outside = outsideGlobals(project);
  return outside.length ? [...project.globals, ...outside] : project.globals;
}
