// Checking a laid-out network against the file: the sources of every input pin drawn on the grid
// must be those wired in the file; where they differ the import says so.
import type { LdElement } from '../model/elements';
import { gridGraph, type Source } from './gridGraph';
import type { LaidOut } from './layoutShapes';
import type { Finding, GNode, GSource } from './ldGraph';

const describe = (n: GNode): string => {
  switch (n.kind) {
    case 'contact':
      return n.contact === 'NOT' ? 'NOT contact' : `contact "${n.variable}"`;
    case 'coil':
      return `coil "${n.variable}"`;
    case 'box':
      return `block ${n.instance ?? n.blockType}`;
    case 'jump':
      return `jump to ${n.target}`;
    case 'return':
      return 'return';
  }
};

/** Checks that the grid draws exactly the wiring of the file; reports elements whose inputs differ. */
export function verify(
  nodes: readonly GNode[],
  members: readonly number[],
  laid: LaidOut,
): { node: number; pin: string }[] {
  const g = gridGraph(laid);
  const indexOfElement = new Map<string, number>();
  laid.elements.forEach((e: LdElement, i) => indexOfElement.set(e.id, i));
  const nodeOfElement = new Map<number, number>();
  for (const i of members) {
    const id = laid.elementOf.get(i);
    if (id) nodeOfElement.set(indexOfElement.get(id)!, i);
  }
  const memberSet = new Set(members);
  const out: { node: number; pin: string }[] = [];
  for (const i of members) {
    const n = nodes[i]!;
    const ei = indexOfElement.get(laid.elementOf.get(i)!);
    if (ei === undefined) continue;
    const drawn = g.sources.get(ei);
    // The pins wired in the file, then those only drawn; the first that differs is reported.
    let bad: string | undefined;
    for (const pin of n.inputs.keys())
      if (pinDiffers(n, pin, drawn, memberSet, nodeOfElement)) {
        bad = pin;
        break;
      }
    if (bad === undefined && drawn)
      for (const pin of drawn.keys())
        if (!n.inputs.has(pin) && pinDiffers(n, pin, drawn, memberSet, nodeOfElement)) {
          bad = pin;
          break;
        }
    if (bad !== undefined) out.push({ node: i, pin: bad });
  }
  return out;
}

/** The finding for a node whose drawn wiring differs from the file. */
export function mismatchFinding(n: GNode, pin: string): Finding {
  return {
    message: `${describe(n)}${pin === 'in' || pin === 'out' ? '' : ` pin ${pin}`}: this wiring cannot be drawn exactly on the ladder grid; check its connections`,
    obj: n.obj,
  };
}

/** Whether the sources of a pin in the file (within the network) differ from those the grid draws. */
function pinDiffers(
  n: GNode,
  pin: string,
  drawn: Map<string, Source[]> | undefined,
  memberSet: ReadonlySet<number>,
  nodeOfElement: ReadonlyMap<number, number>,
): boolean {
  const wantList = (n.inputs.get(pin) ?? []).filter((s) => s.kind === 'rail' || memberSet.has(s.node));
  const gotList = drawn?.get(pin) ?? [];
  // One source each (most pins): compare directly, without building keys or sets.
  if (wantList.length === 1 && gotList.length === 1) {
    const want = wantList[0]!;
    const got = gotList[0]!;
    if (want.kind === 'rail' || got.kind === 'rail') return want.kind !== got.kind;
    return want.node !== nodeOfElement.get(got.el) || want.pin !== got.pin;
  }
  const key = (s: Source | GSource): string => {
    if (s.kind === 'rail') return 'rail';
    if (s.kind === 'pin') return `${nodeOfElement.get(s.el)}:${s.pin}`;
    return `${s.node}:${s.pin}`;
  };
  return !sameSet(new Set(wantList.map(key)), new Set(gotList.map(key)));
}

function sameSet(a: ReadonlySet<string>, b: ReadonlySet<string>): boolean {
  if (a.size !== b.size) return false;
  for (const k of a) if (!b.has(k)) return false;
  return true;
}
