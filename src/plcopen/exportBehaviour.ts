// What an exported LD program does differently once Beremiz or OpenPLC compile it (issue 12,
// LD-SEMANTICS.md "Export to Beremiz/OpenPLC"). Both tools turn a graphical body into ST with the
// same generator, PLCGenerator.py (beremiz/beremiz; thiagoralves/OpenPLC_Editor editor/PLCGenerator.py),
// and MATIEC compiles that ST. Facts of that generator this analysis relies on:
// - ProgramGenerator/PouProgramGenerator.ComputeProgram, for an LD or FBD body, generates only
//   coils, outVariables/inOutVariables, blocks and connectors. `jump`, `label` and `return`
//   objects are never looked at: they are dropped without a message (LD-X01, LD-X02).
// - ComputeProgram orders them: blocks and outVariables with an executionOrderId first (Rungsmith
//   writes back those an imported file had, BoxElement.executionOrder/outputOrders; such a block is
//   never late, so LD-X03 skips it), then every coil and outVariable of the body sorted by position (SortInstances: top to bottom,
//   left to right), then the blocks no coil or outVariable needed, then connectors. A block is
//   generated (GenerateBlock, once per block: ComputedBlocks) when the first coil or outVariable
//   whose path reaches it is generated. A function block whose outputs reach only the right rail
//   (or nothing) is therefore called after every coil of the POU (LD-X03); a function none of
//   whose inputs is connected is cancelled ("function cancelled ... No input connected") (LD-X04).
// - GeneratePaths/ComputeExpression re-trace the whole path of every coil from the left rail, so a
//   contact is read again for each coil (and outVariable) that needs it, at that coil's turn; the
//   engine evaluates each element once in a topological order (section 6). A contact on the path of
//   a coil reads a variable another coil of the same network writes: when the write comes between
//   the two reads in one order and not in the other, the two differ (LD-X05).
// - GeneratePaths builds each path as nested lists (AND) and tuples (OR); ComputePaths writes a
//   tuple in brackets except at the top of an expression. A continuation is replaced by the text
//   of its connector's expression, computed as a top (so an OR there has no brackets) and pasted as
//   is: a contact after it ANDs only its first term (LD-X06). A coil that is the source of another
//   element contributes the list of its own input paths, which ComputePaths ANDs: after an OR join,
//   the element after the coil sees the AND of the branches (LD-X07). Both are bugs of the
//   generator: the simulator does not copy them (a connector pair is a wire), in either profile.
// The simulator's openplc profile runs LD bodies in that order (engine/compile/generated.ts): for
// a project under it the warnings stay (the export is the same) and say the simulation shows it.
// Pure: no React, no DOM.
import { buildGraph, upstream as drivers, type NetworkGraph } from '../engine/compile/graph';
import { evaluationOrder } from '../engine/compile/order';
import { cellName, describeElement } from '../engine/compile/report';
import { boxLayout } from '../model/boxLayout';
import type { BoxElement, CoilElement, LdElement } from '../model/elements';
import type { Cell } from '../model/grid';
import { newId, type ElementId, type NetworkId, type PouId } from '../model/ids';
import { STANDARD_LIBRARY, blockLibrary, type BlockLibrary } from '../model/library';
import type { Network, Pou, Project, Variable } from '../model/project';
import { gridGraph, type GridGraph, type Source } from './gridGraph';

export type ExportRuleId = 'LD-X01' | 'LD-X02' | 'LD-X03' | 'LD-X04' | 'LD-X05' | 'LD-X06' | 'LD-X07' | 'LD-X08';

/** An edit that makes the exported program behave the same: one network rewritten, variables added. */
export interface ExportFix {
  /** What the button does, e.g. `Add a coil "RedTime_Q" on output Q of TON "RedTime"`. */
  readonly label: string;
  readonly pouId: PouId;
  readonly before: Network;
  readonly after: Network;
  /** Local variables the fix declares in the POU. */
  readonly variables: readonly Variable[];
}

export interface ExportWarning {
  readonly rule: ExportRuleId;
  readonly pou: string;
  readonly pouId: PouId;
  /** 0-based network index. */
  readonly network: number;
  readonly networkId: NetworkId;
  readonly networkLabel?: string;
  readonly cell?: Cell;
  readonly elementId?: ElementId;
  readonly message: string;
  readonly fix?: ExportFix;
}

const TOOLS = 'Beremiz and OpenPLC';

/** What a warning adds when the project's profile is openplc: the simulation already behaves so. */
const SIMULATED_SO: Record<ExportRuleId, string> = {
  'LD-X01': 'This project runs under the openplc profile, so the simulator ignores this jump too (LD-W20).',
  'LD-X02': 'This project runs under the openplc profile, so the simulator ignores this RETURN too (LD-W21).',
  'LD-X03': 'This project runs under the openplc profile, so the simulator already calls it there: what you see in simulation is what the exported program does.',
  'LD-X04': 'This project runs under the openplc profile, so the simulator does not call it either (LD-W22).',
  'LD-X05': 'This project runs under the openplc profile, so the simulator already reads it again: what you see in simulation is what the exported program does.',
  'LD-X06': 'The simulator does not copy this bug of their generator, under either profile: what you see in simulation is what the drawing means, not what the exported program does.',
  'LD-X07': 'The simulator does not copy this bug of their generator, under either profile: what you see in simulation is what the drawing means, not what the exported program does.',
  'LD-X08': 'Import the exported file to simulate the order it gets.',
};
const up = (s: string) => s.trim().toUpperCase();

/** `warning LD-X03 Main/network 1:R1C3 message` (the shape of the check's lines). */
export function formatExportWarning(w: ExportWarning): string {
  const label = w.networkLabel ? ` (${w.networkLabel})` : '';
  const cell = w.cell ? `:${cellName(w.cell.row, w.cell.col)}` : '';
  return `warning ${w.rule} ${w.pou}/network ${w.network + 1}${label}${cell} ${w.message}`;
}

/** "network 4", "networks 4, 5 and 7". */
function networksText(indexes: Iterable<number>): string {
  const list = [...new Set(indexes)].sort((a, b) => a - b).map((i) => String(i + 1));
  if (list.length === 1) return `network ${list[0]}`;
  return `networks ${list.slice(0, -1).join(', ')} and ${list[list.length - 1]}`;
}

/** "networks 2 to 4", "network 2" (and the verb that goes with it). */
const rangeText = (from: number, to: number) =>
  from === to ? `network ${from + 1}` : `networks ${from + 1} to ${to + 1}`;
const runs = (from: number, to: number) => (from === to ? 'runs' : 'run');

interface NetView {
  readonly net: Network;
  readonly index: number;
  readonly g: NetworkGraph;
  /** Rungsmith's evaluation position of each node; undefined when the network has a feedback wire. */
  readonly pos: Int32Array | undefined;
}

function viewOf(net: Network, index: number, library: BlockLibrary): NetView {
  const g = buildGraph(net, library);
  const order = evaluationOrder(g);
  let pos: Int32Array | undefined;
  if (order) {
    pos = new Int32Array(g.nodes.length);
    order.forEach((node, k) => (pos![node] = k));
  }
  return { net, index, g, pos };
}

/** Nodes upstream of `from` (not itself), following input nets to their producers. */
function upstream(g: NetworkGraph, from: number, stop?: (node: number) => boolean): Set<number> {
  const seen = new Set<number>();
  const todo = [from];
  while (todo.length) {
    const n = todo.pop()!;
    for (const t of g.nodes[n]!.inputs)
      for (const s of drivers(g, t.net).sources) {
        if (s.node === from || seen.has(s.node)) continue;
        seen.add(s.node);
        if (!stop?.(s.node)) todo.push(s.node);
      }
  }
  return seen;
}

/** Output operands of a box that name a variable (Beremiz writes each as an outVariable). */
const outputOperands = (el: BoxElement) =>
  Object.entries(el.outputs).filter(([, v]) => v !== undefined && v.trim() !== '');

/** Coils and boxes with an output variable: what ComputeProgram generates in position order. */
function isPuller(el: LdElement): boolean {
  return el.kind === 'coil' || (el.kind === 'box' && outputOperands(el).length > 0);
}

/**
 * Sort key of a puller as ComputeProgram sorts it (SortInstances on the exported positions: rows
 * are far apart, so row first, then x): a coil sits in its cell, an outVariable right of its box.
 */
function pullerKey(el: LdElement, library: BlockLibrary): [number, number] {
  if (el.kind === 'box') {
    const layout = boxLayout(el, library);
    const cols = layout?.cols ?? 2;
    const pins = layout?.outputs.filter((p) => (el.outputs[p.name] ?? '').trim() !== '') ?? [];
    const row = pins.length ? el.row + Math.min(...pins.map((p) => p.rowOffset)) : el.row;
    return [row, 2 * (el.col + cols)];
  }
  return [el.row, 2 * el.col + 1];
}

/** Variables an element writes: a coil's variable, a box's output operands. */
function writes(el: LdElement): string[] {
  if (el.kind === 'coil') return el.variable.trim() ? [up(el.variable)] : [];
  if (el.kind === 'box') return outputOperands(el).map(([, v]) => up(v));
  return [];
}

/** Variables an element reads: a contact's variable, a box's input operands. */
function reads(el: LdElement): string[] {
  if (el.kind === 'contact') return el.contact !== 'NOT' && el.variable.trim() ? [up(el.variable)] : [];
  if (el.kind === 'box') return Object.values(el.inputs).filter((v) => v && v.trim()).map(up);
  return [];
}

function locate(pou: Pou, v: NetView, el?: LdElement) {
  return {
    pou: pou.name,
    pouId: pou.id,
    network: v.index,
    networkId: v.net.id,
    ...(v.net.label ? { networkLabel: v.net.label } : {}),
    ...(el ? { cell: { row: el.row, col: el.col }, elementId: el.id } : {}),
  };
}

/** LD-X01 jumps and LD-X02 RETURNs: dropped by ComputeProgram, which never looks at them. */
function dropped(pou: Pou, views: readonly NetView[], out: ExportWarning[]): void {
  const last = views.length - 1;
  for (const v of views) {
    for (const node of v.g.nodes) {
      const el = node.el;
      if (el.kind !== 'jump' && el.kind !== 'return') continue;
      const fromRail = node.inputs.some((t) => drivers(v.g, t.net).leftRail);
      const when = fromRail ? 'every scan' : 'when it is powered';
      if (el.kind === 'jump') {
        const target = views.findIndex((x) => x.net.label && up(x.net.label) === up(el.target));
        let effect: string;
        if (target > v.index + 1)
          effect = `so ${rangeText(v.index + 1, target - 1)}, which it skips ${when} here, ${runs(v.index + 1, target - 1)} in every scan there`;
        else if (target >= 0 && target <= v.index)
          effect = `so ${rangeText(target, v.index)}, which it runs again ${when} here, ${runs(target, v.index)} only once per scan there`;
        else if (target === v.index + 1) continue; // a jump to the next network changes nothing
        else effect = 'so the program runs as if it were not there';
        out.push({
          ...locate(pou, v, el),
          rule: 'LD-X01',
          message: `${TOOLS} drop ${describeElement(el)} without a word (their code generator never writes jumps or labels), ${effect}. No equivalent exists: move the skipped networks into a function block called only when they must run, or keep the program in Rungsmith.`,
        });
      } else {
        if (v.index === last) continue; // nothing after it to skip
        out.push({
          ...locate(pou, v, el),
          rule: 'LD-X02',
          message: `${TOOLS} drop ${describeElement(el)} without a word (their code generator never writes RETURN), so ${rangeText(v.index + 1, last)}, which it ends the POU before ${when} here, ${runs(v.index + 1, last)} in every scan there. No equivalent exists: put the rest of the POU in a function block called only when it must run, or keep the program in Rungsmith.`,
        });
      }
    }
  }
}

/**
 * LD-X08: networks imported with Beremiz's interleaved order (Network.turns, networks drawn side
 * by side) run that way under openplc; the export draws every network under the one before, so
 * ComputeProgram's SortInstances runs the exported file network by network, row by row.
 */
function interleaved(pou: Pou, views: readonly NetView[], out: ExportWarning[]): void {
  const turned = (i: number) => views[i]?.net.turns !== undefined;
  for (let i = 0; i < views.length; ) {
    if (!turned(i)) {
      i++;
      continue;
    }
    let j = i;
    while (turned(j + 1)) j++;
    const what =
      i === j
        ? `the coils of ${rangeText(i, j)} run in the order they were drawn in the imported file, not row by row`
        : `${rangeText(i, j)} run their coils and output variables interleaved, in the order the imported file drew them side by side`;
    out.push({
      ...locate(pou, views[i]!),
      rule: 'LD-X08',
      message: `Under the openplc profile ${what}. The export draws every network below the one before it, so ${TOOLS} run the exported program network by network, row by row: a variable written in one of these networks and read in another may change one scan later or sooner. Keep the program in Rungsmith, or check the exported program's order by simulating the exported file.`,
    });
    i = j + 1;
  }
}

/** The variables of a POU plus the globals, by upper-case name. */
function declaredNames(project: Project, pou: Pou): Set<string> {
  return new Set([...pou.variables, ...project.globals].map((x) => up(x.name)));
}

/** A name for a new BOOL variable that no variable of the POU or global has. */
function freshName(taken: Set<string>, base: string): string {
  const clean = base.replace(/[^A-Za-z0-9_]/g, '_');
  let name = clean;
  for (let k = 2; taken.has(up(name)); k++) name = `${clean}_${k}`;
  return name;
}

/**
 * A coil on `pin` of the box at node `boxNode`, on the row where that output's line reaches the
 * right rail: it replaces the line's last cell, or the network grows by one column for it. Returns
 * the new network, or undefined when no such place exists.
 */
function withCoilOn(v: NetView, boxNode: number, pin: string, variable: string, library: BlockLibrary): Network | undefined {
  const { net, g } = v;
  const term = g.nodes[boxNode]!.outputs.find((t) => t.pin === pin);
  if (!term) return undefined;
  const target = g.nets[term.net]!;
  if (!target.rightRail) return undefined;
  const railRows = [...new Set(target.points.map((p) => Math.floor(p / (net.cols + 1))))].filter(
    (r) => g.netOfPoint[r * (net.cols + 1) + net.cols] === term.net,
  );
  const coil = (row: number, col: number): CoilElement => ({
    id: newId<'ElementId'>('e') as ElementId,
    kind: 'coil',
    coil: 'COIL',
    variable,
    row,
    col,
  });
  const candidates: Network[] = [];
  for (const r of railRows) {
    const last = net.elements.findIndex((e) => e.kind === 'link' && e.row === r && e.col === net.cols - 1);
    if (last >= 0)
      candidates.push({ ...net, elements: net.elements.map((e, i) => (i === last ? coil(r, net.cols - 1) : e)) });
  }
  // No line cell to take: one more column, the lines that reached the rail carried on to it.
  const row = railRows[0] ?? term.row;
  const reaching = [...Array(net.rows).keys()].filter((r) => {
    const id = g.netOfPoint[r * (net.cols + 1) + net.cols]!;
    return id >= 0 && g.nets[id]!.sources.length > 0 && !g.nets[id]!.leftRail;
  });
  candidates.push({
    ...net,
    cols: net.cols + 1,
    elements: [
      ...net.elements,
      ...reaching
        .filter((r) => r !== row)
        .map((r) => ({ id: newId<'ElementId'>('e') as ElementId, kind: 'link' as const, row: r, col: net.cols })),
      coil(row, net.cols),
    ],
  });
  // Keep the first candidate in which the new coil is fed by the box's output.
  for (const after of candidates) {
    const g2 = buildGraph(after, library);
    if (g2.misplaced.length) continue;
    const coilNode = g2.nodes.findIndex((n) => n.el.kind === 'coil' && n.el.variable === variable);
    const boxEl = g.nodes[boxNode]!.el;
    const fed = g2.nodes[coilNode]?.inputs.some((t) =>
      drivers(g2, t.net).sources.some((s) => g2.nodes[s.node]!.el.id === boxEl.id && s.pin === pin),
    );
    if (fed) return after;
  }
  return undefined;
}

/** LD-X03 (late function blocks), LD-X04 (cancelled functions), LD-X05 (contacts read again). */
function ordering(project: Project, pou: Pou, views: readonly NetView[], library: BlockLibrary, out: ExportWarning[]): void {
  // Every element of the POU with where it is and when Rungsmith evaluates it.
  const before = (a: NetView, an: number, b: NetView, bn: number) =>
    a.index !== b.index ? a.index < b.index : a.pos !== undefined && a.pos[an]! < a.pos[bn]!;
  const taken = declaredNames(project, pou);
  // What ComputeProgram generates in the coils' turn (coils, outVariables and all their paths);
  // the rest runs after them, in the blocks' turn.
  const pulledIn = views.map(({ g }) => {
    const pullers = g.nodes.map((_, i) => i).filter((i) => isPuller(g.nodes[i]!.el));
    const pulled = new Set<number>(pullers);
    for (const p of pullers) for (const u of upstream(g, p)) pulled.add(u);
    return pulled;
  });

  for (const v of views) {
    const { g } = v;
    const pulled = pulledIn[v.index]!;

    for (const [bi, node] of g.nodes.entries()) {
      const el = node.el;
      if (el.kind !== 'box') continue;
      const layout = boxLayout(el, library);
      if (!layout) continue;
      const isFb = library.isFbType(el.blockType);
      if (!isFb) {
        // GenerateBlock cancels a function none of whose inputs (EN aside) is connected.
        const connected = node.inputs.some(
          (t) => t.pin !== 'EN' && drivers(g, t.net).fed,
        );
        const operands = Object.entries(el.inputs).some(([k, x]) => k !== 'EN' && x && x.trim());
        if (!connected && !operands && layout.inputs.some((p) => p.name !== 'EN'))
          out.push({
            ...locate(pou, v, el),
            rule: 'LD-X04',
            message: `${TOOLS} never call ${describeElement(el)}: none of its inputs is connected, and their code generator cancels such a call ("function cancelled: No input connected"). Connect or assign its inputs.`,
          });
        continue;
      }
      if (!el.instance || pulled.has(bi) || el.executionOrder) continue;
      const inst = up(el.instance);
      // Readers of the instance's outputs that run after the call here (before the end of the scan there).
      const readersAfter: number[] = [];
      // Variables the call reads (on its paths) that are written after it here (before it there).
      const feeding = new Set<string>();
      const ups = upstream(g, bi);
      for (const u of [bi, ...ups]) for (const r of reads(g.nodes[u]!.el)) feeding.add(r);
      const writtenAfter: { name: string; net: number }[] = [];
      for (const w of views) {
        w.g.nodes.forEach((n, ni) => {
          if (w === v && (ni === bi || ups.has(ni))) return;
          if (!before(v, bi, w, ni)) return;
          // A reader in the blocks' turn itself runs after this call there too.
          if (pulledIn[w.index]!.has(ni) && reads(n.el).some((r) => r.startsWith(`${inst}.`)))
            readersAfter.push(w.index);
          for (const x of writes(n.el)) if (feeding.has(x)) writtenAfter.push({ name: x, net: w.index });
        });
      }
      if (!readersAfter.length && !writtenAfter.length) continue;
      const railPin = node.outputs.find((t) => g.nets[t.net]!.rightRail)?.pin;
      const how = railPin
        ? `its output ${railPin} reaches only the right rail (no coil, no output variable)`
        : 'none of its outputs drives a coil or an output variable';
      const effects: string[] = [];
      if (readersAfter.length)
        effects.push(`what reads ${el.instance}'s outputs in ${networksText(readersAfter)} sees them one scan late`);
      if (writtenAfter.length) {
        const names = [...new Set(writtenAfter.map((x) => x.name))];
        const shown = pou.variables.concat(project.globals).filter((x) => names.includes(up(x.name)));
        effects.push(
          `it reads ${(shown.length ? shown.map((x) => `"${x.name}"`) : names.map((n) => `"${n}"`)).join(', ')} after ${networksText(writtenAfter.map((x) => x.net))} write${writtenAfter.length === 1 ? 's' : ''} ${names.length === 1 ? 'it' : 'them'}, one scan early`,
        );
      }
      let fix: ExportFix | undefined;
      if (railPin) {
        const name = freshName(taken, `${el.instance}_${railPin}`);
        const after = withCoilOn(v, bi, railPin, name, library);
        if (after) {
          taken.add(up(name));
          fix = {
            label: `Add a coil "${name}" on output ${railPin} of ${el.blockType} "${el.instance}"`,
            pouId: pou.id,
            before: v.net,
            after,
            variables: [
              {
                name,
                type: 'BOOL',
                varClass: 'local',
                retain: false,
                comment: `${el.instance}.${railPin}; the coil makes Beremiz/OpenPLC call ${el.instance} in network order`,
              },
            ],
          };
        }
      }
      out.push({
        ...locate(pou, v, el),
        rule: 'LD-X03',
        message: `${describeElement(el)}: ${how}, so ${TOOLS} call it after every coil of the POU, at the end of the scan, not in this network: ${effects.join('; ')}.${fix ? ` A coil on ${railPin} makes them call it here.` : ''}`,
        ...(fix ? { fix } : {}),
      });
    }
    reread(pou, v, library, out);
  }
}

/** LD-X05: a contact read again for a later coil after a coil of the same network wrote its variable. */
function reread(pou: Pou, v: NetView, library: BlockLibrary, out: ExportWarning[]): void {
  const { g, pos } = v;
  if (!pos) return;
  const pullers = g.nodes
    .map((n, i) => ({ i, key: pullerKey(n.el, library) }))
    .filter((p) => isPuller(g.nodes[p.i]!.el))
    .sort((a, b) => a.key[0] - b.key[0] || a.key[1] - b.key[1])
    .map((p) => p.i);
  if (pullers.length < 2) return;
  // When ComputeProgram reads each contact: at the turn of every puller whose path reaches it,
  // except through a block an earlier puller already generated (GenerateBlock runs once).
  const readAt = new Map<number, number[]>();
  const generated = new Set<number>();
  pullers.forEach((p, turn) => {
    const isBox = (n: number) => g.nodes[n]!.el.kind === 'box';
    // An outVariable of a block an earlier coil generated only reads the block's output.
    if (isBox(p) && generated.has(p)) return;
    const seen = upstream(g, p, (n) => isBox(n) && generated.has(n));
    for (const n of seen) {
      if (isBox(n) && generated.has(n)) continue;
      if (g.nodes[n]!.el.kind === 'contact') readAt.set(n, [...(readAt.get(n) ?? []), turn]);
    }
    for (const n of seen) if (isBox(n)) generated.add(n);
    if (isBox(p)) generated.add(p);
  });
  const turnOf = new Map(pullers.map((p, t) => [p, t]));
  // A network of contacts and coils only: try every value of its variables; when both orders end
  // with the same values (a seal-in with a parallel coil does), there is nothing to report.
  if (sameForAllValues(v) === true) return;
  const reported = new Set<number>();
  for (const [c, turns] of readAt) {
    const contact = g.nodes[c]!.el;
    const name = reads(contact)[0];
    if (!name) continue;
    for (const w of pullers) {
      if (!writes(g.nodes[w]!.el).includes(name)) continue;
      const oursNew = pos[w]! < pos[c]!;
      const bad = turns.find((t) => turnOf.get(w)! < t !== oursNew);
      if (bad === undefined || reported.has(c)) continue;
      reported.add(c);
      const writer = g.nodes[w]!.el;
      const reader = g.nodes[pullers[bad]!]!.el;
      out.push({
        ...locate(pou, v, contact),
        rule: 'LD-X05',
        message: `${TOOLS} read ${describeElement(contact)} again for ${describeElement(reader)}, ${oursNew ? 'before' : 'after'} ${describeElement(writer)} writes it (their code generator re-traces every coil's path from the left rail); the simulator's iec profile reads it once, ${oursNew ? 'after' : 'before'} that write. Split the network so each coil's path has its own contacts, or move the coil that writes "${name}" below the others.`,
      });
    }
  }
}

const MAX_EXHAUSTIVE_VARIABLES = 10;

/**
 * For a network of contacts and coils only (no blocks, no edge elements), whether the engine's
 * order and ComputeProgram's (each coil's path re-read at its turn) leave every variable the same
 * for every value of the variables it uses; undefined when the network is not of that kind.
 */
function sameForAllValues(v: NetView): boolean | undefined {
  const { g, pos } = v;
  if (!pos) return undefined;
  const names = new Set<string>();
  for (const n of g.nodes) {
    const el = n.el;
    if (el.kind === 'contact' && (el.contact === 'P' || el.contact === 'N')) return undefined;
    if (el.kind === 'coil' && (el.coil === 'P' || el.coil === 'N')) return undefined;
    if (el.kind !== 'contact' && el.kind !== 'coil' && el.kind !== 'jump' && el.kind !== 'return') return undefined;
    for (const x of [...reads(el), ...writes(el)]) names.add(x);
  }
  if (names.size > MAX_EXHAUSTIVE_VARIABLES) return undefined;
  const list = [...names];
  const order = [...pos.keys()].sort((a, b) => pos[a]! - pos[b]!);
  const coils = g.nodes
    .map((n, i) => ({ i, key: pullerKey(n.el, STANDARD_LIBRARY) }))
    .filter((p) => g.nodes[p.i]!.el.kind === 'coil')
    .sort((a, b) => a.key[0] - b.key[0] || a.key[1] - b.key[1])
    .map((p) => p.i);
  const through = (el: LdElement, power: boolean, state: Map<string, boolean>): boolean => {
    if (el.kind !== 'contact') return power;
    if (el.contact === 'NOT') return !power;
    const x = state.get(up(el.variable)) ?? false;
    return power && (el.contact === 'NC' ? !x : x);
  };
  const write = (el: LdElement, power: boolean, state: Map<string, boolean>) => {
    if (el.kind !== 'coil' || !el.variable.trim()) return;
    const name = up(el.variable);
    if (el.coil === 'SET' || el.coil === 'SM') {
      if (power) state.set(name, true);
    } else if (el.coil === 'RESET' || el.coil === 'RM') {
      if (power) state.set(name, false);
    } else state.set(name, el.coil === 'NEG' ? !power : power);
  };
  const netPower = (net: number, out: (node: number) => boolean) =>
    drivers(g, net).leftRail || drivers(g, net).sources.some((s) => out(s.node));
  for (let mask = 0; mask < 1 << list.length; mask++) {
    const start = () => new Map(list.map((name, k) => [name, (mask & (1 << k)) !== 0]));
    // The engine: every element once, in its order.
    const ours = start();
    const outOf = new Map<number, boolean>();
    for (const i of order) {
      const node = g.nodes[i]!;
      const power = node.inputs.some((t) => netPower(t.net, (s) => outOf.get(s) ?? false));
      outOf.set(i, through(node.el, power, ours));
      write(node.el, power, ours);
    }
    // ComputeProgram: each coil in position order, its whole path read again at its turn.
    const theirs = start();
    for (const c of coils) {
      const seen = new Map<number, boolean>();
      const out = (i: number): boolean => {
        const known = seen.get(i);
        if (known !== undefined) return known;
        const node = g.nodes[i]!;
        const power = node.inputs.some((t) => netPower(t.net, out));
        const r = through(node.el, power, theirs);
        seen.set(i, r);
        return r;
      };
      const node = g.nodes[c]!;
      write(node.el, node.inputs.some((t) => netPower(t.net, out)), theirs);
    }
    for (const name of list) if (ours.get(name) !== theirs.get(name)) return false;
  }
  return true;
}

// ---- LD-X06, LD-X07: how GeneratePaths / FactorizePaths / ComputePaths write a path ----

/** A path as GeneratePaths builds it: null (the left rail), a text, a list (AND) or a tuple (OR). */
type GenPath = null | string | GenPath[] | { readonly or: readonly GenPath[] };

const pathKey = (p: GenPath): string => JSON.stringify(p);

/** FactorizePaths: paths that end in the same element share it (`(A OR B) AND X`). */
function factorize(paths: readonly GenPath[]): GenPath[] {
  const same = new Map<string, { path: GenPath[]; num: number }[]>();
  const left = new Set(paths.keys());
  const out: GenPath[] = [];
  paths.forEach((path, num) => {
    if (Array.isArray(path)) {
      if (path.length > 1) {
        const key = pathKey(path.slice(-1));
        same.set(key, [...(same.get(key) ?? []), { path: path.slice(0, -1), num }]);
      }
    } else {
      out.push(path);
      left.delete(num);
    }
  });
  for (const [key, elements] of same) {
    if (elements.length < 2) continue;
    const tail = JSON.parse(key) as GenPath[];
    const inner = factorize(elements.map((e) => e.path));
    out.push(inner.length > 1 ? [{ or: inner }, ...tail] : [...inner, ...tail]);
    for (const e of elements) left.delete(e.num);
  }
  for (const num of left) out.push(paths[num]!);
  return out;
}

/** ComputePaths as text (`first`: the top of an expression, an OR without brackets). */
function pathText(p: GenPath, first: boolean, text: (leaf: string) => string): string {
  if (p === null) return 'TRUE';
  if (typeof p === 'string') return text(p);
  if (Array.isArray(p)) return p.map((x) => pathText(x, false, text)).join(' AND ');
  if (p.or.includes(null)) return 'TRUE';
  const joined = p.or.map((x) => pathText(x, false, text)).join(' OR ');
  return first ? joined : `(${joined})`;
}

/** ComputeExpression: the paths of a pin's connections as one expression (a tuple when they stay several). */
function expressionOf(paths: readonly GenPath[]): GenPath | undefined {
  if (!paths.length) return undefined;
  if (paths.length === 1) return paths[0]!;
  const f = factorize(paths);
  return f.length > 1 ? { or: f } : f[0]!;
}

interface SlipNetwork {
  readonly v: NetView;
  readonly gg: GridGraph;
}

/** LD-X06 connector ORs pasted without brackets, LD-X07 coils in series after an OR join. */
function generatorSlips(pou: Pou, views: readonly NetView[], library: BlockLibrary, out: ExportWarning[]): void {
  const nets: SlipNetwork[] = views.map((v) => ({ v, gg: gridGraph(v.net, library) }));
  const srcs = (n: SlipNetwork, ei: number, pin = 'in'): readonly Source[] => n.gg.sources.get(ei)?.get(pin) ?? [];
  // Connectors by name (the export writes one body per POU: a continuation finds its connector by name).
  const connectors = new Map<string, { n: SlipNetwork; ei: number }>();
  for (const n of nets)
    n.v.net.elements.forEach((el, ei) => {
      if (el.kind === 'connector' && el.name.trim() && !connectors.has(up(el.name))) connectors.set(up(el.name), { n, ei });
    });
  const leafText = new Map<string, string>();
  const connectorExpr = new Map<string, GenPath | undefined>();
  // GeneratePaths over the exported connections (depth-bounded: a feedback wire is another rule's).
  const paths = (n: SlipNetwork, sources: readonly Source[], depth: number): GenPath[] => {
    const result: GenPath[] = [];
    if (depth > 64) return result;
    for (const s of sources) {
      if (s.kind === 'rail') {
        result.push(null);
        continue;
      }
      const el = n.v.net.elements[s.el]!;
      if (el.kind === 'contact') {
        const leaf = `${n.v.index}:${s.el}`;
        const name = el.variable.trim();
        leafText.set(leaf, el.contact === 'NC' ? `NOT(${name})` : el.contact === 'NOT' ? 'NOT' : name);
        const before = paths(n, srcs(n, s.el), depth + 1);
        if (before.length > 1) {
          const f = factorize(before);
          result.push(f.length > 1 ? [leaf, { or: f }] : [leaf, ...f]);
        } else if (before.length === 0) result.push(leaf);
        else if (Array.isArray(before[0])) result.push([leaf, ...before[0]]);
        else if (before[0] !== null) result.push([leaf, before[0]!]);
        else result.push(leaf);
      } else if (el.kind === 'coil') result.push(paths(n, srcs(n, s.el), depth + 1));
      else if (el.kind === 'continuation') {
        const leaf = `k:${up(el.name)}`;
        const c = connectors.get(up(el.name));
        if (c && !connectorExpr.has(leaf)) {
          connectorExpr.set(leaf, undefined);
          connectorExpr.set(leaf, expressionOf(paths(c.n, srcs(c.n, c.ei), depth + 1)));
        }
        result.push(leaf);
      } else if (el.kind === 'box') {
        const leaf = `${n.v.index}:${s.el}:${s.pin}`;
        leafText.set(leaf, `${el.instance?.trim() || el.blockType}.${s.pin}`);
        result.push(leaf);
      }
    }
    return result;
  };
  const text = (leaf: string): string => {
    if (leaf.startsWith('k:')) {
      const e = connectorExpr.get(leaf);
      return e === undefined ? leaf.slice(2) : pathText(e, true, text);
    }
    return leafText.get(leaf) ?? leaf;
  };
  /** A continuation whose connector's expression is an OR at its top: pasted without brackets. */
  const unbracketed = (p: GenPath): string | undefined => {
    if (typeof p !== 'string' || !p.startsWith('k:')) return undefined;
    const e = connectorExpr.get(p);
    return e !== null && e !== undefined && typeof e === 'object' && !Array.isArray(e) && !e.or.includes(null) ? p : undefined;
  };
  /** The first continuation pasted into an AND of two or more terms, anywhere in the path. */
  const pastedInAnd = (p: GenPath): string | undefined => {
    if (p === null || typeof p === 'string') return undefined;
    const kids = Array.isArray(p) ? p : p.or;
    if (Array.isArray(p) && p.length > 1) for (const k of p) if (unbracketed(k)) return unbracketed(k);
    for (const k of kids) {
      const hit = pastedInAnd(k);
      if (hit) return hit;
    }
    return undefined;
  };

  for (const n of nets) {
    const { v } = n;
    const reported = new Set<string>();
    v.net.elements.forEach((el, ei) => {
      if (el.kind !== 'coil') return;
      const expr = expressionOf(paths(n, srcs(n, ei), 0));
      if (expr === undefined) return;
      // LD-X06: the coil's expression pastes a connector's OR into an AND.
      const k = pastedInAnd(expr);
      if (k && !reported.has(k)) {
        reported.add(k);
        const name = k.slice(2);
        const conn = connectors.get(name)!;
        const cont = v.net.elements.find((x) => x.kind === 'continuation' && up(x.name) === name);
        out.push({
          ...locate(pou, v, cont ?? el),
          rule: 'LD-X06',
          message: `${TOOLS} paste the OR that reaches ${describeElement(conn.n.v.net.elements[conn.ei]!)} into what follows ${cont ? describeElement(cont) : `its continuation`} without brackets: they write ${describeElement(el)} as ${el.variable.trim() || '?'} := ${pathText(expr, true, text)}, where AND binds before OR (their code generator does not bracket a connector's expression), while the drawing means the whole OR in series. Draw the OR on the continuation's side, or write it to a coil and read that variable with a contact.`,
        });
      }
    });
    // LD-X07: a coil after an OR join that feeds another element.
    v.net.elements.forEach((el, ei) => {
      if (el.kind !== 'coil' || srcs(n, ei).length < 2) return;
      const next = v.net.elements.findIndex((_, xi) =>
        [...(n.gg.sources.get(xi)?.values() ?? [])].some((list) => list.some((s) => s.kind === 'pin' && s.el === ei)),
      );
      if (next < 0) return;
      const branches = paths(n, srcs(n, ei), 0).map((p) => pathText(p, false, text));
      out.push({
        ...locate(pou, v, el),
        rule: 'LD-X07',
        message: `${describeElement(el)} joins ${branches.length} branches (${branches.join(' OR ')}), and ${describeElement(v.net.elements[next]!)} follows it in series: ${TOOLS} give ${describeElement(v.net.elements[next]!)} the AND of those branches (${branches.join(' AND ')}), not their OR (their code generator passes on a coil's branches as one path). Join the branches after the coils instead (draw each coil on its own line from the join), or read the first coil's variable with a contact.`,
      });
    });
  }
}

/** Per POU and network, what behaves differently once Beremiz or OpenPLC compile the export. */
export function exportBehaviour(project: Project): ExportWarning[] {
  const library = blockLibrary(project);
  const out: ExportWarning[] = [];
  for (const pou of project.pous) {
    if (pou.language !== 'LD' || !pou.networks.length) continue;
    const views = pou.networks.map((n, i) => viewOf(n, i, library));
    dropped(pou, views, out);
    ordering(project, pou, views, library, out);
    generatorSlips(pou, views, library, out);
    if (project.profile === 'openplc') interleaved(pou, views, out);
  }
  // Profile openplc: the simulator already runs the project as Beremiz and OpenPLC do (LD-SEMANTICS.md
  // section 6), so the warnings stay (the export is the same) but say the simulation shows it.
  if (project.profile === 'openplc')
    for (const [k, w] of out.entries())
      out[k] = { ...w, message: `${w.message} ${SIMULATED_SO[w.rule]}` };
  return out.sort((a, b) =>
    a.pou === b.pou ? a.network - b.network || a.rule.localeCompare(b.rule) : 0,
  );
}

/** The project with a fix applied: its network replaced, its variables declared in the POU. */
export function applyExportFix(project: Project, fix: ExportFix): Project {
  return {
    ...project,
    pous: project.pous.map((p) =>
      p.id !== fix.pouId
        ? p
        : {
            ...p,
            variables: [...p.variables, ...fix.variables],
            networks: p.networks.map((n) => (n.id === fix.before.id ? fix.after : n)),
          },
    ),
  };
}
