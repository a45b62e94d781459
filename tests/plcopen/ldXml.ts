// A tiny PLCopen LD writer for tests: a graph (what feeds what) as a TC6 v2.01 document, in the
// compact style of CODESYS (no route points). Positions are optional (x, y hints; 0,0 otherwise).
// `graphOf` gives back the same graph from an imported project, drawn as the engine compiles it.

import { buildGraph, upstream } from '../../src/engine/compile/graph';
import type { Project } from '../../src/model/project';

/** A wire into a pin: the rail, an element's output (`id` or `id.PIN` for a block), or a variable (`=Name`). */
export type Ref = string;

export type LdObj =
  | { id: number; kind: 'contact'; v: string; neg?: boolean; edge?: 'rising' | 'falling'; in: Ref[] }
  | { id: number; kind: 'coil'; v: string; neg?: boolean; storage?: 'set' | 'reset'; in: Ref[] }
  | {
      id: number;
      kind: 'block';
      type: string;
      instance?: string;
      inputs: Record<string, Ref[]>;
      outputs: string[];
      /** Output pins assigned to a variable (an outVariable wired from the pin). */
      assign?: Record<string, string>;
      /** The block's executionOrderId, and those of the outVariables of `assign` (by pin). */
      order?: number;
      assignOrder?: Record<string, number>;
    }
  /** A PLCopen connector: ends the wire `in` under a name. */
  | { id: number; kind: 'connector'; name: string; in: Ref[] }
  /** A PLCopen continuation: starts a wire with the connector of its name (refer to it by id). */
  | { id: number; kind: 'continuation'; name: string };

export interface LdNetwork {
  readonly objects: LdObj[];
  /** Objects (ids) whose output goes to the right rail. */
  readonly toRail?: number[];
  /** Position hints per object id (x, y); absent objects sit at 0,0. */
  readonly pos?: Record<number, { x: number; y: number }>;
}

export interface LdVar {
  name: string;
  type: string;
  address?: string;
}

const esc = (s: string) => s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/"/g, '&quot;');

/** The connection elements of one input: variables and literals become inVariables (made here). */
function connections(refs: Ref[], rail: number, extra: string[], nextId: () => number): string {
  let out = '';
  for (const r of refs) {
    if (r === 'rail') out += `<connection refLocalId="${rail}"/>`;
    else if (r.startsWith('=')) {
      const id = nextId();
      extra.push(
        `<inVariable localId="${id}"><position x="0" y="0"/><connectionPointOut/><expression>${esc(r.slice(1))}</expression></inVariable>`,
      );
      out += `<connection refLocalId="${id}"/>`;
    } else {
      const [id, pin] = r.split('.');
      out += pin
        ? `<connection refLocalId="${id}" formalParameter="${pin}"/>`
        : `<connection refLocalId="${id}"/>`;
    }
  }
  return `<connectionPointIn>${out}</connectionPointIn>`;
}

/** A one-POU project (program "Main") whose LD body holds these networks (one rail pair each). */
export function ldXml(vars: readonly LdVar[], networks: readonly LdNetwork[]): string {
  let body = '';
  let next = 100000;
  const nextId = () => next++;
  networks.forEach((net, k) => {
    const rail = 90000 + k * 2;
    const pos = (id: number) => {
      const p = net.pos?.[id] ?? { x: 0, y: 0 };
      return `<position x="${p.x}" y="${p.y}"/>`;
    };
    const extra: string[] = [];
    const railPos = net.pos
      ? `<position x="0" y="${Math.min(...Object.values(net.pos).map((p) => p.y))}"/>`
      : '<position x="0" y="0"/>';
    body += `<leftPowerRail localId="${rail}">${railPos}<connectionPointOut formalParameter=""/></leftPowerRail>\n`;
    for (const o of net.objects) {
      switch (o.kind) {
        case 'contact':
          body += `<contact localId="${o.id}" negated="${o.neg ? 'true' : 'false'}"${o.edge ? ` edge="${o.edge}"` : ''}>${pos(o.id)}${connections(o.in, rail, extra, nextId)}<connectionPointOut/><variable>${esc(o.v)}</variable></contact>\n`;
          break;
        case 'coil':
          body += `<coil localId="${o.id}" negated="${o.neg ? 'true' : 'false'}"${o.storage ? ` storage="${o.storage}"` : ''}>${pos(o.id)}${connections(o.in, rail, extra, nextId)}<connectionPointOut/><variable>${esc(o.v)}</variable></coil>\n`;
          break;
        case 'block': {
          let ins = '';
          for (const [pin, refs] of Object.entries(o.inputs))
            ins += `<variable formalParameter="${pin}">${connections(refs, rail, extra, nextId)}</variable>`;
          let outs = '';
          for (const pin of o.outputs)
            outs += `<variable formalParameter="${pin}"><connectionPointOut/></variable>`;
          body += `<block localId="${o.id}" typeName="${o.type}"${o.instance ? ` instanceName="${o.instance}"` : ''}${o.order ? ` executionOrderId="${o.order}"` : ''}>${pos(o.id)}<inputVariables>${ins}</inputVariables><inOutVariables/><outputVariables>${outs}</outputVariables></block>\n`;
          for (const [pin, v] of Object.entries(o.assign ?? {}))
            extra.push(
              `<outVariable localId="${nextId()}"${o.assignOrder?.[pin] ? ` executionOrderId="${o.assignOrder[pin]}"` : ''}><position x="0" y="0"/><connectionPointIn><connection refLocalId="${o.id}" formalParameter="${pin}"/></connectionPointIn><expression>${esc(v)}</expression></outVariable>`,
            );
          break;
        }
        case 'connector':
          body += `<connector localId="${o.id}" name="${esc(o.name)}">${pos(o.id)}${connections(o.in, rail, extra, nextId)}</connector>\n`;
          break;
        case 'continuation':
          body += `<continuation localId="${o.id}" name="${esc(o.name)}">${pos(o.id)}<connectionPointOut/></continuation>\n`;
          break;
      }
    }
    for (const e of extra) body += e + '\n';
    if (net.toRail?.length)
      body += `<rightPowerRail localId="${rail + 1}"><position x="0" y="0"/>${net.toRail
        .map((id) => `<connectionPointIn><connection refLocalId="${id}"/></connectionPointIn>`)
        .join('')}</rightPowerRail>\n`;
  });
  const decl = vars
    .map(
      (v) =>
        `<variable name="${v.name}"${v.address ? ` address="${v.address}"` : ''}><type>${/^[A-Z]+$/.test(v.type) && !['TON', 'TOF', 'TP', 'CTU', 'CTD', 'CTUD', 'R_TRIG', 'F_TRIG', 'SR', 'RS'].includes(v.type) ? `<${v.type}/>` : `<derived name="${v.type}"/>`}</type></variable>`,
    )
    .join('\n');
  return `<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="Rungsmith tests" productName="ldXml" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="ldXml"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous><pou name="Main" pouType="program">
<interface><localVars>
${decl}
</localVars></interface>
<body><LD>
${body}</LD></body>
</pou></pous></types>
  <instances><configurations/></instances>
</project>
`;
}

/** Describes an element of a compiled grid the way `graphOf` names it. */
type Named = { kind: string; name: string };

/**
 * The graph the engine compiles from every network of a POU: one line per wire,
 * "consumer.pin <- producer.pin" (producer "rail" for the left rail; "-> rail" lines for nets that
 * reach the right rail), sorted. Elements are named by kind and variable/instance, with a counter
 * for repeats in file order of the grid (contacts drawn twice by the import share a name).
 */
export function graphOf(project: Project, pou = 'Main'): string[] {
  const p = project.pous.find((x) => x.name === pou)!;
  const out: string[] = [];
  for (const net of p.networks) {
    const g = buildGraph(net);
    const name = (node: number): Named => {
      const el = g.nodes[node]!.el;
      switch (el.kind) {
        case 'contact':
          return { kind: 'contact', name: `${el.contact}:${el.variable}` };
        case 'coil':
          return { kind: 'coil', name: `${el.coil}:${el.variable}` };
        case 'box':
          return { kind: 'box', name: `${el.blockType}:${el.instance ?? ''}` };
        default:
          return { kind: el.kind, name: '' };
      }
    };
    const label = (node: number) => {
      const n = name(node);
      return `${n.kind}:${n.name}`;
    };
    for (const n of g.nets) {
      // What drives the net, through one-way bridges too (a fan-out into two different ORs).
      const up = upstream(g, n.id);
      const srcs = up.sources.map((s) => `${label(s.node)}.${s.pin}`);
      if (up.leftRail) srcs.push('rail');
      for (const s of n.sinks) for (const src of srcs) out.push(`${label(s.node)}.${s.pin} <- ${src}`);
    }
  }
  return out.sort();
}

/** The graph of a generated body in `graphOf`'s terms: what the import must draw. */
export function specGraph(networks: readonly LdNetwork[]): string[] {
  const out: string[] = [];
  for (const net of networks) {
    const byId = new Map(net.objects.map((o) => [o.id, o]));
    const label = (o: LdObj): string => {
      switch (o.kind) {
        case 'contact':
          return `contact:${o.edge === 'rising' ? 'P' : o.edge === 'falling' ? 'N' : o.neg ? 'NC' : 'NO'}:${o.v}`;
        case 'coil':
          return `coil:${o.storage === 'set' ? 'SET' : o.storage === 'reset' ? 'RESET' : o.neg ? 'NEG' : 'COIL'}:${o.v}`;
        case 'block':
          return `box:${o.type}:${o.instance ?? ''}`;
        default:
          return o.kind;
      }
    };
    const add = (consumer: string, refs: Ref[]) => {
      for (const r of refs) {
        if (r.startsWith('=')) continue;
        if (r === 'rail') out.push(`${consumer} <- rail`);
        else {
          const [id, pin] = r.split('.');
          const src = byId.get(Number(id))!;
          if (src.kind === 'continuation') {
            // A continuation carries what its connector is wired to (one way).
            const conn = net.objects.find((x) => x.kind === 'connector' && x.name.toUpperCase() === src.name.toUpperCase());
            if (conn && conn.kind === 'connector') add(consumer, conn.in);
          } else out.push(`${consumer} <- ${label(src)}.${pin ?? 'OUT'}`);
        }
      }
    };
    for (const o of net.objects) {
      if (o.kind === 'connector' || o.kind === 'continuation') continue;
      if (o.kind === 'block')
        for (const [pin, refs] of Object.entries(o.inputs)) add(`${label(o)}.${pin}`, refs);
      else add(`${label(o)}.IN`, o.in);
    }
  }
  return out.sort();
}
