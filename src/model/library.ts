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
import { blockSignature, FB_SIGNATURES, FUNCTION_SIGNATURES, type BlockSignature, type PinSignature } from './blocks';
import { isElementaryType, type PinType } from './iecTypes';
import type { Pou, Project } from './project';

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
  /** The POU behind a user block (FUNCTION_BLOCK or FUNCTION), if the name is one. */
  userPou(name: string): Pou | undefined;
  /** True for a standard FB type or a user FUNCTION_BLOCK. */
  isFbType(type: string): boolean;
  /** The project's own blocks, in project order. */
  readonly userBlocks: readonly BlockSignature[];
  /** Standard blocks then user blocks. */
  all(): readonly BlockSignature[];
}

/** The name PLCopen and Beremiz give a function's result pin. */
export const FUNCTION_RESULT_PIN = 'OUT';

/** A pin type the box drawing and the type checks can use: the elementary type, or ANY for others. */
const pinType = (declared: string): PinType => {
  const t = declared.trim().toUpperCase();
  return isElementaryType(t) ? t : 'ANY';
};

const userPin = (name: string, declared: string, inOut: boolean): UserPinSignature => ({
  name,
  type: pinType(declared),
  declaredType: declared.trim(),
  ...(inOut ? { inOut: true as const } : {}),
});

/** The block signature of a FUNCTION_BLOCK or FUNCTION POU; undefined for a PROGRAM. */
export function pouSignature(pou: Pou): BlockSignature | undefined {
  if (pou.kind === 'PROGRAM') return undefined;
  const inputs: UserPinSignature[] = [];
  const outputs: UserPinSignature[] = [];
  if (pou.kind === 'FUNCTION') outputs.push(userPin(FUNCTION_RESULT_PIN, pou.returnType ?? 'BOOL', false));
  for (const v of pou.variables) if (v.varClass === 'input' || v.varClass === 'inOut') inputs.push(userPin(v.name, v.type, v.varClass === 'inOut'));
  for (const v of pou.variables) if (v.varClass === 'output') outputs.push(userPin(v.name, v.type, false));
  for (const v of pou.variables) if (v.varClass === 'inOut') outputs.push(userPin(v.name, v.type, true));
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

function makeLibrary(pous: readonly Pou[]): BlockLibrary {
  const users = new Map<string, { pou: Pou; sig: BlockSignature }>();
  for (const pou of pous) {
    const sig = pouSignature(pou);
    const key = pou.name.trim().toUpperCase();
    if (sig && !blockSignature(key) && !users.has(key)) users.set(key, { pou, sig });
  }
  const userBlocks = [...users.values()].map((u) => u.sig);
  const all = [...STANDARD, ...userBlocks];
  return {
    signature: (name) => blockSignature(name) ?? users.get(name.trim().toUpperCase())?.sig,
    userPou: (name) => users.get(name.trim().toUpperCase())?.pou,
    isFbType: (type) => {
      const s = blockSignature(type) ?? users.get(type.trim().toUpperCase())?.sig;
      return s?.kind === 'fb';
    },
    userBlocks,
    all: () => all,
  };
}

/** The standard library alone (no project). */
export const STANDARD_LIBRARY: BlockLibrary = makeLibrary([]);

const cache = new WeakMap<readonly Pou[], BlockLibrary>();

/**
 * The blocks of a project. Memoised on the project's `pous` array: projects are immutable, so an
 * edit that changes a POU gives a new array and a new library.
 */
export function blockLibrary(project: Pick<Project, 'pous'> | undefined): BlockLibrary {
  if (!project) return STANDARD_LIBRARY;
  let lib = cache.get(project.pous);
  if (!lib) {
    lib = makeLibrary(project.pous);
    cache.set(project.pous, lib);
  }
  return lib;
}

/** True when the pin is a VAR_IN_OUT of a user block. */
export const isInOutPin = (pin: PinSignature): boolean => (pin as UserPinSignature).inOut === true;

/** The declared type text of a pin (a standard pin's type, or a user pin's declaration). */
export const declaredPinType = (pin: PinSignature): string => (pin as UserPinSignature).declaredType ?? pin.type;
