// Find and replace across every network of every POU: variables (contacts, coils, FB instances,
// pin operands), literals (pin operands that are constants), network comments, titles and labels,
// jump targets, connector/continuation names and block types. Pure functions over the Project; the editor's find panel
// (src/editor/find) shows the hits and applies a replacement as one undo step.
import type { ElementKind, LdElement } from '../model/elements';
import type { ElementId, NetworkId, PouId } from '../model/ids';
import type { Network, Project } from '../model/project';

export type FindField = 'variable' | 'literal' | 'comment' | 'title' | 'label' | 'jump' | 'connector' | 'block';
export const FIND_FIELDS: readonly FindField[] = [
  'variable',
  'literal',
  'comment',
  'title',
  'label',
  'jump',
  'connector',
  'block',
];

export interface FindQuery {
  readonly text: string;
  /** `text`: anywhere in the text; `word`: a whole name (`Timer1` finds `Timer1.Q`, not `Timer10`); `regex`: a pattern. */
  readonly mode: 'text' | 'word' | 'regex';
  readonly caseSensitive?: boolean;
  /** Fields searched; all when absent. */
  readonly fields?: readonly FindField[];
}

/** Where a text lives: a network field, or an element's field (a box pin when `pin`). */
export interface FindPlace {
  readonly pou: PouId;
  readonly pouName: string;
  readonly network: NetworkId;
  /** 0-based index of the network in its POU. */
  readonly networkIndex: number;
  readonly field: FindField;
  readonly element?: ElementId;
  readonly elementKind?: ElementKind;
  readonly row?: number;
  readonly col?: number;
  /** Box pin name (`PT`), or `instance` for the FB instance name. */
  readonly pin?: string;
  /** The whole text searched. */
  readonly text: string;
}

export interface FindHit extends FindPlace {
  /** Where the match starts in `text`, and its length. */
  readonly start: number;
  readonly length: number;
}

const LITERAL = /^(?:[+-]?\d|TRUE$|FALSE$|[A-Za-z_]*#|'|")/i;
/** Is a pin operand a constant (`10`, `T#5s`, `TRUE`, `INT#-3`, `'text'`) rather than a variable? */
export const isLiteral = (operand: string): boolean => LITERAL.test(operand.trim());

/** Every searchable text of one element. */
function elementTexts(el: LdElement): { field: FindField; pin?: string; text: string }[] {
  switch (el.kind) {
    case 'contact':
    case 'coil':
      return el.variable ? [{ field: 'variable', text: el.variable }] : [];
    case 'jump':
      return [{ field: 'jump', text: el.target }];
    // A connector and its continuations share the field: replacing a name renames the pair.
    case 'connector':
    case 'continuation':
      return el.name ? [{ field: 'connector', text: el.name }] : [];
    case 'box': {
      const out: { field: FindField; pin?: string; text: string }[] = [{ field: 'block', text: el.blockType }];
      if (el.instance) out.push({ field: 'variable', pin: 'instance', text: el.instance });
      for (const [pin, text] of [...Object.entries(el.inputs), ...Object.entries(el.outputs)])
        if (text.trim()) out.push({ field: isLiteral(text) ? 'literal' : 'variable', pin, text });
      return out;
    }
    default:
      return [];
  }
}

/** Every searchable place of a network (network fields first, then elements in grid order). */
export function networkPlaces(
  pou: { id: PouId; name: string },
  network: Network,
  networkIndex: number,
): FindPlace[] {
  const base = { pou: pou.id, pouName: pou.name, network: network.id, networkIndex };
  const out: FindPlace[] = [];
  if (network.label) out.push({ ...base, field: 'label', text: network.label });
  if (network.title) out.push({ ...base, field: 'title', text: network.title });
  if (network.comment) out.push({ ...base, field: 'comment', text: network.comment });
  const els = [...network.elements].sort((a, b) => a.row - b.row || a.col - b.col);
  for (const el of els)
    for (const t of elementTexts(el))
      out.push({
        ...base,
        ...t,
        element: el.id,
        elementKind: el.kind,
        row: el.row,
        col: el.col,
      });
  return out;
}

const escapeRe = (s: string) => s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');

/** The query as a global RegExp, or an error message for a bad pattern. */
export function queryRegExp(q: FindQuery): RegExp | string {
  if (!q.text) return 'Type something to find.';
  const flags = q.caseSensitive ? 'g' : 'gi';
  try {
    if (q.mode === 'regex') return new RegExp(q.text, flags);
    if (q.mode === 'word') return new RegExp(`(?<![A-Za-z0-9_])${escapeRe(q.text)}(?![A-Za-z0-9_])`, flags);
    return new RegExp(escapeRe(q.text), flags);
  } catch (e) {
    return `Not a valid pattern: ${(e as Error).message}`;
  }
}

/** Every match of the query in the project, POU by POU, network by network. */
export function findInProject(project: Project, q: FindQuery, limit = Infinity): FindHit[] | string {
  const re = queryRegExp(q);
  if (typeof re === 'string') return re;
  const fields = new Set(q.fields ?? FIND_FIELDS);
  const hits: FindHit[] = [];
  for (const pou of project.pous)
    pou.networks.forEach((network, i) => {
      for (const place of networkPlaces(pou, network, i)) {
        if (!fields.has(place.field)) continue;
        re.lastIndex = 0;
        for (let m = re.exec(place.text); m; m = re.exec(place.text)) {
          if (m[0].length === 0) {
            re.lastIndex++;
            continue;
          }
          if (hits.length >= limit) return;
          hits.push({ ...place, start: m.index, length: m[0].length });
        }
      }
    });
  return hits;
}

export interface Replacement {
  readonly place: FindPlace;
  readonly before: string;
  readonly after: string;
}

/** What a replace-all would change, place by place (the preview). */
export function planReplace(project: Project, q: FindQuery, by: string): Replacement[] | string {
  const re = queryRegExp(q);
  if (typeof re === 'string') return re;
  const fields = new Set(q.fields ?? FIND_FIELDS);
  const out: Replacement[] = [];
  // In text and word modes the replacement is literal text ($ has no meaning).
  const rep = q.mode === 'regex' ? by : by.replace(/\$/g, '$$$$');
  for (const pou of project.pous)
    pou.networks.forEach((network, i) => {
      for (const place of networkPlaces(pou, network, i)) {
        if (!fields.has(place.field)) continue;
        re.lastIndex = 0;
        const after = place.text.replace(re, rep);
        if (after !== place.text) out.push({ place, before: place.text, after });
      }
    });
  return out;
}

function replaceInElement(el: LdElement, r: Replacement): LdElement {
  const { field, pin } = r.place;
  switch (el.kind) {
    case 'contact':
    case 'coil':
      return field === 'variable' ? { ...el, variable: r.after } : el;
    case 'jump':
      return field === 'jump' ? { ...el, target: r.after } : el;
    case 'connector':
    case 'continuation':
      return field === 'connector' ? { ...el, name: r.after } : el;
    case 'box': {
      if (field === 'block') return { ...el, blockType: r.after };
      if (pin === 'instance') return { ...el, instance: r.after };
      if (pin && pin in el.inputs && el.inputs[pin] === r.before)
        return { ...el, inputs: { ...el.inputs, [pin]: r.after } };
      if (pin && pin in el.outputs && el.outputs[pin] === r.before)
        return { ...el, outputs: { ...el.outputs, [pin]: r.after } };
      return el;
    }
    default:
      return el;
  }
}

/** The networks after the replacements, keyed by id (each network's POU alongside). */
export function applyReplacements(
  project: Project,
  replacements: readonly Replacement[],
): { pou: PouId; before: Network; after: Network }[] {
  const byNetwork = new Map<NetworkId, Replacement[]>();
  for (const r of replacements) {
    const list = byNetwork.get(r.place.network);
    if (list) list.push(r);
    else byNetwork.set(r.place.network, [r]);
  }
  const out: { pou: PouId; before: Network; after: Network }[] = [];
  for (const pou of project.pous)
    for (const before of pou.networks) {
      const list = byNetwork.get(before.id);
      if (!list) continue;
      let after: Network = before;
      for (const r of list) {
        if (!r.place.element) {
          const key = r.place.field as 'label' | 'title' | 'comment';
          after = { ...after, [key]: r.after };
        } else {
          after = {
            ...after,
            elements: after.elements.map((e) => (e.id === r.place.element ? replaceInElement(e, r) : e)),
          };
        }
      }
      out.push({ pou: pou.id, before, after });
    }
  return out;
}
