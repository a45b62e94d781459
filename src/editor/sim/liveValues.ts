// Formatting live values for display: the engine's IEC text (TRUE, T#1s500ms, 2.5).
import { formatValue } from '../../engine/values/literals';
import { isElementaryType, type Value } from '../../model/iecTypes';
import { scopedName } from '../../sim/scope';
import type { SimState } from '../../store/simState';

export function formatLive(type: string, value: Value): string {
  return isElementaryType(type) ? formatValue(type, value) : String(value);
}

/** The live value of a name as text, or undefined when it is not in the running program. */
export function liveText(s: SimState, name: string): string | undefined {
  const i = s.variableIndex.get(name.toUpperCase());
  const v = s.layout?.variables[i ?? -1];
  if (i === undefined || !v) return undefined;
  const value = s.values[i];
  return value === undefined ? undefined : formatLive(v.type, value);
}

export function liveValue(s: SimState, name: string): Value | undefined {
  const i = s.variableIndex.get(name.toUpperCase());
  return i === undefined ? undefined : s.values[i];
}

export const isForced = (s: SimState, name: string): boolean => s.forced.has(name.toUpperCase());

export function forcedText(s: SimState, name: string): string | undefined {
  const value = s.forced.get(name.toUpperCase());
  if (value === undefined) return undefined;
  const i = s.variableIndex.get(name.toUpperCase());
  const type = s.layout?.variables[i ?? -1]?.type ?? (typeof value === 'boolean' ? 'BOOL' : 'DINT');
  return formatLive(type, value);
}

/**
 * The readable name an operand on the canvas stands for in the monitored body: `Motor1.Run` for
 * `Run` inside the picked instance Motor1, a global as it is; undefined when the shown POU is not running.
 */
export function canvasName(s: SimState, name: string): string | undefined {
  // No program loaded: names as written (nothing is monitored yet).
  if (!s.layout) return name || undefined;
  return scopedName(s.canvasScope, name, (n) => s.variableIndex.has(n.toUpperCase()));
}
