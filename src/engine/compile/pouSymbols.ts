// The symbol table of one POU as the checks and the program build it (symbols.ts holds the table
// itself): the POU's variables, a FUNCTION's result variable, then the project's globals (also
// declared once per program by declareGlobals), and the VAR_EXTERNAL checks (LD-E10, LD-E16, LD-W16).
import type { Pou, Profile, Project, Variable } from '../../model/project';
import { STANDARD_LIBRARY, type BlockLibrary } from '../../model/library';
import { globalsWithOutside, outsideGlobals } from '../../model/outsideGlobals';
import type { Reporter } from './report';
import { declaredElementaryType, Storage, SymbolTable } from './symbols';
import { yieldPoint } from '../yieldPoint';

/**
 * Builds the symbol table of a POU: its variables first, then the project's globals. A VAR_EXTERNAL
 * declares no storage: it names a global (LD-E16 when there is none, or it has another type).
 */
export function buildSymbols(
  project: Project,
  pou: Pou,
  r: Reporter,
  globalsReporter: Reporter,
  library: BlockLibrary = STANDARD_LIBRARY,
  profile: Profile = project.profile,
): SymbolTable {
  const table = new SymbolTable(storageFor(project, profile), '', library);
  table.instantiating = new Set([pou.name.toUpperCase()]);
  // A yield point every 64 declarations: a program of a thousand variables and more is declared in
  // pieces, between which the simulator runs the scans that fell due (yieldPoint.ts).
  let n = 0;
  for (const v of pou.variables)
    if (v.varClass !== 'external') {
      table.declare(v, false, r, v.varClass === 'temp');
      if ((++n & 63) === 0) yieldPoint();
    }
  if (pou.kind === 'FUNCTION' && !pou.variables.some((v) => v.name.toUpperCase() === pou.name.toUpperCase()))
    table.declare({ name: pou.name, type: pou.returnType ?? 'BOOL', varClass: 'output', retain: false, comment: '' }, false, r);
  for (const v of globalsWithOutside(project)) {
    table.declare(v, true, globalsReporter);
    if ((++n & 63) === 0) yieldPoint();
  }
  for (const v of pou.variables) if (v.varClass === 'external') checkExternal(table, project, pou, v, r);
  return table;
}

/** A program's storage; the profile decides whether two variables at one location are an error. */
export function storageFor(project: Project, profile: Profile): Storage {
  const storage = new Storage(project);
  if (profile === 'openplc') storage.sharedLocation = 'error';
  return storage;
}

/** Declares the project's globals into a program's storage (once per program). */
export function declareGlobals(table: SymbolTable, project: Project, r: Reporter): void {
  let n = 0;
  for (const v of globalsWithOutside(project)) {
    table.declare(v, true, r);
    if ((++n & 63) === 0) yieldPoint();
  }
}

function checkExternal(table: SymbolTable, project: Project, pou: Pou, decl: Variable, r: Reporter): void {
  const what = `the VAR_EXTERNAL "${decl.name}"`;
  const key = decl.name.trim().toUpperCase();
  if (pou.variables.some((v) => v.varClass !== 'external' && v.name.toUpperCase() === key)) {
    r.error(
      'LD-E10',
      `${what} has the name of a variable of the POU; variable names must be unique (case does not count)`,
    );
    return;
  }
  const global = project.globals.find((g) => g.name.toUpperCase() === key);
  if (!global) {
    // LD-W16: declared outside the project (a board's sketch, another file); kept as a global (outsideGlobals).
    const kept = outsideGlobals(project).find((g) => g.name.trim().toUpperCase() === key);
    if (kept)
      r.warning(
        'LD-W16',
        `${decl.name} is declared outside the project (VAR_EXTERNAL, no global of that name: MATIEC on its own refuses that, "the external variable does not match with any global variable", unless the build declares it, as OpenPLC's board builds do); the simulator keeps it as a global ${kept.type}${kept.initial ? ` starting at ${kept.initial}` : ''}, which you can write and force in the watch table`,
      );
    if (!kept || kept.type.trim().toUpperCase() === decl.type.trim().toUpperCase()) return;
  }
  const globalName = global?.name ?? decl.name;
  const sym = table.lookup(key);
  if (!sym || sym.kind === 'ref') return; // the global's own declaration is in error (reported with the globals)
  const declared = declaredElementaryType(decl.type);
  const type = declared && 'type' in declared ? declared.type : decl.type.trim().toUpperCase();
  const globalType = sym.kind === 'var' && sym.dataType ? sym.dataType.name : sym.type;
  if (type !== globalType.toUpperCase())
    r.error('LD-E16', `${what} is declared ${type} but the global variable "${globalName}" is ${sym.type}`);
}
