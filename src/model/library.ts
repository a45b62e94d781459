// The blocks a project can call: the standard library (blocks.ts) plus the project's own
// FUNCTION_BLOCK and FUNCTION POUs, whose pins come from their interfaces. Shared by the editor
// (palette, box drawing), the engine (type checks, calls) and PLCopen import/export, so a user
// block is drawn, checked and exported from one description.
//
// Pins of a user POU (IEC 61131-3 6.6.1, graphical representation):
// - inputs: VAR_INPUT then VAR_IN_OUT, each class in declaration order;
// - outputs: a FUNCTION's result `OUT` (the name PLCopen files use for it), then VAR_OUTPUT,
//   then VAR_IN_OUT (an in-out pin appears on both sides, joined through the box).
// A FUNCTION box shows EN/ENO like a standard function; an FB box shows them when the box asks
// (BoxElement.executionControl), as for standard FBs.
//
// External blocks (externalBlocks.ts) resolve like user blocks, through a synthesized POU with no
// networks: the project's `externalBlocks`, then OpenPLC's vendor libraries (vendorBlocks.ts).
// Libraries kept with the project (project.libraries, libraries.ts) resolve like the project's own
// POUs (category 'user', `library` set), after them.
// Precedence by name: standard block, then the project's own POU, then a library's block, then the
// project's external block, then the vendor block.
import { blockSignature, FB_SIGNATURES, FUNCTION_SIGNATURES, type BlockSignature, type PinSignature } from './blocks';
import { externalBlockPou, externalSignature } from './externalBlocks';
import { isElementaryType, type PinType } from './iecTypes';
import type { DataType, ExternalBlock, Pou, Project, ProjectLibrary } from './project';
import { ENUM_STORAGE, resolveType } from './dataTypes';
import { VENDOR_BLOCKS } from './vendorBlocks';

/** A pin of a user block: its declared type text, kept even when it is not an elementary type. */
export interface UserPinSignature extends PinSignature {
  /** VAR_IN_OUT: passed by reference; listed in both inputs and outputs. */
  readonly inOut?: true;
  /** The type as declared (e.g. `INT`, `STRING`, `MyStruct`); `type` is it when elementary. */
  readonly declaredType: string;
}

export interface BlockLibrary {
  /** Standard or user block by (case-insensitive) name. A user POU never hides a standard block. */
  signature(name: string): BlockSignature | undefined;
  /**
   * The POU behind a user block (FUNCTION_BLOCK or FUNCTION), if the name is one; for an external
   * block, its synthesized POU (no networks, `extensions.external`, never in `project.pous`).
   */
  userPou(name: string): Pou | undefined;
  /** True for a standard FB type, a user FUNCTION_BLOCK or an external function block. */
  isFbType(type: string): boolean;
  /** True when the name resolves to an external block (the simulator does not run its body). */
  isExternal(name: string): boolean;
  /** The project's own blocks, in project order. */
  readonly userBlocks: readonly BlockSignature[];
  /** Blocks of the libraries kept with the project, library by library (`library` set). */
  readonly libraryBlocks: readonly BlockSignature[];
  /** External blocks: the project's, then the vendor libraries', library by library (category 'external'). */
  readonly externalBlocks: readonly BlockSignature[];
  /** Standard blocks, user blocks, then external blocks. */
  all(): readonly BlockSignature[];
}

const NO_TYPES: readonly DataType[] = [];
const NO_LIBRARIES: readonly ProjectLibrary[] = [];

/** The name PLCopen and Beremiz give a function's result pin. */
export const FUNCTION_RESULT_PIN = 'OUT';

/**
 * A pin type the box drawing and the type checks can use: the elementary type (that of an alias,
 * subrange or enum data type, dataTypes.ts: an enum is stored as INT), or ANY for others.
 */
const pinType = (declared: string, dataTypes: readonly DataType[]): PinType => {
  const t = declared.trim().toUpperCase();
  if (isElementaryType(t)) return t;
  const r = resolveType({ pous: [], dataTypes }, declared);
  if (!r.ok) return 'ANY';
  const s = r.shape;
  return s.kind === 'elementary' ? s.type : s.kind === 'subrange' ? s.base : s.kind === 'enum' ? ENUM_STORAGE : 'ANY';
};

const userPin = (name: string, declared: string, inOut: boolean, dataTypes: readonly DataType[]): UserPinSignature => ({
  name,
  type: pinType(declared, dataTypes),
  declaredType: declared.trim(),
  ...(inOut ? { inOut: true as const } : {}),
});

/** The block signature of a FUNCTION_BLOCK or FUNCTION POU; undefined for a PROGRAM. */
export function pouSignature(pou: Pou, dataTypes: readonly DataType[] = NO_TYPES): BlockSignature | undefined {
  if (pou.kind === 'PROGRAM') return undefined;
  const inputs: UserPinSignature[] = [];
  const outputs: UserPinSignature[] = [];
  const pin = (name: string, declared: string, inOut: boolean) => userPin(name, declared, inOut, dataTypes);
  if (pou.kind === 'FUNCTION') outputs.push(pin(FUNCTION_RESULT_PIN, pou.returnType ?? 'BOOL', false));
  for (const v of pou.variables) if (v.varClass === 'input' || v.varClass === 'inOut') inputs.push(pin(v.name, v.type, v.varClass === 'inOut'));
  for (const v of pou.variables) if (v.varClass === 'output') outputs.push(pin(v.name, v.type, false));
  for (const v of pou.variables) if (v.varClass === 'inOut') outputs.push(pin(v.name, v.type, true));
  return {
    name: pou.name,
    kind: pou.kind === 'FUNCTION' ? 'function' : 'fb',
    category: 'user',
    inputs,
    outputs,
    description: pou.comment.trim() || `${pou.kind === 'FUNCTION' ? 'Function' : 'Function block'} ${pou.name} of this project.`,
  };
}

const STANDARD: readonly BlockSignature[] = [...FB_SIGNATURES, ...FUNCTION_SIGNATURES];

interface Entry {
  readonly pou: Pou;
  readonly sig: BlockSignature;
}

const externalEntry = (block: ExternalBlock, origin: 'vendor' | 'project'): Entry | undefined => {
  const pou = externalBlockPou(block, origin);
  const base = pouSignature(pou);
  return base && { pou, sig: externalSignature(base, pou) };
};

/** Adds the entries whose name is not taken yet (by a standard block or an earlier entry). */
function addEntries(into: Map<string, Entry>, entries: Iterable<Entry | undefined>): Entry[] {
  const added: Entry[] = [];
  for (const e of entries) {
    const key = e?.pou.name.trim().toUpperCase();
    if (!e || !key || blockSignature(key) || into.has(key)) continue;
    into.set(key, e);
    added.push(e);
  }
  return added;
}

/** The vendor blocks' entries, built once: they are the same for every project. */
let vendorEntries: readonly Entry[] | undefined;
const vendor = () => (vendorEntries ??= VENDOR_BLOCKS.map((b) => externalEntry(b, 'vendor')).filter((e) => e !== undefined));

function makeLibrary(
  pous: readonly Pou[],
  externals: readonly ExternalBlock[],
  withVendor: boolean,
  dataTypes: readonly DataType[] = NO_TYPES,
  libraries: readonly ProjectLibrary[] = NO_LIBRARIES,
): BlockLibrary {
  const byName = new Map<string, Entry>();
  const types = libraries.length ? [...dataTypes, ...libraries.flatMap((l) => l.dataTypes ?? [])] : dataTypes;
  const users = addEntries(
    byName,
    pous.map((pou) => {
      const sig = pouSignature(pou, types);
      return sig && { pou, sig };
    }),
  );
  const libs = addEntries(
    byName,
    libraries.flatMap((lib) =>
      lib.pous.map((pou) => {
        const sig = pouSignature(pou, types);
        const what = `${pou.kind === 'FUNCTION' ? 'Function' : 'Function block'} ${pou.name} of the library ${lib.name}.`;
        return sig && { pou, sig: { ...sig, library: lib.name, description: pou.comment.trim() ? `${pou.comment.trim()} (library ${lib.name})` : what } };
      }),
    ),
  );
  const ext = [...addEntries(byName, externals.map((b) => externalEntry(b, 'project'))), ...(withVendor ? addEntries(byName, vendor()) : [])];
  const userBlocks = users.map((u) => u.sig);
  const libraryBlocks = libs.map((u) => u.sig);
  const externalBlocks = ext.map((e) => e.sig);
  const externalKeys = new Set(ext.map((e) => e.pou.name.trim().toUpperCase()));
  const all = [...STANDARD, ...userBlocks, ...libraryBlocks, ...externalBlocks];
  const find = (name: string) => byName.get(name.trim().toUpperCase());
  return {
    signature: (name) => blockSignature(name) ?? find(name)?.sig,
    userPou: (name) => (blockSignature(name) ? undefined : find(name)?.pou),
    isFbType: (type) => (blockSignature(type) ?? find(type)?.sig)?.kind === 'fb',
    isExternal: (name) => !blockSignature(name) && externalKeys.has(name.trim().toUpperCase()),
    userBlocks,
    libraryBlocks,
    externalBlocks,
    all: () => all,
  };
}

/** The standard library alone (no project, no vendor blocks). */
export const STANDARD_LIBRARY: BlockLibrary = makeLibrary([], [], false);

const NO_EXTERNALS: readonly ExternalBlock[] = [];
const cache = new WeakMap<
  readonly Pou[],
  WeakMap<readonly ExternalBlock[], WeakMap<readonly DataType[], WeakMap<readonly ProjectLibrary[], BlockLibrary>>>
>();

/** The value of `key` in a WeakMap, made by `make` on first use. */
function memo<K extends object, V>(map: WeakMap<K, V>, key: K, make: () => V): V {
  let v = map.get(key);
  if (v === undefined) {
    v = make();
    map.set(key, v);
  }
  return v;
}

/**
 * The blocks of a project: standard, its own POUs, its external blocks and the vendor blocks.
 * Memoised on the project's `pous`, `externalBlocks`, `dataTypes` and `libraries` arrays: projects are immutable, so an edit
 * that changes a POU or an external block gives a new array and a new library.
 */
export function blockLibrary(
  project: Pick<Project, 'pous' | 'externalBlocks' | 'dataTypes' | 'libraries'> | undefined,
): BlockLibrary {
  if (!project) return STANDARD_LIBRARY;
  const externals = project.externalBlocks ?? NO_EXTERNALS;
  const types = project.dataTypes ?? NO_TYPES;
  const libraries = project.libraries ?? NO_LIBRARIES;
  const byExternals = memo(cache, project.pous, () => new WeakMap());
  const byTypes = memo(byExternals, externals, () => new WeakMap());
  const byLibraries = memo(byTypes, types, () => new WeakMap());
  return memo(byLibraries, libraries, () => makeLibrary(project.pous, externals, true, types, libraries));
}

/** True when the pin is a VAR_IN_OUT of a user block. */
export const isInOutPin = (pin: PinSignature): boolean => (pin as UserPinSignature).inOut === true;

/** The declared type text of a pin (a standard pin's type, or a user pin's declaration). */
export const declaredPinType = (pin: PinSignature): string => (pin as UserPinSignature).declaredType ?? pin.type;
