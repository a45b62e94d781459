// Initial values are IEC literal text; the engine's literal parser decides what is valid for a type.
import type { ElementaryType } from '../../model/iecTypes';
import { parseLiteral } from '../../engine/values/literals';
import { canWiden } from '../../engine/values/types';

/** Why `text` is not a valid initial value for `type`, or undefined when it is. */
export function checkInitialValue(text: string, type: ElementaryType): string | undefined {
  const literal = text.trim();
  const result = parseLiteral(literal, type);
  if (!result.ok) return result.message;
  if (result.type !== type && !canWiden(result.type, type))
    return `${literal} is a ${result.type} value, which does not fit ${type}`;
  return undefined;
}
