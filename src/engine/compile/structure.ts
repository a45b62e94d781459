// Structural rules of one network (LD-SEMANTICS.md section 9): LD-R01 right-to-left flow,
// LD-R02 short circuit, LD-R03 open ends, LD-R04 coils at the right end, LD-R05 one jump,
// LD-R09 transition coils off the left rail, the wiring half of LD-R10.
// Returns false when the network cannot be ordered or executed (any error found here).
// LD-R02, LD-R03, LD-R04, LD-R09 and the one-power-line half of LD-R10 are vendor editor rules
// (002, 000): IEC 61131-3 and MATIEC accept such networks, so they are warnings and the network runs.
// Open ends run as Beremiz generates them: a path that leads nowhere is evaluated and its result
// unused; a left side fed by nothing is not energised; a coil fed by nothing is not executed.
import type { LdElement, VLink } from '../../model/elements';
import type { Network } from '../../model/project';
import type { GraphNode, Net, NetworkGraph } from './graph';
import { netIsUsed, upstream } from './graph';
import { cellName, describeElement, type Located, type Reporter } from './report';
import type { RuleId } from '../api';

const isCoil = (el: LdElement) => el.kind === 'coil';
const isTransitionCoil = (el: LdElement) => el.kind === 'coil' && (el.coil === 'P' || el.coil === 'N');

/** The pin that carries power flow into a box: EN for functions, the first BOOL input for FBs. */
export function powerInputPin(node: GraphNode): string | undefined {
  return node.layout?.inputs.find((p) => p.type === 'BOOL')?.name;
}
export function powerOutputPin(node: GraphNode): string | undefined {
  return node.layout?.outputs.find((p) => p.type === 'BOOL')?.name;
}

/** A finding of the structural rules, as reported (replayed on every reporter that checks the same graph). */
interface Finding {
  readonly severity: 'error' | 'warning';
  readonly rule: RuleId;
  readonly message: string;
  readonly at?: Located;
}

/** Collects findings instead of reporting them. */
class Findings {
  readonly list: Finding[] = [];
  errors = 0;
  error(rule: RuleId, message: string, at?: Located): void {
    this.errors++;
    this.list.push({ severity: 'error', rule, message, ...(at ? { at: located(at) } : {}) });
  }
  warning(rule: RuleId, message: string, at?: Located): void {
    this.list.push({ severity: 'warning', rule, message, ...(at ? { at: located(at) } : {}) });
  }
}

const located = (at: Located): Located => ({ row: at.row, col: at.col, ...(at.id !== undefined ? { id: at.id } : {}) });

/**
 * The findings per graph: a graph is built once per network object (graph.ts), and the rules read
 * only the network and its graph, so a network checked again (an unchanged network in the next
 * compile, a body lowered for every instance of its FB) gives the same findings without the work.
 */
const checked = new WeakMap<NetworkGraph, { readonly ok: boolean; readonly found: readonly Finding[] }>();

export function checkStructure(network: Network, g: NetworkGraph, r: Reporter): boolean {
  let memo = checked.get(g);
  if (!memo) {
    const findings = new Findings();
    const ok = checkRules(network, g, findings);
    memo = { ok, found: findings.list };
    checked.set(g, memo);
  }
  for (const f of memo.found) {
    if (f.severity === 'error') r.error(f.rule, f.message, f.at);
    else r.warning(f.rule, f.message, f.at);
  }
  return memo.ok;
}

function checkRules(network: Network, g: NetworkGraph, r: Findings): boolean {
  const before = r.errors;
  const width = g.cols + 1;
  const at = (p: number) => ({ row: Math.floor(p / width), col: Math.min(p % width, g.cols - 1) });

  for (const m of g.misplaced) {
    const el = network.elements[m.index]!;
    r.error('LD-E30', `${describeElement(el)} ${m.reason}`, el);
  }
  for (const i of g.badVlinks) {
    const v = network.vlinks[i]!;
    r.error('LD-E31', `the vertical link at row ${v.row + 1}, boundary ${v.boundary} lies outside the grid`, {
      row: v.row,
      col: v.boundary,
    });
  }

  // Wires attached to each point, to find dangling ends.
  const linkRight = new Int32Array(g.rows * width).fill(-1); // link element index starting at p
  const linkLeft = new Int32Array(g.rows * width).fill(-1); // link element index ending at p
  const vUp = new Int32Array(g.rows * width).fill(-1);
  const vDown = new Int32Array(g.rows * width).fill(-1);
  const terminals = new Uint8Array(g.rows * width);
  network.elements.forEach((el, i) => {
    if (el.kind !== 'link' || g.linkNet[i]! < 0) return;
    const p = el.row * width + el.col;
    linkRight[p] = i;
    linkLeft[p + 1] = i;
  });
  network.vlinks.forEach((v: VLink, i) => {
    if (g.vlinkNet[i]! < 0) return;
    const p = v.row * width + v.boundary;
    vDown[p] = i;
    vUp[p + width] = i;
  });
  for (const n of g.nodes)
    for (const t of [...n.inputs, ...n.outputs]) terminals[t.row * width + t.boundary] = 1;
  for (const [from, to] of g.connections) {
    terminals[from] = 1;
    for (const p of to) terminals[p] = 1;
  }

  // LD-R14: connectors and continuations pair up by name within the network.
  for (const u of g.unpaired) {
    const el = network.elements[u.index]!;
    if (u.severity === 'error') r.error('LD-R14', `${describeElement(el)} ${u.reason}`, el);
    else r.warning('LD-R14', `${describeElement(el)} ${u.reason}`, el);
  }

  // LD-R03 (002, warning): dangling wire ends. A line carries power or nothing; it changes no result.
  const reportedLinks = new Set<number>();
  for (let p = 0; p < g.rows * width; p++) {
    const b = p % width;
    if (b === 0 || b === g.cols || terminals[p]) continue;
    const wires = [linkRight[p], linkLeft[p], vUp[p], vDown[p]].filter((x) => x! >= 0).length;
    if (wires !== 1) continue;
    const { row } = at(p);
    if (linkLeft[p]! >= 0 || linkRight[p]! >= 0) {
      const i = linkLeft[p]! >= 0 ? linkLeft[p]! : linkRight[p]!;
      if (reportedLinks.has(i)) continue;
      reportedLinks.add(i);
      const el = network.elements[i]!;
      const side = linkLeft[p]! >= 0 ? 'right' : 'left';
      r.warning(
        'LD-R03',
        `the line at ${cellName(el.row, el.col)} ends in nothing on its ${side}; connect it or delete it`,
        el,
      );
    } else {
      const v = vUp[p]! >= 0 ? vUp[p]! : vDown[p]!;
      r.warning(
        'LD-R03',
        `the vertical line at ${cellName(row, b)} ends in nothing; connect it to a line or an element`,
        {
          row: network.vlinks[v]!.row,
          col: Math.max(0, b - 1),
        },
      );
    }
  }

  for (const net of g.nets) {
    if (!netIsUsed(net)) continue;
    const hasSource = upstream(g, net.id).fed;
    const hasSink = net.rightRail || net.sinks.length > 0 || net.feedsOut.length > 0;
    const nodeOf = (i: number) => g.nodes[i]!;
    // LD-R01: a line fed by nothing on its left that joins, further right, a line that is fed:
    // drawn as if power came back to it from the right, which a one-way vertical link never does.
    if (!hasSource && (net.sinks.length || net.rightRail) && fedOnItsRight(g, net)) {
      const bridge = net.feedsOut[0] ?? net.feeds[0];
      const via = bridge !== undefined ? network.elements[g.bridges[bridge]!.via]! : { row: Math.floor(net.points[0]! / (g.cols + 1)) };
      for (const s of net.sinks)
        r.error(
          'LD-R01',
          `${describeElement(nodeOf(s.node).el)} is fed from its right: power would flow right to left through the branch at row ${via.row + 1}; redraw the branch so it runs left to right`,
          nodeOf(s.node).el,
        );
      if (!net.sinks.length)
        r.error(
          'LD-R01',
          `the line reaching the right rail at row ${via.row + 1} carries power right to left; redraw the branch so it runs left to right`,
          { row: via.row, col: g.cols - 1 },
        );
      continue;
    }
    // LD-R03 (002, warning): element sides left open. Beremiz generates code from coils and blocks
    // backwards: a contact whose right side leads nowhere is never read, a coil with nothing on its
    // left gets no assignment, a block input with no connection is left out of the call.
    if (!hasSource) {
      for (const s of net.sinks) {
        const n = nodeOf(s.node);
        if (n.el.kind === 'box') {
          if (net.links.length || net.vlinks.length)
            r.warning(
              'LD-R03',
              `input ${s.pin} of ${describeElement(n.el)} is wired to a line that starts nowhere (the input counts as unconnected); connect the line on its left`,
              n.el,
            );
        } else if (n.el.kind === 'coil')
          r.warning(
            'LD-R03',
            `${describeElement(n.el)} has an open left side: it is never executed and its variable keeps its value; connect it to the left rail or to an element on its left`,
            n.el,
          );
        else
          r.warning(
            'LD-R03',
            `${describeElement(n.el)} has an open left side: it is never energised; connect it to the left rail or to an element on its left`,
            n.el,
          );
      }
    }
    if (!hasSink) {
      for (const s of net.sources) {
        const n = nodeOf(s.node);
        if (n.el.kind === 'contact')
          r.warning(
            'LD-R03',
            `${describeElement(n.el)} has an open right side: its result goes nowhere; connect it to a coil, a block input or the right rail`,
            n.el,
          );
      }
    }
    if (!hasSource || !hasSink) continue;

    // LD-R02 short circuit; LD-R09 transition coils on the left rail.
    const coilSinks = net.sinks.filter((s) => isCoil(nodeOf(s.node).el));
    if (net.leftRail && net.rightRail) {
      const railPoint = net.points.find((p) => p % width === g.cols)!;
      r.warning(
        'LD-R02',
        `short circuit: a bare line joins the left rail to the right rail at row ${Math.floor(railPoint / width) + 1}; it does nothing (put a contact or coil on it, or delete it)`,
        at(railPoint),
      );
    }
    if (net.leftRail) {
      for (const s of coilSinks) {
        const el = nodeOf(s.node).el;
        if (isTransitionCoil(el))
          r.warning(
            'LD-R09',
            `${describeElement(el)} is connected directly to the left rail: it is ON in the first scan only; put a condition before it`,
            el,
          );
        else
          r.warning(
            'LD-R02',
            `${describeElement(el)} is connected to the left rail by a bare line, so it is always energised (legal IEC; some editors call it a short circuit)`,
            el,
          );
      }
    }
    if (net.rightRail && !net.leftRail) {
      for (const s of net.sinks) {
        const el = nodeOf(s.node).el;
        r.warning(
          'LD-R02',
          `a bare line to the right rail bypasses ${describeElement(el)} (it still runs; the right rail carries no state); remove the line or put an element on it`,
          el,
        );
      }
    }
    // LD-R04 (002, warning): after a coil only further coils or the right rail. IEC table 62: a coil
    // passes its left state to its right link, so whatever follows runs with that state.
    if (net.sources.some((s) => isCoil(nodeOf(s.node).el))) {
      const coilSource = nodeOf(net.sources.find((s) => isCoil(nodeOf(s.node).el))!.node).el;
      for (const s of net.sinks) {
        const el = nodeOf(s.node).el;
        if (!isCoil(el))
          r.warning(
            'LD-R04',
            `${describeElement(el)} stands after ${describeElement(coilSource)}; it runs with the coil's left state (IEC), but some editors allow only coils after a coil`,
            el,
          );
      }
    }
  }

  // LD-R05: at most one jump per network.
  const jumps = g.nodes.filter((n) => n.el.kind === 'jump');
  for (const extra of jumps.slice(1))
    r.error(
      'LD-R05',
      `${describeElement(extra.el)} is a second jump in this network; a network holds at most one jump`,
      extra.el,
    );

  // LD-R10 (wiring, 000, warning): one power-flow line into a box. IEC and MATIEC evaluate the line
  // once and give its state to both pins.
  for (const n of g.nodes) {
    if (n.el.kind !== 'box' || !n.layout) continue;
    const power = powerInputPin(n);
    const powerNet = n.inputs.find((t) => t.pin === power)?.net;
    if (powerNet === undefined) continue;
    for (const t of n.inputs) {
      if (t.pin === power || t.net !== powerNet) continue;
      r.warning(
        'LD-R10',
        `the power flow enters ${describeElement(n.el)} twice: ${power} and ${t.pin} share one line (both get its state); some editors refuse this`,
        n.el,
      );
    }
  }
  return r.errors === before;
}

/**
 * LD-R01: true when a net fed by nothing bridges into a net that is fed (graph.ts, wires.ts): its
 * wire carries power only if power ran right to left, which the language forbids (section 1).
 */
function fedOnItsRight(g: NetworkGraph, net: Net): boolean {
  const seen = new Set<number>([net.id]);
  const stack = [net.id];
  while (stack.length) {
    const n = g.nets[stack.pop()!]!;
    if (n.id !== net.id && upstream(g, n.id).fed) return true;
    for (const b of [...n.feeds, ...n.feedsOut]) {
      const { from, to } = g.bridges[b]!;
      for (const m of [from, to])
        if (!seen.has(m)) {
          seen.add(m);
          stack.push(m);
        }
    }
  }
  return false;
}
