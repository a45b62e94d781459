// VAR_EXTERNAL where the target needs it (issue 24): MATIEC, which OpenPLC and Beremiz build with,
// lets a POU read a configuration's or resource's VAR_GLOBAL only through a VAR_EXTERNAL of the same
// name and type (IEC 61131-3 2.4.1.2). Rungsmith lets every POU use the project's globals directly,
// so the export under the openplc profile declares, in each LD program and function block, a
// VAR_EXTERNAL for every global its networks use and it does not declare itself (a FUNCTION may not
// have one: IEC 61131-3 and MATIEC refuse it). The names added are recorded in the POU's addData,
// and the import drops exactly those again, so export then import gives the project back.
// Pure: no DOM.
import type { LdElement } from '../model/elements';
import type { Pou, Profile, Variable } from '../model/project';
import { childrenNamed, type XmlElement } from './xml/parse';
import { escapeAttr } from './xml/write';
import { RS_NS } from './types';

export const RS_EXTERNALS = `${RS_NS}/addedExternals`;

/** Profiles whose target compiles only with the VAR_EXTERNAL declarations (MATIEC). */
export const needsExternals = (profile: Profile): boolean => profile === 'openplc';

/** The variable (first identifier) an operand names: `Word.3` and `Timer1.Q` name Word and Timer1. */
const IDENT = /^\s*([A-Za-z_][A-Za-z0-9_]*)/;

function operands(el: LdElement): readonly string[] {
  switch (el.kind) {
    case 'contact':
    case 'coil':
      return [el.variable];
    case 'box':
      return [el.instance ?? '', ...Object.values(el.inputs), ...Object.values(el.outputs)];
    default:
      return [];
  }
}

/**
 * The VAR_EXTERNAL declarations a POU lacks: the globals its LD networks use that it does not
 * declare (a local of the same name hides the global), in order of first use, with the global's
 * type and CONSTANT. None for a FUNCTION or a POU in another language.
 */
export function missingExternals(pou: Pou, globals: readonly Variable[]): Variable[] {
  if (pou.language !== 'LD' || pou.kind === 'FUNCTION') return [];
  const declared = new Set(pou.variables.map((v) => v.name.toUpperCase()));
  const byName = new Map(globals.map((g) => [g.name.toUpperCase(), g]));
  const out = new Map<string, Variable>();
  for (const net of pou.networks)
    for (const el of net.elements)
      for (const text of operands(el)) {
        const name = IDENT.exec(text)?.[1];
        const key = name?.toUpperCase();
        const g = key ? byName.get(key) : undefined;
        if (!g || declared.has(key!) || out.has(key!)) continue;
        out.set(key!, {
          name: g.name,
          type: g.type,
          varClass: 'external',
          retain: false,
          ...(g.constant ? { constant: true } : {}),
          comment: '',
        });
      }
  return [...out.values()];
}

/** The POU's addData `data` naming the VAR_EXTERNALs the export added. */
export const externalsMark = (added: readonly Variable[]): string =>
  `<data name="${RS_EXTERNALS}" handleUnknown="discard"><externals xmlns="${RS_NS}">${added
    .map((v) => `<variable name="${escapeAttr(v.name)}"/>`)
    .join('')}</externals></data>`;

/** The names a POU's `data` says the export added (upper-cased), if the `data` is that record. */
export function readExternalsMark(data: XmlElement): Set<string> | undefined {
  if (data.attrs.name !== RS_EXTERNALS) return undefined;
  const list = childrenNamed(data, 'externals')[0];
  return new Set(
    (list ? childrenNamed(list, 'variable') : []).map((v) => (v.attrs.name ?? '').toUpperCase()).filter(Boolean),
  );
}
