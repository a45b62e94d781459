// Blocks a file calls that are neither standard, nor POUs of the file, nor blocks of a shipped
// vendor library (issue 12 part 5): each becomes an external block of the project with the pins
// the file wires, so the call imports with its wiring and the rest of the program runs. Pin types
// come from the variables wired to them where the file names a declared variable; otherwise the
// pin is untyped (shown as ANY, holds its initial value).
import type { BlockLibrary } from '../model/library';
import type { ExternalBlock, ExternalBlockPin, Pou } from '../model/project';
import { child, childrenNamed, type XmlElement } from './xml/parse';

const BODY_OBJECTS = new Set(['LD', 'FBD', 'SFC', 'body', 'actions', 'action', 'transitions', 'transition', 'inline']);

function* blocksIn(el: XmlElement): Generator<XmlElement> {
  for (const c of el.children) {
    if (c.name === 'block') yield c;
    else if (BODY_OBJECTS.has(c.name)) yield* blocksIn(c);
  }
}

/** Variables (in/out/inOut) of one body by localId, with their expression text. */
function variablesById(body: XmlElement): Map<string, { expr: string; el: XmlElement }> {
  const out = new Map<string, { expr: string; el: XmlElement }>();
  for (const c of body.children)
    if (c.name === 'inVariable' || c.name === 'outVariable' || c.name === 'inOutVariable') {
      const id = c.attrs.localId;
      const expr = child(c, 'expression')?.text.trim();
      if (id && expr) out.set(id, { expr, el: c });
    }
  return out;
}

const refsOf = (holder: XmlElement | undefined): string[] =>
  holder
    ? childrenNamed(holder, 'connection')
        .map((c) => c.attrs.refLocalId ?? '')
        .filter(Boolean)
    : [];

/**
 * External blocks for every block type of these POUs that the library does not know, in order
 * of first use. `library` already holds the file's POUs (and the shipped vendor blocks).
 */
export function unknownBlocks(
  pous: readonly { readonly el: XmlElement; readonly pou: Pou }[],
  library: BlockLibrary,
): {
  blocks: ExternalBlock[];
  /** Where each of `blocks` is first called. */
  firstUse: { pou: string; el: XmlElement }[];
  vendorCalls: { pou: string; type: string; el: XmlElement }[];
} {
  const vendorCalls: { pou: string; type: string; el: XmlElement }[] = [];
  const found = new Map<string, { name: string; fb: boolean; pins: Map<string, ExternalBlockPin>; pou: string; el: XmlElement }>();
  for (const { el, pou } of pous) {
    const declared = new Map(pou.variables.map((v) => [v.name.toUpperCase(), v.type]));
    const typeOf = (expr: string | undefined): string | undefined =>
      expr !== undefined ? declared.get(expr.trim().toUpperCase()) : undefined;
    const body = child(el, 'body');
    const holders = [...(body ? [body] : []), ...childrenNamed(child(el, 'actions') ?? el, 'action'), ...childrenNamed(child(el, 'transitions') ?? el, 'transition')];
    for (const holder of holders)
      for (const lang of holder.children.flatMap((c) => (c.name === 'body' ? c.children : [c]))) {
        if (!['LD', 'FBD'].includes(lang.name)) continue;
        const vars = variablesById(lang);
        // Output pins: outVariables whose input connects to (block localId, formalParameter).
        const outputTargets = new Map<string, string>();
        // Power flow is BOOL: an input fed by the rail or a contact/coil, an output feeding a contact/coil.
        const powerIds = new Set<string>();
        const powerTargets = new Set<string>();
        for (const v of lang.children)
          if (v.name === 'leftPowerRail' || v.name === 'contact' || v.name === 'coil') {
            if (v.attrs.localId) powerIds.add(v.attrs.localId);
            for (const c of childrenNamed(child(v, 'connectionPointIn') ?? v, 'connection'))
              if (c.attrs.refLocalId && c.attrs.formalParameter)
                powerTargets.add(`${c.attrs.refLocalId}|${c.attrs.formalParameter.toUpperCase()}`);
          }
        for (const v of lang.children) {
          if (v.name !== 'outVariable' && v.name !== 'inOutVariable') continue;
          for (const c of childrenNamed(child(v, 'connectionPointIn') ?? v, 'connection')) {
            const expr = child(v, 'expression')?.text.trim();
            if (c.attrs.refLocalId && c.attrs.formalParameter && expr)
              outputTargets.set(`${c.attrs.refLocalId}|${c.attrs.formalParameter.toUpperCase()}`, expr);
          }
        }
        for (const block of blocksIn(lang)) {
          const typeName = (block.attrs.typeName ?? '').trim();
          if (!typeName) continue;
          if (library.signature(typeName)) {
            if (library.isExternal(typeName)) vendorCalls.push({ pou: pou.name, type: library.signature(typeName)!.name, el: block });
            continue;
          }
          const key = typeName.toUpperCase();
          let entry = found.get(key);
          if (!entry) {
            entry = { name: typeName, fb: false, pins: new Map(), pou: pou.name, el: block };
            found.set(key, entry);
          }
          if (block.attrs.instanceName) entry.fb = true;
          const add = (name: string, dir: 'in' | 'out', type: string | undefined) => {
            const upper = name.toUpperCase();
            if (upper === 'EN' || upper === 'ENO' || !name) return;
            const had = entry.pins.get(upper);
            if (had && had.dir !== dir) entry.pins.set(upper, { ...had, dir: 'inOut', ...(had.type ?? type ? { type: had.type ?? type } : {}) });
            else if (!had) entry.pins.set(upper, { name, dir, ...(type ? { type } : {}) });
            else if (!had.type && type) entry.pins.set(upper, { ...had, type });
          };
          for (const v of childrenNamed(child(block, 'inputVariables') ?? block, 'variable')) {
            const refs = refsOf(child(v, 'connectionPointIn'));
            const power = refs.some((r) => powerIds.has(r));
            add(v.attrs.formalParameter ?? '', 'in', power ? 'BOOL' : typeOf(refs.map((r) => vars.get(r)?.expr).find(Boolean)));
          }
          for (const v of childrenNamed(child(block, 'inOutVariables') ?? block, 'variable')) {
            const refs = refsOf(child(v, 'connectionPointIn'));
            add(v.attrs.formalParameter ?? '', 'in', typeOf(refs.map((r) => vars.get(r)?.expr).find(Boolean)));
            add(v.attrs.formalParameter ?? '', 'out', undefined);
          }
          for (const v of childrenNamed(child(block, 'outputVariables') ?? block, 'variable')) {
            const pin = v.attrs.formalParameter ?? '';
            const at = `${block.attrs.localId ?? ''}|${pin.toUpperCase()}`;
            add(pin, 'out', powerTargets.has(at) ? 'BOOL' : typeOf(outputTargets.get(at)));
          }
        }
      }
  }
  const blocks = [...found.values()].map((e): ExternalBlock => {
    const pins = [...e.pins.values()];
    if (e.fb) return { name: e.name, kind: 'FUNCTION_BLOCK', pins, comment: 'Block of another library: interface as the file wires it' };
    // A function's result is its OUT pin (PLCopen's name for it); the other outputs are VAR_OUTPUTs.
    const result = pins.find((p) => p.name.toUpperCase() === 'OUT' && p.dir === 'out');
    return {
      name: e.name,
      kind: 'FUNCTION',
      pins,
      ...(result?.type ? { returnType: result.type } : {}),
      comment: 'Function of another library: interface as the file wires it',
    };
  });
  return { blocks, firstUse: [...found.values()].map((e) => ({ pou: e.pou, el: e.el })), vendorCalls };
}
