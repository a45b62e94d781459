// "Why?": an explanation of an element's or a variable's value at one scan, built from the engine's
// own execution (the recorded power-flow nets and values of that scan) and the compiled program's
// structure (which operation reads and drives which net, which writes which variable). There is no
// second interpreter: every statement here is read off what the generated code computed.
import type { LdElement } from '../../model/elements';
import type { ElementaryType } from '../../model/iecTypes';
import type { Pou } from '../../model/project';
import type { CompiledProgram } from '../compile/program';
import type { Source } from '../compile/ir';
import { accessName, type Access } from '../compile/symbols';
import { formatValue } from '../values/literals';
import { accessKey, networkGraph, pathsTo, writesOf, type Arc, type PowerPath } from './graph';
import { fbReason } from './fbReasons';
import { elementSymbol, plural } from './words';
import { bodyAt } from './flatPou';
import type { ScanView } from './view';

export type ExplainTarget =
  | { readonly kind: 'element'; readonly network: number; readonly element: number }
  | { readonly kind: 'variable'; readonly name: string };

export type MarkRole = 'subject' | 'blocking' | 'path' | 'writer' | 'other-writer';

/** An element to draw on the canvas with the explanation. */
export interface ExplainMark {
  readonly network: number;
  readonly element: number;
  readonly elementId: string;
  readonly role: MarkRole;
}

/** "When did it change?": jump the timeline to `scan` and explain `target` there. */
export interface ExplainLink {
  readonly label: string;
  readonly scan: number;
  readonly target: ExplainTarget;
}

/** One path from the left rail to a coil and where its power stopped (index into `elements`), if it did. */
export interface PathReport {
  readonly elements: readonly { readonly network: number; readonly element: number }[];
  readonly blockedAt?: number;
}

export interface Explanation {
  readonly scan: number;
  readonly target: ExplainTarget;
  /** One line: `Motor is FALSE after scan 42`. */
  readonly title: string;
  /** The explanation in plain words, one statement per line. */
  readonly lines: readonly string[];
  readonly marks: readonly ExplainMark[];
  readonly links: readonly ExplainLink[];
  /** For a coil: each path from the left rail and where it was blocked. */
  readonly paths?: readonly PathReport[];
  /**
   * The located variables explained (`HighLevel` at `%IX0.3`): the simulator adds what drives an
   * input from outside or what an output drives (a machine in closed loop, issue 26).
   */
  readonly io?: readonly { readonly name: string; readonly location: string }[];
}

class Builder {
  readonly lines: string[] = [];
  readonly marks: ExplainMark[] = [];
  readonly links: ExplainLink[] = [];
  readonly io: { name: string; location: string }[] = [];
  private readonly linked = new Set<string>();
  constructor(
    readonly program: CompiledProgram,
    readonly pou: Pou,
    readonly view: ScanView,
  ) {}

  element(network: number, element: number): LdElement | undefined {
    return this.pou.networks[network]?.elements[element];
  }

  mark(network: number, element: number, role: MarkRole): void {
    const el = this.element(network, element);
    if (!el || this.marks.some((m) => m.network === network && m.element === element && m.role === role)) return;
    this.marks.push({ network, element, elementId: el.id, role });
  }

  typeOf(name: string): ElementaryType | undefined {
    const r = this.program.symbols.resolve(name, { literals: false, implicitLocations: false });
    return r.ok && r.access.kind !== 'const' ? r.access.type : undefined;
  }

  /** `TRUE`, `T#1s200ms`, `42`; `?` for a name the program cannot read. */
  show(name: string): string {
    const v = this.view.value(name);
    const t = this.typeOf(name);
    return v === undefined || !t ? '?' : formatValue(t, v);
  }

  /** Adds "X last changed at scan N" as a link (once per name). */
  changeLink(name: string, label?: string): number | undefined {
    const at = this.view.changedAt?.(name);
    if (at === undefined) return undefined;
    const key = `${name.toUpperCase()}@${at}`;
    if (!this.linked.has(key)) {
      this.linked.add(key);
      this.links.push({ label: label ?? `${name} changed to ${this.show(name)} at scan ${at.toLocaleString('en-US')}`, scan: at, target: { kind: 'variable', name } });
    }
    return at;
  }
}

/**
 * Network n (of the flattened program) in words: `network 3` or `network 3 (label Fill)` in the
 * program's own body, `network 2 of Motor1 (Motor)` in an FB instance's or another program's body.
 */
function networkName(b: Builder, n: number): string {
  const label = b.pou.networks[n]?.label;
  const body = bodyAt(b.program, n);
  const where = body && (body.first > 0 || body.instance) ? ` of ${body.instance ? `${body.instance} (${body.pou})` : body.pou}` : '';
  return `network ${n - (where ? body!.first : 0) + 1}${where}${label ? ` (label ${label})` : ''}`;
}

/** Why one arc's output on a path is off (the arc's input is on or it has none). */
function blockReason(b: Builder, network: number, arc: Arc, outNet: number): string {
  const op = arc.op;
  const el = b.element(network, arc.element);
  const sym = el ? elementSymbol(el) : 'an element';
  if (op.op === 'contact') {
    const name = op.src ? accessName(op.src) : '';
    const v = name ? b.show(name) : '';
    switch (op.contact) {
      case 'NO':
        return `${sym} is open: ${name} is ${v}`;
      case 'NC':
        return `${sym} is open: ${name} is ${v}, so the normally closed contact does not pass power`;
      case 'P':
        return `${sym} passes power only in the scan ${name} goes from FALSE to TRUE; it did not in this scan (${name} is ${v})`;
      case 'N':
        return `${sym} passes power only in the scan ${name} goes from TRUE to FALSE; it did not in this scan (${name} is ${v})`;
      case 'NOT':
        return `${sym} inverts its input: power reaches it, so it passes none`;
    }
  }
  if (op.op === 'fb') {
    const out = op.outs.find((o) => o.net === outNet);
    const instance = b.program.symbols.fbs[op.fb]!;
    const pin = out?.pin ?? 'Q';
    const reason = fbReason(b, instance.name, instance.type, pin);
    return `${sym}: ${instance.name}.${pin} is FALSE${reason ? ` (${reason})` : ''}`;
  }
  if (op.op === 'function') {
    const which = op.eno.net === outNet ? 'ENO' : 'its output';
    return `${sym}: ${which} is FALSE`;
  }
  return `${sym} passes no power`;
}

function describePath(b: Builder, network: number, path: PowerPath): string {
  if (path.length === 0) return 'straight from the left rail';
  return path
    .map(({ arc }) => {
      const el = b.element(network, arc.element);
      return el ? elementSymbol(el) : '?';
    })
    .join(' → ');
}

/** Paths from the rail to a net, each with where its power stopped; marks them on the canvas. */
function analysePaths(b: Builder, network: number, inNet: number, lead: string): PathReport[] {
  const g = networkGraph(b.program.networks[network]!);
  const paths = pathsTo(g, inNet);
  const reports: PathReport[] = [];
  const on = b.view.net(network, inNet);
  if (paths.length === 0) {
    b.lines.push(`${lead}: nothing connects it to the left rail.`);
    return reports;
  }
  const carried = (p: PowerPath) => carries(b, network, p);
  if (on) {
    const live = paths.find(carried);
    if (live) {
      b.lines.push(`${lead} is energised through ${describePath(b, network, live)}.`);
      for (const s of live) b.mark(network, s.arc.element, 'path');
      for (const s of live) contactChange(b, s.arc);
    }
  } else {
    b.lines.push(`${lead} gets no power: ${plural(paths.length, 'path')} from the left rail could energise it, and each is blocked:`);
  }
  for (const path of paths) {
    const blockedAt = carried(path) ? -1 : blockIndex(b, network, path);
    reports.push({ elements: path.map((s) => ({ network, element: s.arc.element })), ...(blockedAt >= 0 ? { blockedAt } : {}) });
    if (on || blockedAt < 0) continue;
    const step = path[blockedAt]!;
    b.mark(network, step.arc.element, 'blocking');
    b.lines.push(`  • ${describePath(b, network, path)}: ${blockReason(b, network, step.arc, step.outNet)}.`);
    contactChange(b, step.arc);
  }
  return reports;
}

/**
 * Whether the path carried power to its end: every element passed power from where the power on
 * the path starts (the rail, or the last |NOT| whose input along the path had none: it gives power).
 */
function carries(b: Builder, network: number, path: PowerPath): boolean {
  const out = (k: number) => b.view.net(network, path[k]!.outNet);
  let start = 0;
  for (let k = 1; k < path.length; k++) {
    const a = path[k]!.arc.op;
    if (a.op === 'contact' && a.contact === 'NOT' && !out(k - 1)) start = k;
  }
  for (let k = start; k < path.length; k++) if (!out(k)) return false;
  return true;
}

/**
 * Where a path that carries no power to its end lost it: the last element whose input along the path
 * (the rail, or the element before it) had power and whose own result had none. Without inverting
 * contacts that is the first open element; a |NOT| after it could give power back.
 */
function blockIndex(b: Builder, network: number, path: PowerPath): number {
  let at = -1;
  for (let k = 0; k < path.length; k++) {
    const pin = k === 0 ? true : b.view.net(network, path[k - 1]!.outNet);
    if (pin && !b.view.net(network, path[k]!.outNet)) at = k;
  }
  return at >= 0 ? at : path.findIndex((s) => !b.view.net(network, s.outNet));
}

/** For a contact on a path: when its variable last changed, to follow the chain back. */
function contactChange(b: Builder, arc: Arc): void {
  if (arc.op.op === 'contact' && arc.op.src && arc.op.src.kind !== 'const') b.changeLink(accessName(arc.op.src));
}

interface Writer {
  readonly network: number;
  readonly arc: Arc;
  /** Whether it wrote in the scan, and the value when known. */
  readonly wrote: boolean;
  readonly value?: boolean;
}

function writersOf(b: Builder, a: Access): Writer[] {
  const key = accessKey(a);
  const fbIndex = a.kind === 'pin' ? a.fb.index : -1;
  const out: Writer[] = [];
  b.program.networks.forEach((ir, network) => {
    const g = networkGraph(ir);
    const ran = b.view.executed(network);
    for (const arc of g.arcs) {
      const hit = writesOf(arc.op).some((w) => (w.access && accessKey(w.access) === key) || (w.fb !== undefined && w.fb === fbIndex && a.kind === 'pin' && a.dir === 'out'));
      if (!hit) continue;
      out.push({ network, arc, ...writeEffect(b, network, arc, ran) });
    }
  });
  return out;
}

function writeEffect(b: Builder, network: number, arc: Arc, ran: boolean): { wrote: boolean; value?: boolean } {
  if (!ran) return { wrote: false };
  const op = arc.op;
  if (op.op === 'coil') {
    const power = op.inNet >= 0 && b.view.net(network, op.inNet);
    switch (op.coil) {
      case 'COIL':
      case 'M':
        return { wrote: true, value: power };
      case 'NEG':
        return { wrote: true, value: !power };
      case 'SET':
      case 'SM':
        return power ? { wrote: true, value: true } : { wrote: false };
      case 'RESET':
      case 'RM':
        return power ? { wrote: true, value: false } : { wrote: false };
      case 'P':
      case 'N':
        return { wrote: true };
    }
  }
  const en = (op as { readonly en?: Source }).en;
  if (en?.from === 'power') return { wrote: b.view.net(network, en.net) };
  return { wrote: true };
}

function writerName(b: Builder, w: Writer): string {
  const el = b.element(w.network, w.arc.element);
  return `${el ? elementSymbol(el) : 'an element'} in ${networkName(b, w.network)}`;
}

/** Who wrote a variable in the scan: the last writer, the others, or where the value came from. */
function explainWriters(b: Builder, name: string, subject?: { network: number; element: number }): Writer | undefined {
  const r = b.program.symbols.resolve(name, { literals: false, implicitLocations: false });
  if (!r.ok || r.access.kind === 'const') {
    b.lines.push(`${name} is not a variable of ${b.program.pou}.`);
    return undefined;
  }
  const a = r.access;
  const writers = writersOf(b, a);
  const wrote = writers.filter((w) => w.wrote);
  const last = wrote[wrote.length - 1];
  const varName = a.kind === 'var' || a.kind === 'bit' ? a.v.name : name;
  const forced = b.view.forced?.has(varName.toUpperCase());
  if (a.kind === 'var' && a.v.locationText && !b.io.some((x) => x.name === varName)) b.io.push({ name: varName, location: a.v.locationText });
  if (forced) b.lines.push(`${varName} is forced: the program's writes do not change it.`);
  if (last) {
    b.mark(last.network, last.arc.element, 'writer');
    const others = wrote.length - 1;
    b.lines.push(
      `${name} was last written in scan ${b.view.scan.toLocaleString('en-US')} by ${writerName(b, last)}${last.value !== undefined ? `, which wrote ${last.value ? 'TRUE' : 'FALSE'}` : ''}${others > 0 ? ` (after ${plural(others, 'other write')} in the same scan)` : ''}.`,
    );
  } else if (a.kind === 'var' && a.v.location?.area === 'I') {
    b.lines.push(`Nothing in the program writes ${name}: it is an input (${a.v.locationText}), read from the input image at the start of the scan.`);
  } else if (writers.length === 0) {
    b.lines.push(`Nothing in the program writes ${name}: it keeps its initial value or what was written or forced from outside.`);
  } else {
    b.lines.push(`No writer of ${name} wrote it in scan ${b.view.scan.toLocaleString('en-US')}: it kept its value from the scan before.`);
  }
  if (writers.length > 1) {
    b.lines.push(`${name} has ${plural(writers.length, 'writer')} (two coils on one variable: the last one that runs wins):`);
    for (const w of writers) {
      const isSubject = subject && subject.network === w.network && subject.element === w.arc.element;
      if (w !== last && !isSubject) b.mark(w.network, w.arc.element, 'other-writer');
      b.lines.push(`  • ${writerName(b, w)}${w.wrote ? (w.value !== undefined ? `: wrote ${w.value ? 'TRUE' : 'FALSE'}` : ': wrote') : ': did not write in this scan'}${w === last ? ' (last)' : ''}`);
    }
  }
  return last;
}

export function explain(program: CompiledProgram, pou: Pou, view: ScanView, target: ExplainTarget): Explanation {
  const b = new Builder(program, pou, view);
  let title: string;
  let paths: PathReport[] | undefined;
  const scanText = `scan ${view.scan.toLocaleString('en-US')}`;
  if (target.kind === 'variable') {
    const name = target.name;
    title = `${name} is ${b.show(name)} after ${scanText}`;
    const last = explainWriters(b, name);
    if (last && last.arc.op.op === 'coil' && last.arc.op.inNet >= 0)
      paths = analysePaths(b, last.network, last.arc.op.inNet, `The coil ${elementSymbol(b.element(last.network, last.arc.element)!)}`);
    else if (last && last.arc.op.op === 'fb') {
      const fb = program.symbols.fbs[last.arc.op.fb]!;
      const pin = name.slice(name.indexOf('.') + 1).toUpperCase();
      const reason = fbReason(b, fb.name, fb.type, pin);
      if (reason) b.lines.push(`${fb.name}.${pin} is ${b.show(name)}: ${reason}.`);
    }
    changeOf(b, name, target);
  } else {
    const el = b.element(target.network, target.element);
    if (!el) return { scan: view.scan, target, title: 'Nothing to explain', lines: ['The element is not in the program that ran.'], marks: [], links: [] };
    b.mark(target.network, target.element, 'subject');
    const sym = elementSymbol(el);
    const ran = view.executed(target.network);
    // openplc: a contact is read again at each coil's turn; its latest reading is the one shown.
    const readings = program.networks[target.network] ? networkGraph(program.networks[target.network]!).arcs.filter((a) => a.element === target.element && a.op.op !== 'pass') : [];
    const arc = el.kind === 'contact' ? readings[readings.length - 1] : readings[0];
    title = `${sym} in ${networkName(b, target.network)}, ${scanText}`;
    if (!ran) b.lines.push(`${networkName(b, target.network)} did not run in ${scanText}: a jump or RETURN skipped it, so nothing in it was evaluated.`);
    if (el.kind === 'coil') {
      const name = el.variable.trim();
      title = `${sym}: ${name} is ${b.show(name)} after ${scanText}`;
      if (!arc) b.lines.push(`${sym} is not connected to anything that could energise it, so it is not executed.`);
      else if (ran && arc.op.op === 'coil' && arc.op.inNet >= 0) paths = analysePaths(b, target.network, arc.op.inNet, `The coil ${sym}`);
      explainWriters(b, name, target);
      changeOf(b, name, target);
    } else if (el.kind === 'contact') {
      const name = el.variable.trim();
      if (arc && arc.op.op === 'contact' && ran) {
        const inOn = arc.op.inNet >= 0 && view.net(target.network, arc.op.inNet);
        const outOn = view.net(target.network, arc.outNets[0]!);
        title = `${sym} is ${outOn ? 'passing power' : 'not passing power'} in ${scanText}`;
        b.lines.push(inOn ? `Power reaches its left side.` : `No power reaches its left side.`);
        if (!outOn && inOn) b.lines.push(`${blockReason(b, target.network, arc, arc.outNets[0]!)}.`);
        else if (outOn) b.lines.push(name ? `It is closed: ${name} is ${b.show(name)}.` : 'It passes power.');
        else if (name) b.lines.push(`${name} is ${b.show(name)}.`);
        if (!inOn) analysePaths(b, target.network, arc.op.inNet, `Its left side`);
        if (readings.length > 1)
          b.lines.push(
            `Under the openplc profile this contact is read ${readings.length} times in each scan, once for each coil or block whose path holds it (as Beremiz and OpenPLC generate it); this is its last reading. A coil read by an earlier reading may have seen another value: ask "Why?" on that coil.`,
          );
      }
      if (name) {
        explainWriters(b, name);
        changeOf(b, name, { kind: 'variable', name });
      }
    } else if (el.kind === 'box') {
      if (el.instance) {
        const type = el.blockType.toUpperCase();
        title = `${el.instance} (${type}) after ${scanText}`;
        const fb = program.symbols.fbs.find((f) => f.name.toUpperCase() === el.instance!.toUpperCase());
        if (fb) {
          for (const pin of ['Q', 'QU', 'QD', 'Q1'].filter((p) => view.value(`${fb.name}.${p}`) !== undefined)) {
            const reason = fbReason(b, fb.name, fb.type, pin);
            b.lines.push(`${fb.name}.${pin} is ${b.show(`${fb.name}.${pin}`)}${reason ? `: ${reason}` : ''}.`);
            changeOf(b, `${fb.name}.${pin}`, { kind: 'variable', name: `${fb.name}.${pin}` });
          }
        }
      } else if (arc && arc.op.op === 'function') {
        const op = arc.op;
        const enOn = op.en?.from === 'power' ? view.net(target.network, op.en.net) : true;
        b.lines.push(enOn ? `${sym} ran in this scan (EN is TRUE).` : `${sym} did not run: EN is FALSE, so its outputs kept their values and ENO is FALSE.`);
        if (!enOn && op.en?.from === 'power') analysePaths(b, target.network, op.en.net, 'Its EN input');
      }
    } else if (arc && arc.inNets.length > 0) {
      const on = view.net(target.network, arc.inNets[0]!);
      b.lines.push(on ? 'Power reaches it.' : 'No power reaches it.');
      if (!on) analysePaths(b, target.network, arc.inNets[0]!, sym);
    }
  }
  return { scan: view.scan, target, title, lines: b.lines, marks: b.marks, links: b.links, ...(paths ? { paths } : {}), ...(b.io.length ? { io: b.io } : {}) };
}

function changeOf(b: Builder, name: string, target: ExplainTarget): void {
  const at = b.view.changedAt?.(name);
  if (at === undefined) {
    if (b.view.changedAt) b.lines.push(`${name} did not change in the recorded scans.`);
    return;
  }
  b.links.unshift({ label: `When did it change? ${name} became ${b.show(name)} at scan ${at.toLocaleString('en-US')}`, scan: at, target });
}
