// What CODESYS V3 writes in its PLCopen exports (namespace tc6_0200) beyond the TC6 schema, in
// `addData` of http://www.3s-software.com/plcopenxml/...:
// - POUs and data types of the application (the ones under "Application" in the device tree) are
//   not in `types` but in the resource's addData: `resource/addData/data[@name=.../pou]/pou`,
//   `data[@name=.../datatype]/dataType`; an application exported alone is a resource in the
//   project's addData (`data[@name=.../application]/resource`), with its tasks;
// - a CFC body is `<body><ST><xhtml/></ST><addData><data name=".../cfc"><CFC>...</CFC>`: an empty
//   ST body with the CFC graph beside it;
// - a task's `pouInstance` names the program in `name` and leaves `typeName` empty;
// - every object carries its object id (`.../objectid`, handleUnknown="discard").
// Library blocks CODESYS projects call without declaring them are in model/codesysUtil.ts.
import { blockSignature } from '../model/blocks';
import { codesysUtilBlock, fitsPins, isCodesysUtilName } from '../model/codesysUtil';
import type { Pou } from '../model/project';
import { hasInputAliases, iecInputName } from '../model/vendorPins';
import { child, childrenNamed, type XmlElement } from './xml/parse';

export const CODESYS_DATA = 'http://www.3s-software.com/plcopenxml/';
export const CODESYS_POU = `${CODESYS_DATA}pou`;
export const CODESYS_CFC = `${CODESYS_DATA}cfc`;
export const CODESYS_DATATYPE = `${CODESYS_DATA}datatype`;
export const CODESYS_APPLICATION = `${CODESYS_DATA}application`;
export const CODESYS_OBJECT_ID = `${CODESYS_DATA}objectid`;

const dataNamed = (holder: XmlElement | undefined, name: string): XmlElement[] => {
  const add = holder ? child(holder, 'addData') : undefined;
  return add ? childrenNamed(add, 'data').filter((d) => d.attrs.name === name) : [];
};

/**
 * The resources CODESYS writes outside `instances` when it exports an application alone:
 * `project/addData/data[@name=.../application]/resource`.
 */
export function applicationResources(root: XmlElement): XmlElement[] {
  return dataNamed(root, CODESYS_APPLICATION).flatMap((d) => childrenNamed(d, 'resource'));
}

function inApplication(root: XmlElement, data: string, element: string): XmlElement[] {
  const out: XmlElement[] = [];
  const instances = child(root, 'instances');
  const configs = instances ? childrenNamed(child(instances, 'configurations') ?? instances, 'configuration') : [];
  for (const conf of configs) {
    for (const d of dataNamed(conf, data)) out.push(...childrenNamed(d, element));
    for (const res of childrenNamed(conf, 'resource'))
      for (const d of dataNamed(res, data)) out.push(...childrenNamed(d, element));
  }
  for (const res of applicationResources(root)) for (const d of dataNamed(res, data)) out.push(...childrenNamed(d, element));
  return out;
}

/** The POUs CODESYS writes in the addData of configurations and resources, in file order. */
export const applicationPous = (root: XmlElement): XmlElement[] => inApplication(root, CODESYS_POU, 'pou');

/** The data types (DUTs) CODESYS writes in the addData of configurations and resources. */
export const applicationDataTypes = (root: XmlElement): XmlElement[] => inApplication(root, CODESYS_DATATYPE, 'dataType');

/** The `<CFC>` graph of a CODESYS body, if it is one. */
export function cfcOf(body: XmlElement | undefined): XmlElement | undefined {
  for (const d of dataNamed(body, CODESYS_CFC)) {
    const cfc = child(d, 'CFC');
    if (cfc) return cfc;
  }
  return undefined;
}

/**
 * A type named with the namespace of a CODESYS library whose blocks Rungsmith knows by their bare
 * names: `Standard.TON` is TON, `Util.BLINK` is BLINK. Other namespaces (MQTT.*, SysCom.*) stay.
 */
export function unqualifiedType(name: string): string {
  const m = /^\s*(?:Standard|Standard64|Util)\.([A-Za-z_]\w*)\s*$/i.exec(name);
  return m ? m[1]! : name;
}

/** Where blocks sit: bodies (a CFC one in addData), SFC actions and transitions; never inside a block. */
const HOLDERS = new Set(['body', 'LD', 'FBD', 'SFC', 'CFC', 'addData', 'data', 'actions', 'action', 'transitions', 'transition', 'inline']);

/** The blocks of a POU element, found once per import (three passes below read them). */
const blocksCache = new WeakMap<XmlElement, XmlElement[]>();
function blocksOf(el: XmlElement): XmlElement[] {
  let found = blocksCache.get(el);
  if (!found) {
    found = [];
    collectBlocks(el, found);
    blocksCache.set(el, found);
  }
  return found;
}
function collectBlocks(el: XmlElement, into: XmlElement[]): void {
  for (const c of el.children) {
    if (c.name === 'block') into.push(c);
    else if (HOLDERS.has(c.name)) collectBlocks(c, into);
  }
}
const pinsOf = (b: XmlElement): string[] =>
  ['inputVariables', 'inOutVariables', 'outputVariables'].flatMap((list) =>
    childrenNamed(child(b, list) ?? b, 'variable').map((x) => x.attrs.formalParameter ?? ''),
  );

/**
 * The Util blocks (model/codesysUtil.ts) that these POUs call or declare instances of without the
 * file declaring a POU of that name, each wired only through its own pins: the library POUs to
 * add to the project, in order of first use, with where that is.
 */
export function utilBlocksUsed(
  pous: readonly { readonly el: XmlElement; readonly pou: Pou }[],
): { pou: Pou; firstUse: { pou: string; el: XmlElement } }[] {
  const declared = new Set(pous.map((p) => p.pou.name.toUpperCase()));
  const used = new Map<string, { pou: Pou; fits: boolean; firstUse: { pou: string; el: XmlElement } }>();
  const note = (name: string, pins: () => string[], where: { pou: string; el: XmlElement }) => {
    const key = name.trim().toUpperCase();
    const lib = codesysUtilBlock(key);
    if (!lib || declared.has(key) || blockSignature(key)) return;
    const had = used.get(key);
    used.set(key, { pou: lib, fits: (had?.fits ?? true) && fitsPins(lib, pins()), firstUse: had?.firstUse ?? where });
  };
  for (const { el, pou } of pous) {
    for (const b of blocksOf(el)) note(b.attrs.typeName ?? '', () => pinsOf(b).filter(Boolean), { pou: pou.name, el: b });
    // Instances declared (and called from ST, or not at all).
    for (const v of pou.variables) note(v.type, () => [], { pou: pou.name, el });
  }
  return [...used.values()].filter((u) => u.fits).map(({ pou, firstUse }) => ({ pou, firstUse }));
}

/**
 * Calls of a block that Util and the standard library both name (HYSTERESIS, PID, INTEGRAL,
 * DERIVATIVE: OpenPLC's annex F blocks, which always win) wired with pins the standard block does
 * not have: a CODESYS program calling Util's block. The import names them (their wires to the
 * unknown pins are dropped).
 */
export function utilNameClashes(
  pous: readonly { readonly el: XmlElement; readonly pou: Pou }[],
): { name: string; pins: string[]; pou: string; el: XmlElement }[] {
  const out: { name: string; pins: string[]; pou: string; el: XmlElement }[] = [];
  for (const { el, pou } of pous)
    for (const b of blocksOf(el)) {
      const name = (b.attrs.typeName ?? '').trim();
      if (!isCodesysUtilName(name)) continue;
      const sig = blockSignature(name);
      if (!sig) continue;
      const known = new Set([...sig.inputs, ...sig.outputs].map((p) => p.name.toUpperCase()));
      const pins = pinsOf(b).filter((p) => p && !['EN', 'ENO'].includes(p.toUpperCase()));
      const foreign = pins.filter((p) => !known.has(p.toUpperCase()));
      if (foreign.length) out.push({ name: sig.name, pins: foreign, pou: pou.name, el: b });
    }
  return out;
}

/** The CODESYS input names of standard blocks these POUs wire (`CTU.RESET -> R`), in order of first use. */
export function standardPinAliases(pous: readonly { readonly el: XmlElement }[]): string[] {
  const seen = new Set<string>();
  for (const { el } of pous)
    for (const b of blocksOf(el)) {
      const type = (b.attrs.typeName ?? '').trim().toUpperCase();
      if (!hasInputAliases(type)) continue;
      for (const v of childrenNamed(child(b, 'inputVariables') ?? b, 'variable')) {
        const pin = v.attrs.formalParameter ?? '';
        const iec = iecInputName(type, pin);
        if (iec) seen.add(`${type}.${pin.toUpperCase()} as ${iec}`);
      }
    }
  return [...seen];
}
