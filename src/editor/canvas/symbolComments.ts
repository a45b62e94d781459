// The comments of declared variables, looked up by the names written on the canvas (the
// "Show symbol comments" view option, as CODESYS's Options > FBD, LD and IL). IEC names are
// case-insensitive; a POU variable hides a global of the same name (and its comment); `Word.3` and
// `Instance.Q` show the comment of `Word` and `Instance`.
import type { Variable } from '../../model/project';
import type { SymbolComments } from './geometry';

export function symbolCommentLookup(locals: readonly Variable[], globals: readonly Variable[]): SymbolComments {
  const map = new Map<string, string>();
  for (const v of globals) map.set(v.name.toLowerCase(), v.comment ?? '');
  for (const v of locals) map.set(v.name.toLowerCase(), v.comment ?? '');
  return (name) => {
    const key = name.trim().toLowerCase();
    const whole = map.get(key);
    if (whole !== undefined) return whole || undefined;
    const dot = key.indexOf('.');
    return dot > 0 ? map.get(key.slice(0, dot)) || undefined : undefined;
  };
}

let last: { locals: readonly Variable[]; globals: readonly Variable[]; value: SymbolComments } | undefined;

/**
 * The lookup for the view: undefined when the option is off; otherwise one function per pair of
 * declaration lists (the same object while they do not change, so per-network memos hold).
 */
export function symbolCommentsFor(
  on: boolean,
  locals: readonly Variable[] | undefined,
  globals: readonly Variable[],
): SymbolComments | undefined {
  if (!on) return undefined;
  const l = locals ?? NONE;
  if (!last || last.locals !== l || last.globals !== globals)
    last = { locals: l, globals, value: symbolCommentLookup(l, globals) };
  return last.value;
}

const NONE: readonly Variable[] = [];
