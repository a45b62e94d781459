// LD-W05: a POU variable with the name of a global variable. Inside the POU the name means the POU's
// own variable (IEC 61131-3 scoping; MATIEC and CODESYS do the same), so a contact or coil the
// programmer meant for the global reads or writes another variable: legal, and a classic cause of
// "the output never comes on". A VAR_EXTERNAL is the global itself and is not warned.
import type { Project, VarClass } from '../../model/project';
import type { Diagnostic } from '../api';
import { Reporter } from './report';

const CLASS_KEYWORDS: Record<VarClass, string> = {
  local: 'VAR',
  input: 'VAR_INPUT',
  output: 'VAR_OUTPUT',
  inOut: 'VAR_IN_OUT',
  external: 'VAR_EXTERNAL',
  temp: 'VAR_TEMP',
};

export function checkShadowedGlobals(project: Project, out: Diagnostic[]): void {
  if (project.globals.length === 0) return;
  const globals = new Map(project.globals.map((g) => [g.name.trim().toUpperCase(), g]));
  for (const pou of project.pous) {
    const r = new Reporter(out, pou.name, -1);
    for (const v of pou.variables) {
      if (v.varClass === 'external') continue;
      const g = globals.get(v.name.trim().toUpperCase());
      if (!g) continue;
      r.warning(
        'LD-W05',
        `the ${CLASS_KEYWORDS[v.varClass]} variable "${v.name}" of ${pou.name} has the name of the global variable ${g.name}: inside ${pou.name} the name means ${pou.name}'s own variable, never the global; rename one of them, or declare it VAR_EXTERNAL to use the global`,
      );
    }
  }
}
