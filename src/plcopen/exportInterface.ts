// Variable declarations → PLCopen var lists. Consecutive variables sharing class and attributes form
// one list, so declaration order survives the round trip.
import { isElementaryType, parseSizedString } from '../model/iecTypes';
import type { VarClass, Variable } from '../model/project';
import { writeInitialValue, writeTypeText } from './dataTypes';
import { RS_VARIABLE } from './types';
import type { XmlWriter } from './xml/write';

const LIST_OF: Record<VarClass, string> = {
  local: 'localVars',
  input: 'inputVars',
  output: 'outputVars',
  inOut: 'inOutVars',
  external: 'externalVars',
  temp: 'tempVars',
};

/**
 * A type element: `<BOOL/>`, `<string length="20"/>` (STRING[20]), `<derived name="TON"/>`, or an
 * anonymous `<array>`, `<struct>`, `<enum>`, `<subrangeSigned>` for such a type text.
 */
export function writeType(w: XmlWriter, type: string): void {
  writeTypeText(w, type, writeNamedType);
}

/** `<BOOL/>`, `<string/>`, `<string length="20"/>` (STRING[20]), `<derived name="TON"/>`. */
function writeNamedType(w: XmlWriter, type: string): void {
  const t = type.trim();
  const upper = t.toUpperCase();
  const sized = parseSizedString(upper);
  if (upper === 'STRING') w.empty('string');
  else if (upper === 'WSTRING') w.empty('wstring');
  else if (sized) w.empty(sized.type.toLowerCase(), { length: String(sized.length) });
  else if (isElementaryType(upper)) w.empty(upper);
  else if (upper === 'TIME_OF_DAY') w.empty('TOD');
  else if (upper === 'DATE_AND_TIME') w.empty('DT');
  else if (['LTIME', 'CHAR', 'WCHAR'].includes(upper)) w.empty(upper);
  else w.empty('derived', { name: t });
}

export function writeVariable(w: XmlWriter, v: Variable, impliedRetain: boolean): void {
  w.open('variable', { name: v.name, address: v.location || undefined }, () => {
    w.open('type', undefined, () => writeType(w, v.type));
    if (v.initial !== undefined && v.initial !== '') writeInitialValue(w, v.initial);
    if (impliedRetain) {
      w.open('addData', undefined, () =>
        w.open('data', { name: RS_VARIABLE, handleUnknown: 'discard' }, () =>
          w.empty('variable', { xmlns: '', retainByCoil: 'true' }),
        ),
      );
    }
    if (v.comment) w.formatted('documentation', v.comment);
  });
}

/**
 * Writes the var lists of a POU or of globals. `retainedByCoil` names variables written by M/SM/RM
 * coils: they go in a RETAIN list so other tools keep them over a warm restart as Rungsmith does,
 * marked so that an import gives back the original declaration.
 */
export function writeVarLists(
  w: XmlWriter,
  vars: readonly Variable[],
  retainedByCoil: ReadonlySet<string>,
  globalList = false,
): void {
  let i = 0;
  while (i < vars.length) {
    const first = vars[i]!;
    const implied = (v: Variable) => !v.retain && retainedByCoil.has(v.name.toUpperCase());
    const key = (v: Variable) =>
      `${globalList ? 'global' : v.varClass}|${v.retain || implied(v)}|${!!v.constant}`;
    const k = key(first);
    let j = i;
    while (j < vars.length && key(vars[j]!) === k) j++;
    const retain = first.retain || implied(first);
    const list = globalList ? 'globalVars' : LIST_OF[first.varClass];
    const group = vars.slice(i, j);
    w.open(
      list,
      { constant: first.constant ? 'true' : undefined, retain: retain ? 'true' : undefined },
      () => {
        for (const v of group) writeVariable(w, v, implied(v));
      },
    );
    i = j;
  }
}
