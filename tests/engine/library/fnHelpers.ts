// Test helper: resolve a standard function by argument types and call it once.
import { callFunction, resolveFunction } from '../../../src/engine/library/functions';
import type { ResolvedFunction } from '../../../src/engine/library/fnTypes';
import type { ElementaryType, Value } from '../../../src/model/iecTypes';
import type { Profile } from '../../../src/model/project';

export function resolved(name: string, types: readonly (ElementaryType | undefined)[], profile: Profile = 'iec', hint?: ElementaryType): ResolvedFunction {
  const r = resolveFunction(name, types, profile, hint);
  if (!r.ok) throw new Error(r.message);
  return r.fn;
}

/** Calls `name` with arguments all of type `t` (or the given types); returns [OUT, ENO]. */
export function call(name: string, t: ElementaryType | readonly ElementaryType[], args: readonly Value[], profile: Profile = 'iec'): [Value, boolean] {
  const types = Array.isArray(t) ? (t as readonly ElementaryType[]) : args.map(() => t as ElementaryType);
  const { value, eno } = callFunction(resolved(name, types, profile), args);
  return [value, eno];
}
