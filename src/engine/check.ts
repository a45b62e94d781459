// checkProject: every rule of LD-SEMANTICS.md section 9 (and the LD-E/LD-W checks) over every
// POU of a project, as located diagnostics for the editor's problem list and `rungsmith check`:
// each POU on its own (user FBs and functions too, called or not), then recursion (LD-E21),
// the POUs' names (LD-E25) and POU variables hiding a global (LD-W05).
import type { Project } from '../model/project';
import type { Diagnostic } from './api';
import { reportDataTypes } from './compile/aggregates';
import { checkRecursion } from './compile/callGraph';
import { lowerPou } from './compile/pou';
import { checkPouNames } from './compile/pouNames';
import { checkShadowedGlobals } from './compile/shadowedGlobals';

export function checkProject(project: Project): Diagnostic[] {
  const out: Diagnostic[] = [];
  const globals: Diagnostic[] = [];
  reportDataTypes(project, globals);
  project.pous.forEach((pou, i) => lowerPou(project, pou, project.profile, out, i === 0 ? globals : []));
  checkRecursion(project, out);
  checkPouNames(project, out);
  checkShadowedGlobals(project, out);
  return [...globals, ...out];
}
