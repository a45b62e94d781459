// Which gateway input addresses a program reads: its input variables' locations, keyed so that
// `%ix0.0` and `%IX0.0` match.
import { parseLocation } from '../model/iecTypes';
import type { SimLayout } from './protocol';

/** The locations of a program's input variables, by locationKey. */
export function inputKeysOf(layout: SimLayout): Set<string> {
  return new Set(layout.variables.flatMap((v) => (v.role === 'input' && v.location ? [locationKey(v.location)] : [])));
}

/** `%ix0.0` and `%IX0.0` alike: the key a location is bound by. */
export function locationKey(text: string): string {
  const loc = parseLocation(text);
  return loc ? `%${loc.area}${loc.size}${loc.index}${loc.bit !== undefined ? `.${loc.bit}` : ''}` : text.trim().toUpperCase();
}
