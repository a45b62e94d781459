// POUs in ST, IL, SFC or FBD (an FBD body that does not convert to LD). Rungsmith keeps their
// interface (LD networks call them, the editor lists them) and their body as written (`source`).
// Export gives the `<pou>` of the file back byte for byte while the POU is as imported; once its
// name, kind, interface, source or comment is edited, the `<pou>` is written anew from the model
// (interface from the variables, body from `source`, SFC actions and transitions as read).
import type { Pou } from '../model/project';
import { writeType, writeVarLists } from './exportInterface';
import { preserved, XHTML_NS, type PreservedPou } from './types';
import { libraryInfo } from '../model/codesysUtil';
import { CODESYS_CFC } from './codesys';
import type { XmlWriter } from './xml/write';

const POU_TYPE = { PROGRAM: 'program', FUNCTION_BLOCK: 'functionBlock', FUNCTION: 'function' } as const;

/** What the kept `<pou>` element depends on: equal fingerprints, same element. */
export function pouFingerprint(pou: Pou): string {
  return JSON.stringify([pou.name, pou.kind, pou.returnType ?? '', pou.language, pou.source ?? '', pou.comment, pou.variables]);
}

/** The interface of a POU: return type, then its var lists in declaration order. */
export function writeInterface(w: XmlWriter, pou: Pou, retainedByCoil: ReadonlySet<string>): void {
  w.open('interface', undefined, () => {
    if (pou.kind === 'FUNCTION') w.open('returnType', undefined, () => writeType(w, pou.returnType || 'BOOL'));
    writeVarLists(w, pou.variables, retainedByCoil);
  });
}

/** Writes a POU that is not in LD (see the file comment); `marks`: addData `data` to add (a library's mark). */
export function writeOtherPou(w: XmlWriter, pou: Pou, marks: readonly string[] = []): void {
  // A block of a vendor library the import added (CODESYS Util): the vendor's tool brings its own.
  if (libraryInfo(pou)) return;
  const keep = preserved<PreservedPou>(pou.extensions);
  if (keep?.pou && keep.fingerprint === pouFingerprint(pou) && !marks.length) {
    w.raw(keep.pou);
    return;
  }
  w.open('pou', { name: pou.name, pouType: POU_TYPE[pou.kind] }, () => {
    writeInterface(w, pou, new Set());
    if (keep?.actions) w.raw(keep.actions);
    if (keep?.transitions) w.raw(keep.transitions);
    w.open('body', undefined, () => {
      const source = pou.source ?? '';
      if (pou.language === 'ST' || pou.language === 'IL') w.formatted(pou.language, source);
      else if (!keep?.legacyBody && source.trim().startsWith(`<${pou.language}`)) w.raw(source);
      else if (source.trim().startsWith('<CFC')) {
        // CODESYS's shape: an empty ST body, the CFC graph in its addData (codesys.ts).
        w.open('ST', undefined, () => w.empty('xhtml', { xmlns: XHTML_NS }));
        w.open('addData', undefined, () => w.open('data', { name: CODESYS_CFC, handleUnknown: 'implementation' }, () => w.raw(source)));
      }
      else w.empty(pou.language);
    });
    const addData = [...(keep?.addData ?? []), ...marks];
    if (addData.length) w.open('addData', undefined, () => addData.forEach((d) => w.raw(d)));
    if (pou.comment) w.formatted('documentation', pou.comment);
  });
}
