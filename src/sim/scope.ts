// Which body the canvas monitors and how its operand names are read (issue 11): the shown POU's
// tab picks the view. A PROGRAM shows its own networks (in a configuration, one program instance's:
// names `Prog1.Var`); a FUNCTION_BLOCK one chosen instance's body, as CODESYS does (names
// `Motor1.Run`, `Line.Motor1.T1.ET`); a FUNCTION the call that ran last. Globals keep their names.
import type { PouKind } from '../model/project';
import type { SimLayout, SimView } from './protocol';

/** The POU on the canvas, as the editor tells the store. */
export interface ShownPou {
  readonly name: string;
  readonly kind: PouKind;
}

export interface CanvasScope {
  /** The body whose power the canvas shows. */
  readonly view: SimView;
  /** Operand names of the body are read as `<prefix>.<name>` ('' : as they are; undefined: only globals, a function's). */
  readonly prefix: string | undefined;
  /** The instances the user can pick from (FB instances of the type, or a configuration's program instances). */
  readonly choices: readonly string[];
}

const same = (a: string | undefined, b: string | undefined) => (a ?? '').toUpperCase() === (b ?? '').toUpperCase();

const pick = (choices: readonly string[], picked: string | undefined) => choices.find((c) => same(c, picked)) ?? choices[0];

/**
 * The scope of the shown POU in the loaded program, or undefined when the program does not run it
 * (another PROGRAM, an FB without an instance). No shown POU: the program's own body.
 */
export function scopeFor(layout: SimLayout | undefined, shown: ShownPou | undefined, picked?: string): CanvasScope | undefined {
  if (!layout) return undefined;
  const programs = layout.programs;
  const kind = shown?.kind ?? 'PROGRAM';
  const name = shown?.name ?? layout.pou;
  if (kind === 'PROGRAM') {
    if (!programs) return same(name, layout.pou) ? { view: { pou: layout.pou }, prefix: '', choices: [] } : undefined;
    const choices = programs.filter((p) => same(p.pou, name)).map((p) => p.instance);
    const instance = pick(choices, picked);
    return instance === undefined ? undefined : { view: { pou: name, instance }, prefix: instance, choices };
  }
  if (kind === 'FUNCTION_BLOCK') {
    const choices = (layout.instances ?? []).filter((i) => same(i.type, name)).map((i) => i.path);
    const instance = pick(choices, picked);
    return instance === undefined ? undefined : { view: { pou: name, instance }, prefix: instance, choices };
  }
  return { view: { pou: name }, prefix: undefined, choices: [] };
}

export const viewKey = (view: SimView | undefined): string => (view ? `${view.pou.toUpperCase()}|${(view.instance ?? '').toUpperCase()}` : '');

/**
 * The readable name an operand of the shown body stands for: `<prefix>.<name>` when the program has
 * it (the body's own variable), else the name as it is (a global or VAR_EXTERNAL); undefined when
 * the shown POU is not running.
 */
export function scopedName(scope: CanvasScope | undefined, name: string, known: (name: string) => boolean): string | undefined {
  if (!scope || !name) return undefined;
  if (scope.prefix === '' || name.startsWith('%')) return name;
  if (scope.prefix !== undefined) {
    const inBody = `${scope.prefix}.${name}`;
    if (known(inBody)) return inBody;
  }
  return name;
}
