// The chart of an SFC body, read from PLCopen XML in the order MATIEC compiles it. Beremiz's
// generator (PLCGenerator.py) writes a PLCopen chart as IEC SFC text: one pass over the body's
// elements registers steps, transitions and action blocks (walking back from each step and jump
// through convergences and divergences), then the text is written from each initial step: the
// step, its actions, its transitions and, depth first, the steps they lead to. MATIEC tests the
// transitions, associates actions and runs action bodies in that text order, so the chart keeps it.
// LD and FBD pieces (action bodies, transition bodies, graphics wired to a condition) are read
// with the LD importer; blocks in conditions run in a COMPUTE_FUNCTION_BLOCKS action stored on the
// first initial step, as Beremiz generates it, and the condition reads what they gave. A feedback
// wire in a condition reads the FB output's value of the previous call, as MATIEC's depth-first
// order does; the pieces' import findings are reported through `warn`.
import type { BlockLibrary } from '../model/library';
import type { Network, SfcAction, SfcAssociation, SfcChart, SfcCode, SfcStep, SfcTransition } from '../model/project';
import { importLdBody } from './importBody';
import { LdGraphError } from './ldGraph';
import { child, childrenNamed, deepText, parseXml, type XmlElement } from './xml/parse';

/** The action Beremiz adds for blocks wired to conditions. */
export const COMPUTE_FUNCTION_BLOCKS = 'COMPUTE_FUNCTION_BLOCKS';

interface StepInfo {
  name: string;
  initial: boolean;
  localId: number;
  transitions: XmlElement[];
  associations: SfcAssociation[];
}
interface TransitionInfo {
  el: XmlElement;
  from: string[];
  to: string[];
  priority?: number;
  condition: SfcCode;
}

const num = (s: string | undefined): number | undefined => (s !== undefined && s !== '' ? Number(s) : undefined);

/** Reads the chart of `pouEl` (its body's `<SFC>`, `<actions>` and `<transitions>`). */
export function readSfcChart(pouEl: XmlElement, sfc: XmlElement, library: BlockLibrary, warn: (message: string) => void = () => {}): SfcChart {
  const byId = new Map<number, XmlElement>();
  for (const el of sfc.children) {
    const id = num(el.attrs.localId);
    if (id !== undefined) byId.set(id, el);
  }
  const declaredActions = new Map<string, XmlElement>();
  for (const a of childrenNamed(child(pouEl, 'actions') ?? pouEl, 'action'))
    declaredActions.set((a.attrs.name ?? '').toUpperCase(), a);
  const declaredTransitions = new Map<string, XmlElement>();
  for (const t of childrenNamed(child(pouEl, 'transitions') ?? pouEl, 'transition'))
    declaredTransitions.set((t.attrs.name ?? '').toUpperCase(), t);

  const steps = new Map<string, StepInfo>();
  const initialSteps: string[] = [];
  const transitions = new Map<XmlElement, TransitionInfo>();
  const actions = new Map<string, SfcAction>();
  const computed: Network[] = [];
  const locals: string[] = [];
  let inlineCount = 0;

  const inputsOf = (el: XmlElement): XmlElement[] => {
    const out: XmlElement[] = [];
    for (const cpi of childrenNamed(el, 'connectionPointIn'))
      for (const c of childrenNamed(cpi, 'connection')) {
        const hit = byId.get(num(c.attrs.refLocalId) ?? -1);
        if (hit) out.push(hit);
      }
    return out;
  };
  /** The single element wired to `el`'s input. */
  const inputOf = (el: XmlElement): XmlElement | undefined => {
    const cpi = child(el, 'connectionPointIn');
    const cs = cpi ? childrenNamed(cpi, 'connection') : [];
    return cs.length === 1 ? byId.get(num(cs[0]!.attrs.refLocalId) ?? -1) : undefined;
  };
  /** Transitions leading into a step or jump (through a selection convergence or simultaneous divergence). */
  const transitionsInto = (el: XmlElement): XmlElement[] => {
    const src = inputOf(el);
    if (!src) return [];
    if (src.name === 'transition') return [src];
    if (src.name === 'selectionConvergence') return inputsOf(src);
    if (src.name === 'simultaneousDivergence') {
      const t = inputOf(src);
      if (!t) return [];
      if (t.name === 'transition') return [t];
      if (t.name === 'selectionConvergence') return inputsOf(t);
    }
    return [];
  };

  const importPiece = (xml: string, from: string): Network[] | string => {
    try {
      const body = parseXml(xml);
      const { networks } = importLdBody(body, (e) => e.doc.src.slice(e.offset, e.end), (f) => warn(`${from}: ${f.message}`), library);
      return networks;
    } catch (e) {
      if (e instanceof LdGraphError) return `${from}: ${e.message}`;
      return `${from} cannot be read: ${(e as Error).message}`;
    }
  };
  const rawOf = (el: XmlElement) => el.doc.src.slice(el.offset, el.end);

  /** A graphical network wired to a condition, as a body writing `result`. */
  const graphicCondition = (
    connections: XmlElement,
    elementsById: Map<number, XmlElement>,
    result: string,
    from: string,
  ): { networks: Network[] | string; blocks: boolean } => {
    // Depth first from the condition, as MATIEC orders the blocks. A wire back to an element still
    // being visited (a feedback loop: TON3.IN from SR0, SR0.R from TON3.Q) carries the value of the
    // previous call: it becomes a read of the FB instance's output, which holds exactly that value.
    const seen = new Set<XmlElement>();
    const open = new Set<XmlElement>();
    const feedback: { consumer: XmlElement; wire: XmlElement; source: XmlElement }[] = [];
    const visit = (el: XmlElement) => {
      if (seen.has(el)) return;
      seen.add(el);
      open.add(el);
      const ins: XmlElement[] = [];
      const gather = (e: XmlElement) => {
        for (const c of e.children) {
          if (c.name === 'connection') {
            const hit = elementsById.get(num(c.attrs.refLocalId) ?? -1);
            if (hit && open.has(hit)) feedback.push({ consumer: el, wire: c, source: hit });
            else if (hit) ins.push(hit);
          } else if (c.name !== 'connectionPointOut') gather(c);
        }
      };
      gather(el);
      ins.forEach(visit);
      open.delete(el);
    };
    const wires = childrenNamed(connections, 'connection');
    for (const w of wires) {
      const hit = elementsById.get(num(w.attrs.refLocalId) ?? -1);
      if (hit) visit(hit);
    }
    const parts = [...seen];
    const replaced = new Map<XmlElement, { wire: XmlElement; text: string }[]>();
    let nextId = 2_000_000;
    for (const f of feedback) {
      const instance = f.source.attrs.instanceName;
      const pin = f.wire.attrs.formalParameter;
      const wireName = `${f.source.attrs.instanceName ?? f.source.attrs.typeName ?? f.source.name}${pin ? `.${pin}` : ''} -> ${f.consumer.attrs.instanceName ?? f.consumer.attrs.typeName ?? f.consumer.name} (localId ${f.consumer.attrs.localId ?? '?'})`;
      // A loop through a function stays drawn: the engine cuts it there and reads the function's
      // result of its previous call (order.ts, feedback.ts), as Beremiz's `_TMP_XOR20_OUT` holds it.
      if (f.source.name === 'block' && !instance) continue;
      if (f.source.name !== 'block' || !pin)
        return {
          networks: `${from}: the wire ${wireName} closes a loop through a ${f.source.name}, which keeps no value of a previous call; only a block's output can feed back`,
          blocks: true,
        };
      const id = nextId++;
      parts.push(
        parseXml(`<inVariable localId="${id}" height="30" width="60"><position x="0" y="0"/><connectionPointOut><relPosition x="60" y="15"/></connectionPointOut><expression>${instance}.${pin}</expression></inVariable>`),
      );
      const list = replaced.get(f.consumer) ?? [];
      list.push({ wire: f.wire, text: `<connection refLocalId="${id}"/>` });
      replaced.set(f.consumer, list);
    }
    const partText = (el: XmlElement): string => {
      let text = rawOf(el);
      const list = [...(replaced.get(el) ?? [])].sort((a, b) => b.wire.offset - a.wire.offset);
      for (const r of list) text = text.slice(0, r.wire.offset - el.offset) + r.text + text.slice(r.wire.end - el.offset);
      return text;
    };
    const blocks = parts.some((p) => p.name === 'block');
    const ld = parts.some((p) => p.name === 'leftPowerRail' || p.name === 'contact' || p.name === 'coil');
    const wireText = wires
      .map(
        (w) =>
          `<connection refLocalId="${w.attrs.refLocalId}"${w.attrs.formalParameter !== undefined ? ` formalParameter="${w.attrs.formalParameter}"` : ''}/>`,
      )
      .join('');
    const id = 1_000_000;
    const sink = ld
      ? `<coil localId="${id}" height="15" width="21"><position x="0" y="0"/><connectionPointIn>${wireText}</connectionPointIn><connectionPointOut/><variable>${result}</variable></coil><rightPowerRail localId="${id + 1}" height="40" width="3"><position x="0" y="0"/><connectionPointIn><connection refLocalId="${id}"/></connectionPointIn></rightPowerRail>`
      : `<outVariable localId="${id}" height="30" width="60"><position x="0" y="0"/><connectionPointIn>${wireText}</connectionPointIn><expression>${result}</expression></outVariable>`;
    const tag = ld ? 'LD' : 'FBD';
    const xml = `<${tag}>${parts.map(partText).join('')}${sink}</${tag}>`;
    return { networks: importPiece(xml, from), blocks };
  };

  const conditionOf = (tr: XmlElement): SfcCode => {
    const cond = child(tr, 'condition');
    const id = tr.attrs.localId ?? '?';
    const inline = cond && child(cond, 'inline');
    if (inline) {
      const st = child(inline, 'ST');
      if (st) return { language: 'ST', text: deepText(st).trim() };
      return { language: 'none', why: `the inline condition of transition ${id} is not written in ST` };
    }
    const ref = cond && child(cond, 'reference');
    if (ref) {
      const name = ref.attrs.name ?? '';
      const known = referenced.get(name.toUpperCase());
      if (known) return known;
      const code = referencedCondition(name, id);
      referenced.set(name.toUpperCase(), code);
      return code;
    }
    const wires = cond && child(cond, 'connectionPointIn');
    // A condition wired straight from a variable (CODESYS writes every transition so): its
    // expression is ST, `T1 > T#7S OR Step4.t > T2` as much as a name.
    const only = wires ? childrenNamed(wires, 'connection') : [];
    const source = only.length === 1 ? byId.get(num(only[0]!.attrs.refLocalId) ?? -1) : undefined;
    const expression = source?.name === 'inVariable' ? child(source, 'expression')?.text.trim() : undefined;
    if (expression) return { language: 'ST', text: expression };
    if (wires) {
      const result = `_SFC_C${id}`;
      return placed(graphicCondition(wires, byId, result, `the condition of transition ${id}`), result);
    }
    return { language: 'none', why: `transition ${id} has no condition` };
  };
  /** A transition body named by transitions (its blocks run once, however many transitions name it). */
  const referenced = new Map<string, SfcCode>();
  const referencedCondition = (name: string, id: string): SfcCode => {
    {
      const decl = declaredTransitions.get(name.toUpperCase());
      if (!decl) return { language: 'none', why: `transition ${id} refers to "${name}", which the POU does not declare` };
      const body = child(decl, 'body');
      const st = body && child(body, 'ST');
      if (st) return { language: 'ST', text: deepText(st).trim().replace(/^:=\s*/, '').replace(/;\s*$/, '') };
      const graphic = body && (child(body, 'LD') ?? child(body, 'FBD'));
      if (!graphic) return { language: 'none', why: `the body of transition "${name}" is not written in ST, LD or FBD` };
      const sinks = graphic.children.filter(
        (c) =>
          (c.name === 'coil' && (child(c, 'variable')?.text.trim() ?? '').toUpperCase() === name.toUpperCase()) ||
          (c.name === 'outVariable' && (child(c, 'expression')?.text.trim() ?? '').toUpperCase() === name.toUpperCase()),
      );
      const sink = sinks[0];
      const wires = sink && child(sink, 'connectionPointIn');
      if (!wires)
        return {
          language: 'none',
          why: `the body of transition "${name}" must contain an output variable or coil named "${name}"`,
        };
      const ids = new Map<number, XmlElement>();
      for (const c of graphic.children) {
        const n = num(c.attrs.localId);
        if (n !== undefined) ids.set(n, c);
      }
      const result = `_SFC_${name}`;
      return placed(graphicCondition(wires, ids, result, `transition "${name}"`), result);
    }
  };
  /** A graphical condition: run where the transition is tested, or (with blocks) in COMPUTE_FUNCTION_BLOCKS. */
  const placed = (g: { networks: Network[] | string; blocks: boolean }, result: string): SfcCode => {
    if (typeof g.networks === 'string') return { language: 'none', why: g.networks };
    if (!locals.some((l) => l.toUpperCase() === result.toUpperCase())) locals.push(result);
    if (!g.blocks) return { language: 'LD', networks: g.networks, result };
    computed.push(...g.networks);
    return { language: 'ST', text: result };
  };

  const generateStep = (step: XmlElement): void => {
    const name = step.attrs.name ?? '';
    if (steps.has(name.toUpperCase())) return;
    const initial = step.attrs.initialStep === 'true';
    if (initial) initialSteps.push(name);
    const info: StepInfo = { name, initial, localId: num(step.attrs.localId) ?? -1, transitions: [], associations: [] };
    steps.set(name.toUpperCase(), info);
    for (const t of transitionsInto(step)) {
      generateTransition(t);
      transitions.get(t)?.to.push(name);
    }
  };
  const generateJump = (jump: XmlElement): void => {
    for (const t of transitionsInto(jump)) {
      generateTransition(t);
      transitions.get(t)?.to.push(jump.attrs.targetName ?? '');
    }
  };
  const generateTransition = (tr: XmlElement): void => {
    if (transitions.has(tr)) return;
    const fromSteps: XmlElement[] = [];
    const src = inputOf(tr);
    if (src?.name === 'step') fromSteps.push(src);
    else if (src?.name === 'selectionDivergence') {
      const s = inputOf(src);
      if (s?.name === 'step') fromSteps.push(s);
      else if (s?.name === 'simultaneousConvergence') fromSteps.push(...inputsOf(s).filter((x) => x.name === 'step'));
    } else if (src?.name === 'simultaneousConvergence') fromSteps.push(...inputsOf(src).filter((x) => x.name === 'step'));
    const priority = num(tr.attrs.priority);
    const info: TransitionInfo = {
      el: tr,
      from: [],
      to: [],
      ...(priority !== undefined ? { priority } : {}),
      condition: { language: 'none', why: '' },
    };
    transitions.set(tr, info);
    info.condition = conditionOf(tr);
    for (const s of fromSteps) {
      generateStep(s);
      const si = steps.get((s.attrs.name ?? '').toUpperCase());
      if (!si) continue;
      info.from.push(si.name);
      si.transitions.push(tr);
    }
  };
  const generateActionBlock = (block: XmlElement): void => {
    const step = inputOf(block);
    if (!step || step.name !== 'step') return;
    generateStep(step);
    const si = steps.get((step.attrs.name ?? '').toUpperCase());
    if (!si) return;
    for (const a of childrenNamed(block, 'action')) {
      const qualifier = a.attrs.qualifier || 'N';
      const extra = {
        ...(a.attrs.duration ? { duration: a.attrs.duration } : {}),
        ...(a.attrs.indicator ? { indicator: a.attrs.indicator } : {}),
      };
      const ref = child(a, 'reference');
      if (ref) {
        const name = ref.attrs.name ?? '';
        generateAction(name);
        si.associations.push({ action: name, qualifier, ...extra });
        continue;
      }
      const name = `${si.name.toUpperCase()}_INLINE${++inlineCount}`;
      const inline = child(a, 'inline');
      const st = inline && child(inline, 'ST');
      actions.set(name, {
        name,
        body: st
          ? { language: 'ST', text: deepText(st).trim() }
          : { language: 'none', why: `an inline action of step ${si.name} is not written in ST` },
      });
      si.associations.push({ action: name, qualifier, ...extra });
    }
  };
  const generateAction = (name: string): void => {
    if (actions.has(name.toUpperCase())) return;
    const decl = declaredActions.get(name.toUpperCase());
    if (!decl) return; // a BOOL variable, or unknown (the engine tells)
    const body = child(decl, 'body');
    const st = body && child(body, 'ST');
    const graphic = body && (child(body, 'LD') ?? child(body, 'FBD'));
    let code: SfcCode;
    if (st) code = { language: 'ST', text: deepText(st).trim() };
    else if (graphic) {
      const networks = importPiece(rawOf(graphic), `action "${name}"`);
      code = typeof networks === 'string' ? { language: 'none', why: networks } : { language: 'LD', networks };
    } else code = { language: 'none', why: `the body of action "${name}" is not written in ST, LD or FBD` };
    actions.set(name.toUpperCase(), { name: decl.attrs.name ?? name, body: code });
  };

  for (const el of sfc.children) {
    if (el.name === 'step') generateStep(el);
    else if (el.name === 'actionBlock') generateActionBlock(el);
    else if (el.name === 'transition') generateTransition(el);
    else if (el.name === 'jumpStep') generateJump(el);
  }
  if (initialSteps.length && computed.length) {
    steps.get(initialSteps[0]!.toUpperCase())!.associations.push({ action: COMPUTE_FUNCTION_BLOCKS, qualifier: 'S' });
    actions.set(COMPUTE_FUNCTION_BLOCKS, { name: COMPUTE_FUNCTION_BLOCKS, body: { language: 'LD', networks: computed } });
  }

  // The text order: from each initial step, depth first.
  const outSteps: SfcStep[] = [];
  const outTransitions: SfcTransition[] = [];
  const outActions: SfcAction[] = [];
  const stepsLeft = new Map(steps);
  const transitionsLeft = new Map(transitions);
  const actionsLeft = new Map(actions);
  const computeStep = (name: string): void => {
    const s = stepsLeft.get(name.toUpperCase());
    if (!s) return;
    stepsLeft.delete(name.toUpperCase());
    outSteps.push({ name: s.name, initial: s.initial, associations: s.associations, localId: s.localId });
    for (const a of s.associations) {
      const act = actionsLeft.get(a.action.toUpperCase());
      if (!act) continue;
      actionsLeft.delete(a.action.toUpperCase());
      outActions.push(act);
    }
    for (const t of s.transitions) computeTransition(t);
  };
  const computeTransition = (el: XmlElement): void => {
    const t = transitionsLeft.get(el);
    if (!t) return;
    transitionsLeft.delete(el);
    outTransitions.push({
      from: t.from,
      to: t.to,
      ...(t.priority !== undefined ? { priority: t.priority } : {}),
      condition: t.condition,
      localId: num(el.attrs.localId) ?? -1,
    });
    for (const s of t.to) computeStep(s);
  };
  for (const s of initialSteps) computeStep(s);
  return {
    steps: outSteps,
    transitions: outTransitions,
    actions: outActions,
    ...(locals.length ? { locals } : {}),
  };
}
