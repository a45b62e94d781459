// The values on box pins that no name reads (issue 24, monitoring): a data line from one block's
// output to another block's input carries a value the program keeps in a slot of its own (a
// function's result, boxPins.ts lowerOutput) or reads from an FB instance's output. For the canvas
// to show that value beside both pins, this lists, per body network, each box pin whose value is such
// a line, and where the value lives. Pins given a variable or a literal are read by their names.
import type { ElementaryType } from '../../model/iecTypes';
import type { Op, Source } from './ir';
import type { CompiledProgram } from './program';
import { yieldPoint } from '../yieldPoint';

export interface PinLine {
  /** Network index relative to the body's first network. */
  readonly network: number;
  /** The box's index in the network's elements (document order). */
  readonly element: number;
  readonly pin: string;
  readonly side: 'in' | 'out';
  readonly type: ElementaryType;
  /** Where the value is: a data slot, or the FB instance output the line reads. */
  readonly src: Extract<Source, { from: 'data' } | { from: 'access' }>;
}

type Call = Extract<Op, { op: 'function' | 'fb' | 'call' }>;
const isCall = (op: Op): op is Call => op.op === 'function' || op.op === 'fb' || op.op === 'call';

/** The last segment of a callee variable's name: the pin it stands for (`site.IN1` -> `IN1`). */
const pinOf = (name: string): string => name.slice(name.lastIndexOf('.') + 1);

/**
 * What an input reads, when it may be a line: a slot, or a variable or FB output (a wire from an FB
 * instance's output reads it; so does a pin given that name, which the canvas reads by its name).
 */
function lineSource(src: Source): PinLine['src'] | undefined {
  if (src.from === 'data') return src;
  if (src.from === 'access' && (src.access.kind === 'pin' || src.access.kind === 'var' || src.access.kind === 'bit')) return src;
  return undefined;
}

/** The pins of one call op that carry a data line. */
function callLines(network: number, op: Call, out: PinLine[]): void {
  const element = op.node;
  const input = (pin: string, type: ElementaryType, src: Source) => {
    const line = lineSource(src);
    if (line && type !== 'BOOL') out.push({ network, element, pin, side: 'in', type, src: line });
  };
  const output = (pin: string, type: ElementaryType, data: { store: 'b' | 'n' | 'g'; slot: number } | undefined) => {
    if (data && type !== 'BOOL') out.push({ network, element, pin, side: 'out', type, src: { from: 'data', ...data, type } });
  };
  switch (op.op) {
    case 'function':
      for (const a of op.args) input(a.pin, a.type, a.src);
      output(op.out.pin, op.out.type, op.out.data);
      return;
    case 'fb':
      for (const a of op.args) input(a.pin, a.type, a.src);
      for (const o of op.outs) output(o.pin, o.type, o.data);
      return;
    case 'call':
      for (const a of op.assigns) if (a.dst.kind === 'var') input(pinOf(a.dst.v.name), a.dst.type, a.src);
      for (const o of op.outs) output(o.out.pin, o.out.type, o.out.data);
      return;
  }
}

/**
 * The data lines on box pins of the networks [first, end) of the program: one entry per input fed by
 * a line and per output that feeds one (BOOL lines are power flow, drawn as such). A box's own call is
 * its first call operation; later ones on the same element (the openplc profile's writes of the
 * variables beside its outputs) are not its pins.
 */
export function pinLines(program: CompiledProgram, first: number, end: number): PinLine[] {
  const out: PinLine[] = [];
  for (let n = first; n < end; n++) {
    const ir = program.networks[n];
    if (!ir) continue;
    const seen = new Set<number>();
    const visit = (ops: readonly Op[]) => {
      for (const op of ops) {
        if (!isCall(op) || op.node < 0 || seen.has(op.node)) continue;
        seen.add(op.node);
        callLines(n - first, op, out);
      }
    };
    visit(ir.ops);
    for (const seg of ir.early ?? []) visit(seg);
    visit(ir.late ?? []);
    yieldPoint();
  }
  return out;
}
