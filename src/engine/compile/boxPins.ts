// A box's pins as both kinds of call lower them, built-in blocks (box.ts) and user POUs
// (userCall.ts): what feeds an input (InputInfo), an output and the variable written beside it
// (OutputInfo, lowerOutput: LD-R11, data lines), an input's initial value as text, a source in words.
import type { BoxElement } from '../../model/elements';
import type { ElementaryType } from '../../model/iecTypes';
import type { PlacedPin } from '../../model/boxLayout';
import { canWiden } from '../values/types';
import type { AggValue } from './aggregatePins';
import type { PouContext } from './context';
import type { OutIR, Source } from './ir';
import type { NetMap } from './netMap';
import { accessWords } from './operands';
import { describeElement, type Reporter } from './report';
import { storeOf, type Access } from './symbols';

export interface InputInfo {
  readonly pin: PlacedPin;
  /** Wired source or operand; undefined when the pin is left open. */
  src?: Source;
  /** Known type of the source (undefined: an untyped literal or a data line not typed yet). */
  type?: ElementaryType;
  /** Operand text when the pin takes a literal that must be re-read at the resolved type. */
  literal?: string;
  /** A function input left unconnected: it takes its type's initial value (IEC; MATIEC's default). */
  open?: boolean;
  /** A struct/array pin of a user block: the whole value given to it (aggregatePins.ts). */
  agg?: AggValue;
}

/** An output pin of a box: its net, whether a line is attached, the variable written beside it. */
export interface OutputInfo {
  readonly pin: PlacedPin;
  readonly net: number;
  readonly wired: boolean;
  readonly operand: string;
}

export function lowerOutput(
  ctx: PouContext,
  nets: NetMap,
  el: BoxElement,
  name: string,
  o: { pin: PlacedPin; net: number; wired: boolean; operand: string },
  type: ElementaryType,
  fbPin: Access | undefined,
  r: Reporter,
): OutIR | undefined {
  let dst: Access | undefined;
  if (o.operand) {
    const res = ctx.symbols.resolve(o.operand, { literals: false, implicitLocations: true });
    if (!res.ok) {
      r.error(res.unknown ? 'LD-E02' : 'LD-R11', `output ${o.pin.name} of ${name}: ${res.message}`, el);
      return undefined;
    }
    const a = res.access;
    if (a.kind === 'pin' && a.dir === 'out')
      return void r.error(
        'LD-R11',
        `output ${o.pin.name} of ${name} cannot write ${accessWords(a)}, an output of another block`,
        el,
      );
    if ((a.kind === 'var' || a.kind === 'bit') && a.v.constant)
      return void r.error(
        'LD-R11',
        `output ${o.pin.name} of ${name} cannot write "${a.v.name}", which is CONSTANT`,
        el,
      );
    if (!canWiden(type, a.type))
      return void r.error(
        'LD-R11',
        `output ${o.pin.name} of ${name} gives ${type} but ${accessWords(a)} is ${a.type}`,
        el,
      );
    dst = a;
  }
  const g = nets.g.nets[o.net]!;
  if (type === 'BOOL') {
    nets.dataPending.delete(o.net);
    return { pin: o.pin.name, type, net: nets.powerNet(o.net), ...(dst ? { dst } : {}) };
  }
  if (!o.wired) return { pin: o.pin.name, type, ...(dst ? { dst } : {}) };
  // A data line: one source, read only by block inputs.
  if (g.sources.length > 1 || g.leftRail || g.feeds.length || g.feedsOut.length) {
    r.error(
      'LD-R11',
      `output ${o.pin.name} of ${name} carries ${type}; its line is joined to other outputs or to the rail`,
      el,
    );
    return undefined;
  }
  for (const s of g.sinks) {
    const sinkEl = nets.g.nodes[s.node]!.el;
    if (sinkEl.kind !== 'box')
      r.error(
        'LD-R11',
        `${describeElement(sinkEl)} is on the ${type} line from output ${o.pin.name} of ${name}; contacts and coils need BOOL power flow`,
        sinkEl,
      );
  }
  if (g.rightRail)
    r.error(
      'LD-R11',
      `output ${o.pin.name} of ${name} carries ${type} to the right rail; only power flow may reach the rail`,
      el,
    );
  let data: { store: ReturnType<typeof storeOf>; slot: number } | undefined;
  let source: Source;
  // openplc: a slot a block with an executionOrderId already reads (generated.ts): written here too.
  const held = nets.heldData.get(o.net);
  if (fbPin && !held) source = { from: 'access', access: fbPin };
  else {
    const store = storeOf(type);
    data = held && held.store === store ? held : { store, slot: ctx.symbols.counts[store]++ };
    if (data !== held) ctx.dataSlots.push({ ...data, type });
    source = { from: 'data', ...data, type };
  }
  nets.data.set(o.net, source);
  return { pin: o.pin.name, type, ...(data ? { data } : {}), ...(dst ? { dst } : {}) };
}

export function initialText(type: string): string {
  if (type === 'STRING') return "''";
  if (type === 'WSTRING') return '""';
  if (type === 'DATE') return 'D#1970-01-01';
  if (type === 'TOD') return 'TOD#00:00:00';
  if (type === 'DT') return 'DT#1970-01-01-00:00:00';
  return type === 'BOOL'
    ? 'FALSE'
    : type === 'TIME'
      ? 'T#0s'
      : type === 'REAL' || type === 'LREAL'
        ? '0.0'
        : '0';
}

export function describeSource(src: Source): string {
  if (src.from === 'power') return 'its line';
  if (src.from === 'data') return 'the wired value';
  return accessWords(src.access);
}
