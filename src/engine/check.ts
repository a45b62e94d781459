// checkProject: every rule of LD-SEMANTICS.md section 9 (and the LD-E/LD-W checks) over every
// POU of a project, as located diagnostics for the editor's problem list and `rungsmith check`:
// each POU on its own (user FBs and functions too, called or not), then recursion (LD-E21),
// the POUs' names (LD-E25) and POU variables hiding a global (LD-W05).
import { withLibraries } from '../model/libraries';
import type { Project } from '../model/project';
import type { Diagnostic } from './api';
import { reportDataTypes } from './compile/aggregates';
import { checkRecursion } from './compile/callGraph';
import { lowerPou } from './compile/pou';
import { checkPouNames } from './compile/pouNames';
import { checkShadowedGlobals } from './compile/shadowedGlobals';

// The project's libraries (project.libraries) are checked with it: their blocks resolve for the
// project's POUs, a POU named like a library block is LD-E25; their own bodies are checked only
// when a program that calls them is compiled (they are read-only here).
export function checkProject(given: Project): Diagnostic[] {
  const project = withLibraries(given);
  const out: Diagnostic[] = [];
  const globals: Diagnostic[] = [];
  reportDataTypes(project, globals);
  given.pous.forEach((pou, i) => lowerPou(project, pou, project.profile, out, i === 0 ? globals : []));
  checkRecursion(project, out);
  checkPouNames(project, out);
  checkShadowedGlobals(given, out);
  return [...globals, ...out];
}
