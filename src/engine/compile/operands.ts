// The operands of contacts, coils and jumps (LD-R07, LD-R08, LD-R13, LD-E22): the variable a contact
// reads, the variable a coil writes, a jump's target network, edge memories, a contact's operation,
// and an access described in words for messages (accessWords). Used by lower.ts (iec order) and
// generated.ts (openplc order); accessWords also by boxPins.ts and userCall.ts.
import type { CoilElement, ContactElement, JumpElement } from '../../model/elements';
import type { CoilFamily, PouContext } from './context';
import type { Op } from './ir';
import { describeElement, type Reporter } from './report';
import type { Access } from './symbols';

const FAMILY: Record<CoilElement['coil'], CoilFamily> = {
  COIL: 'assign',
  M: 'assign',
  NEG: 'negated',
  P: 'pulse',
  N: 'pulse',
  SET: 'latch',
  RESET: 'latch',
  SM: 'latch',
  RM: 'latch',
};

/** The network a jump goes to (LD-R07: its label exists); `back`: warn when it jumps back (LD-W03). */
export function jumpTarget(ctx: PouContext, el: JumpElement, index: number, r: Reporter, back = true): number | undefined {
  const target = ctx.labels.get(el.target.trim().toUpperCase());
  if (el.target.trim() === '')
    r.error(
      'LD-R07',
      `${describeElement(el)} names no label; write the label of the network to continue at`,
      el,
    );
  else if (target === undefined)
    r.error(
      'LD-R07',
      `${describeElement(el)} has no target: no network of ${ctx.pouName} is labelled "${el.target}"`,
      el,
    );
  // LD-W03: a jump back (to its own network or an earlier one) runs those networks again in
  // the same scan, looping until its condition goes FALSE (the watchdog stops an endless one).
  else if (back && target - ctx.first <= index)
    r.warning(
      'LD-W03',
      `${describeElement(el)} jumps back to network ${target - ctx.first + 1} ("${el.target.trim()}"): legal, but networks ${target - ctx.first + 1} to ${index + 1} run again in the same scan until the jump's condition goes FALSE; make sure it does, or the watchdog stops the PLC`,
      el,
    );
  return target;
}

/** A contact's operation (`ownNet`: its own result where other outputs join its right side). */
export function contactOp(
  node: number,
  contact: ContactElement['contact'],
  src: Access | undefined,
  inNet: number,
  outNet: number,
  ownNet: number | undefined,
  edge: number | undefined,
): Op {
  return {
    op: 'contact',
    node,
    contact,
    ...(src ? { src } : {}),
    inNet,
    outNet,
    ...(ownNet !== undefined ? { ownNet } : {}),
    ...(edge !== undefined ? { edge } : {}),
  };
}

/** The edge memory of a |P| |N| contact or (P) (N) coil; a FUNCTION has none to keep (LD-E22). */
export function edgeOf(ctx: PouContext, el: ContactElement | CoilElement, network: number, r: Reporter, trace = 0): number {
  if (ctx.pouKind === 'FUNCTION' && trace === 0)
    r.error(
      'LD-E22',
      `${describeElement(el)} detects an edge, which a FUNCTION cannot: a function keeps nothing between calls, so the memory of the previous value would be lost; use a FUNCTION_BLOCK`,
      el,
    );
  return ctx.edges.allocate(el, ctx.pouName, network, ctx.instance, trace);
}

export function contactOperand(ctx: PouContext, el: ContactElement, r: Reporter): Access | undefined {
  const edge = el.contact === 'P' || el.contact === 'N';
  if (el.variable.trim() === '') {
    r.error('LD-R08', `${describeElement(el)} names no variable; write a BOOL variable on it`, el);
    return undefined;
  }
  const res = ctx.symbols.resolve(el.variable, {
    expected: 'BOOL',
    literals: !edge,
    implicitLocations: true,
  });
  if (!res.ok) {
    const constant = /constant/.test(res.message) || /^(TRUE|FALSE)$/i.test(el.variable.trim());
    r.error(
      'LD-R08',
      edge && constant
        ? `${describeElement(el)} names a constant; a transition contact needs a BOOL variable`
        : `${describeElement(el)}: ${res.message}`,
      el,
    );
    return undefined;
  }
  if (res.access.type !== 'BOOL') {
    r.error(
      'LD-R08',
      `${describeElement(el)} names ${res.access.type} ${accessWords(res.access)}; a contact needs a BOOL variable, an FB's BOOL pin or a bit like Word.3`,
      el,
    );
    return undefined;
  }
  return res.access;
}

export function coilOperand(ctx: PouContext, el: CoilElement, network: number, r: Reporter): Access | undefined {
  if (el.variable.trim() === '') {
    r.error('LD-R08', `${describeElement(el)} names no variable; write a BOOL variable on it`, el);
    return undefined;
  }
  const res = ctx.symbols.resolve(el.variable, {
    expected: 'BOOL',
    literals: false,
    implicitLocations: true,
  });
  if (!res.ok) {
    r.error(
      'LD-R08',
      `${describeElement(el)}: ${res.message}${/constant/.test(res.message) ? '; a coil must write a BOOL variable' : ''}`,
      el,
    );
    return undefined;
  }
  const a = res.access;
  if (a.type !== 'BOOL') {
    r.error(
      'LD-R08',
      `${describeElement(el)} names ${a.type} ${accessWords(a)}; a coil needs a BOOL variable, an FB's BOOL input or a bit like Word.3`,
      el,
    );
    return undefined;
  }
  if (a.kind === 'pin' && a.dir === 'out') {
    r.error(
      'LD-R08',
      `${describeElement(el)} writes the output ${a.fb.name}.${a.pin}, which only the block itself sets`,
      el,
    );
    return undefined;
  }
  if ((a.kind === 'var' || a.kind === 'bit') && a.v.constant) {
    r.error('LD-R08', `${describeElement(el)} writes "${a.v.name}", which is declared CONSTANT`, el);
    return undefined;
  }
  if (a.kind === 'var' || a.kind === 'bit') {
    const v = a.v;
    if (v.location?.area === 'I')
      r.warning(
        'LD-R13',
        `${describeElement(el)} writes the input ${v.locationText}; the next input read overwrites it`,
        el,
      );
    if (el.coil === 'M' || el.coil === 'SM' || el.coil === 'RM') ctx.retentiveCoilVars.add(v);
    if (a.kind === 'var') {
      let families = ctx.coilWrites.get(v);
      if (!families) ctx.coilWrites.set(v, (families = new Map()));
      if (!families.has(FAMILY[el.coil]))
        families.set(FAMILY[el.coil], { network, row: el.row, col: el.col });
    }
  }
  return a;
}

export function accessWords(a: Access): string {
  switch (a.kind) {
    case 'var':
      return `"${a.v.name}"`;
    case 'bit':
      return `bit ${a.bit} of "${a.v.name}"`;
    case 'pin':
      return `"${a.fb.name}.${a.pin}"`;
    case 'const':
      return `constant ${a.text}`;
    case 'elem':
      return `"${a.text}"`;
  }
}
