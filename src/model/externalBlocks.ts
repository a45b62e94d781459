// External blocks: blocks the simulator cannot run (MQTT, TCP sockets, board I/O of OpenPLC's
// libraries, or a block a file calls without defining it). Each is described as a synthesized
// FUNCTION_BLOCK or FUNCTION POU with its interface and no networks, marked in
// `extensions.external`, so the engine calls it like a user block with an empty body: its outputs
// hold their initial values, and the watch table and scenarios can write or force them by path
// (`MQTT1.SUCCESS`). Synthesized POUs never enter `project.pous`; export writes only their calls.
import type { BlockSignature } from './blocks';
import { isElementaryType } from './iecTypes';
import type { PouId } from './ids';
import type { ExternalBlock, ExternalBlockPin, Pou, Variable } from './project';

/** The `extensions.external` marker of a synthesized POU. */
export interface ExternalInfo {
  /** 'vendor': an interface Rungsmith ships (vendorBlocks.ts); 'project': one the project carries. */
  readonly origin: 'vendor' | 'project';
  readonly library?: string;
  readonly vendor?: string;
}

/** The name PLCopen and Beremiz give a function's result pin. */
const RESULT_PIN = 'OUT';
/** The type of a pin whose type nobody gave. */
const UNKNOWN_TYPE = 'ANY';
const EXECUTION_CONTROL = new Set(['EN', 'ENO']);

const VAR_CLASS: Record<ExternalBlockPin['dir'], Variable['varClass']> = { in: 'input', out: 'output', inOut: 'inOut' };

const isResultPin = (block: ExternalBlock, pin: ExternalBlockPin) =>
  block.kind === 'FUNCTION' && pin.dir === 'out' && pin.name.toUpperCase() === RESULT_PIN;

/**
 * The POU that stands for an external block. EN/ENO pins are dropped (a box shows them from its
 * kind or `executionControl`); a FUNCTION's `OUT` pin becomes its result, of `returnType`, else the
 * pin's type, else BOOL. A pin without a type is declared ANY.
 */
export function externalBlockPou(block: ExternalBlock, origin: ExternalInfo['origin'] = 'project'): Pou {
  const pins = block.pins.filter((p) => !EXECUTION_CONTROL.has(p.name.toUpperCase()));
  const result = pins.find((p) => isResultPin(block, p));
  const info: ExternalInfo = {
    origin,
    ...(block.library !== undefined ? { library: block.library } : {}),
    ...(block.vendor !== undefined ? { vendor: block.vendor } : {}),
  };
  return {
    id: `external:${block.name.toUpperCase()}` as PouId,
    name: block.name,
    kind: block.kind,
    ...(block.kind === 'FUNCTION' ? { returnType: block.returnType ?? result?.type ?? 'BOOL' } : {}),
    language: 'LD',
    comment: block.comment ?? '',
    variables: pins
      .filter((p) => p !== result)
      .map((p) => ({
        name: p.name,
        type: p.type?.trim() || UNKNOWN_TYPE,
        varClass: VAR_CLASS[p.dir],
        ...(p.initial !== undefined ? { initial: p.initial } : {}),
        retain: false,
        comment: '',
      })),
    networks: [],
    extensions: { external: info },
  };
}

/** The external marker of a POU, or undefined for a POU of the project. */
export function externalInfo(pou: Pou | undefined): ExternalInfo | undefined {
  const info = pou?.extensions?.['external'];
  return typeof info === 'object' && info !== null && 'origin' in info ? (info as ExternalInfo) : undefined;
}

/** Where the block comes from, in words: "OpenPLC MQTT library", "this project". */
export function externalSource(info: ExternalInfo): string {
  if (info.library) return `${info.vendor ? `${info.vendor} ` : ''}${info.library} library`;
  return info.origin === 'vendor' ? `${info.vendor ?? 'vendor'} library` : 'this project';
}

/**
 * The signature of an external block: the user-block signature of its POU, category 'external',
 * and a description that says it is not simulated and which pins Rungsmith cannot hold.
 */
export function externalSignature(base: BlockSignature, pou: Pou): BlockSignature {
  const info = externalInfo(pou);
  const declared = [...(pou.kind === 'FUNCTION' ? [{ name: RESULT_PIN, type: pou.returnType ?? 'BOOL' }] : []), ...pou.variables];
  const untyped = declared.filter((v) => !isElementaryType(v.type.toUpperCase())).map((v) => `${v.name} (${v.type})`);
  const what = pou.comment.trim() || `${pou.kind === 'FUNCTION' ? 'Function' : 'Function block'} ${pou.name}.`;
  const notes = [
    `External block${info ? ` (${externalSource(info)})` : ''}: the simulator does not run it; its outputs hold their initial values and can be set from the watch table or a scenario.`,
    ...(untyped.length
      ? [`Pins of types Rungsmith does not simulate show as ANY and keep their initial value; leave them unwired: ${untyped.join(', ')}.`]
      : []),
  ];
  return { ...base, category: 'external', description: `${what} ${notes.join(' ')}` };
}
