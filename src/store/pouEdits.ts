// Pure helpers behind the POU commands (src/store/pouCommands.ts): names, where a POU is used,
// the changes that make references follow a rename, copies with fresh ids, and calls that follow
// a change of the callee's interface (pins renamed, boxes grown).
import { libraryOf } from '../model/libraries';
import { elementCells, elementSize } from '../model/factory';
import { blockSignature } from '../model/blocks';
import type { BoxElement, LdElement } from '../model/elements';
import { isElementaryType } from '../model/iecTypes';
import { newId, type ElementId, type NetworkId, type PouId } from '../model/ids';
import { blockLibrary, type BlockLibrary } from '../model/library';
import type { Network, Pou, PouKind, Project, Task, Variable } from '../model/project';
import { applyChanges, diffNetwork, type Change, type VariableScope } from './changes';
import { grow, insertRow } from './networkEdits';

const same = (a: string, b: string) => a.trim().toUpperCase() === b.trim().toUpperCase();

export const POU_KIND_WORDS: Record<PouKind, string> = {
  PROGRAM: 'program',
  FUNCTION_BLOCK: 'function block',
  FUNCTION: 'function',
};

const IDENTIFIER = /^[A-Za-z_][A-Za-z0-9_]*$/;

/** Why `name` cannot name a POU of the project (another POU than `except`), or undefined. */
export function pouNameProblem(project: Project, name: string, except?: PouId): string | undefined {
  const n = name.trim();
  if (n === '') return 'A POU needs a name.';
  if (!IDENTIFIER.test(n) || n.includes('__'))
    return `"${n}" is not an IEC identifier (letters, digits and single underscores, not starting with a digit).`;
  if (blockSignature(n)) return `"${n}" is the name of the standard block ${n.toUpperCase()}.`;
  if (isElementaryType(n.toUpperCase())) return `"${n}" is the name of the type ${n.toUpperCase()}.`;
  const other = project.pous.find((p) => p.id !== except && same(p.name, n));
  if (other) return `The project already has a ${POU_KIND_WORDS[other.kind]} named ${other.name}.`;
  const type = project.dataTypes?.find((t) => same(t.name, n));
  if (type) return `The project already has a data type named ${type.name}.`;
  const library = libraryOf(project, n);
  if (library) return `"${n}" is a block or data type of the library ${library.name}.`;
  return undefined;
}

/** `base`, or `base2`, `base3`... the first name no POU (nor standard block) has. */
export function freshPouName(project: Project, base: string): string {
  if (!pouNameProblem(project, base)) return base;
  for (let i = 1; ; i++) if (!pouNameProblem(project, `${base}${i}`)) return `${base}${i}`;
}

/** `Motor1`, `Motor2`, ...: the first instance name not declared in the POU nor as a global. */
export function freshInstanceName(project: Project, pou: Pou | undefined, blockType: string): string {
  const base = blockType.replace(/^FB_/i, '') || 'Instance';
  const taken = new Set([...(pou?.variables ?? []), ...project.globals].map((v) => v.name.toUpperCase()));
  for (const p of project.pous) taken.add(p.name.toUpperCase());
  for (let i = 1; ; i++) if (!taken.has(`${base}${i}`.toUpperCase())) return `${base}${i}`;
}

/** One place that uses a POU. */
export type PouUse =
  | {
      readonly kind: 'call';
      readonly pou: PouId;
      readonly pouName: string;
      readonly network: NetworkId;
      /** 0-based network index in the calling POU. */
      readonly networkIndex: number;
      readonly element: ElementId;
      readonly instance?: string;
    }
  | {
      readonly kind: 'instance';
      readonly scope: VariableScope;
      readonly owner: string;
      readonly variable: string;
    }
  | { readonly kind: 'task'; readonly task: string; readonly instance: string };

/** Every call (box), instance declaration and task entry naming the POU called `name`. */
export function pouUsages(project: Project, name: string): PouUse[] {
  const out: PouUse[] = [];
  for (const pou of project.pous) {
    pou.networks.forEach((net, networkIndex) => {
      for (const el of net.elements)
        if (el.kind === 'box' && same(el.blockType, name))
          out.push({
            kind: 'call',
            pou: pou.id,
            pouName: pou.name,
            network: net.id,
            networkIndex,
            element: el.id,
            ...(el.instance ? { instance: el.instance } : {}),
          });
    });
    for (const v of pou.variables)
      if (same(v.type, name))
        out.push({ kind: 'instance', scope: pou.id, owner: pou.name, variable: v.name });
  }
  for (const v of project.globals)
    if (same(v.type, name))
      out.push({ kind: 'instance', scope: 'globals', owner: 'global variables', variable: v.name });
  for (const task of project.tasks)
    for (const p of task.programs)
      if (same(p.pou, name)) out.push({ kind: 'task', task: task.name, instance: p.instance });
  return out;
}

/** "Main, network 2 (Motor1)", "Main: instance Motor1", "task MainTask: MainInstance". */
export function describeUse(u: PouUse): string {
  switch (u.kind) {
    case 'call':
      return `${u.pouName}, network ${u.networkIndex + 1}${u.instance ? ` (${u.instance})` : ''}`;
    case 'instance':
      return `${u.owner}: instance ${u.variable}`;
    case 'task':
      return `task ${u.task}: program instance ${u.instance}`;
  }
}

/** Every network of every POU rewritten element by element (changes only where something changed). */
function mapElements(project: Project, fn: (el: LdElement, pou: Pou) => LdElement): Change[] {
  const changes: Change[] = [];
  for (const pou of project.pous)
    for (const net of pou.networks) {
      let touched = false;
      const elements = net.elements.map((e) => {
        const next = fn(e, pou);
        if (next !== e) touched = true;
        return next;
      });
      if (touched) changes.push(...diffNetwork(pou.id, net, { ...net, elements }));
    }
  return changes;
}

/** Variables of every scope (POUs and globals) whose type is `from`, retyped to `to`. */
function retypeVariables(project: Project, from: string, to: string): Change[] {
  const changes: Change[] = [];
  const scan = (scope: VariableScope, vars: readonly Variable[]) =>
    vars.forEach((v, index) => {
      if (same(v.type, from))
        changes.push({ type: 'variable.update', scope, index, before: v, after: { ...v, type: to } });
    });
  for (const pou of project.pous) scan(pou.id, pou.variables);
  scan('globals', project.globals);
  return changes;
}

/** The changes renaming POU `pou` to `to`: the POU, calls' block types, instance types, task entries. */
export function renamePouChanges(project: Project, pou: Pou, to: string): Change[] {
  const from = pou.name;
  const changes: Change[] = [
    { type: 'pou.update', pou: pou.id, before: { name: from }, after: { name: to } },
  ];
  changes.push(
    ...mapElements(project, (el) =>
      el.kind === 'box' && same(el.blockType, from) ? { ...el, blockType: to } : el,
    ),
  );
  changes.push(...retypeVariables(project, from, to));
  // A task made for the program (`T_<name>`, running only it) is renamed along.
  const ownTask = (t: Task) =>
    same(t.name, `T_${from}`) &&
    t.programs.length > 0 &&
    t.programs.every((p) => same(p.pou, from)) &&
    !project.tasks.some((o) => same(o.name, `T_${to}`));
  const tasks: Task[] = project.tasks.map((t) =>
    t.programs.some((p) => same(p.pou, from))
      ? {
          ...t,
          ...(ownTask(t) ? { name: `T_${to}` } : {}),
          programs: t.programs.map((p) => (same(p.pou, from) ? { ...p, pou: to } : p)),
        }
      : t,
  );
  if (tasks.some((t, i) => t !== project.tasks[i]))
    changes.push({ type: 'tasks.update', before: project.tasks, after: tasks });
  return changes;
}

/** A copy of the POU named `name`, with new ids for it, its networks and their elements. */
export function copyPou(pou: Pou, name: string): Pou {
  return {
    ...pou,
    id: newId<'PouId'>('p') as PouId,
    name,
    networks: pou.networks.map((n) => ({
      ...n,
      id: newId<'NetworkId'>('n') as NetworkId,
      elements: n.elements.map((e) => ({ ...e, id: newId<'ElementId'>('e') as ElementId })),
    })),
  };
}

function renameKey(
  rec: Readonly<Record<string, string>>,
  from: string,
  to: string,
): Readonly<Record<string, string>> {
  const key = Object.keys(rec).find((k) => same(k, from));
  if (key === undefined) return rec;
  const out: Record<string, string> = {};
  for (const [k, v] of Object.entries(rec)) out[k === key ? to : k] = v;
  return out;
}

/**
 * A pin of block `callee` renamed from `from` to `to`: every call's operand for that pin moves to
 * the new name, and `Instance.from` operands of the callee's instances become `Instance.to`.
 */
export function pinRenameChanges(project: Project, callee: string, from: string, to: string): Change[] {
  const instancesOf = (pou: Pou) =>
    new Set(
      [...pou.variables, ...project.globals]
        .filter((v) => same(v.type, callee))
        .map((v) => v.name.toUpperCase()),
    );
  const cache = new Map<PouId, Set<string>>();
  const renamePin = (operand: string, instances: Set<string>): string => {
    const t = operand.trim();
    const dot = t.indexOf('.');
    if (dot < 0 || !instances.has(t.slice(0, dot).toUpperCase())) return operand;
    const rest = t.slice(dot + 1);
    const pinEnd = rest.indexOf('.');
    const pin = pinEnd < 0 ? rest : rest.slice(0, pinEnd);
    if (!same(pin, from)) return operand;
    return `${t.slice(0, dot)}.${to}${pinEnd < 0 ? '' : rest.slice(pinEnd)}`;
  };
  const renameRec = (rec: Readonly<Record<string, string>>, instances: Set<string>) => {
    let changed = false;
    const out: Record<string, string> = {};
    for (const [k, v] of Object.entries(rec)) {
      out[k] = renamePin(v, instances);
      if (out[k] !== v) changed = true;
    }
    return changed ? out : rec;
  };
  return mapElements(project, (el, pou) => {
    let instances = cache.get(pou.id);
    if (!instances) cache.set(pou.id, (instances = instancesOf(pou)));
    switch (el.kind) {
      case 'contact':
      case 'coil': {
        const variable = renamePin(el.variable, instances);
        return variable === el.variable ? el : { ...el, variable };
      }
      case 'box': {
        let box: BoxElement = el;
        if (same(el.blockType, callee)) {
          const inputs = renameKey(el.inputs, from, to);
          const outputs = renameKey(el.outputs, from, to);
          if (inputs !== el.inputs || outputs !== el.outputs) box = { ...box, inputs, outputs };
        }
        const inputs = renameRec(box.inputs, instances);
        const outputs = renameRec(box.outputs, instances);
        return inputs === box.inputs && outputs === box.outputs ? box : { ...box, inputs, outputs };
      }
      default:
        return el;
    }
  });
}

/**
 * Calls of `callee` whose box grew between the `before` and `after` projects (a pin was added):
 * the network grows to hold the box, and when the bigger box would cover other elements, empty
 * rows are inserted under the box's old bottom so the rest of the network moves down.
 */
export function makeRoomForCalls(before: Project, after: Project, callee: string): Change[] {
  const oldLib = blockLibrary(before);
  const newLib = blockLibrary(after);
  const changes: Change[] = [];
  for (const pou of after.pous)
    for (const net of pou.networks) {
      const next = roomInNetwork(net, callee, oldLib, newLib);
      if (next !== net) changes.push(...diffNetwork(pou.id, net, next));
    }
  return changes;
}

function roomInNetwork(net: Network, callee: string, oldLib: BlockLibrary, newLib: BlockLibrary): Network {
  let n = net;
  const calls = net.elements.filter((e): e is BoxElement => e.kind === 'box' && same(e.blockType, callee));
  if (calls.length === 0) return net;
  // Lowest box first, so rows inserted for it do not move the boxes still to do.
  for (const call of [...calls].sort((a, b) => b.row - a.row)) {
    const box = n.elements.find((e) => e.id === call.id) as BoxElement;
    const oldRows = elementSize(box, oldLib).rows;
    const extra = elementSize(box, newLib).rows - oldRows;
    if (extra <= 0) continue;
    const covered = new Set(elementCells(box, newLib).map((c) => `${c.row}:${c.col}`));
    const blocked = n.elements.some(
      (e) => e.id !== box.id && elementCells(e, oldLib).some((c) => covered.has(`${c.row}:${c.col}`)),
    );
    if (blocked) for (let i = 0; i < extra; i++) n = insertRow(n, box.row + oldRows, oldLib);
  }
  return grow(n, n.elements, n.vlinks, newLib);
}

const PIN_CLASSES = new Set(['input', 'output', 'inOut']);

/**
 * Calls follow a change of a block's interface: `changes` edit variables of the POU `scope`; when
 * that POU is a FUNCTION_BLOCK or FUNCTION, an interface pin renamed from `renamed.from` moves
 * on every call, and boxes that grew get room. Returns the follow-up changes (maybe none).
 */
export function followInterface(
  project: Project,
  scope: VariableScope,
  changes: readonly Change[],
  renamed?: { readonly from: Variable; readonly to: Variable },
): Change[] {
  const callee = scope === 'globals' ? undefined : project.pous.find((p) => p.id === scope);
  if (!callee || callee.kind === 'PROGRAM') return [];
  let after = applyChanges(project, changes);
  const out: Change[] = [];
  if (renamed && renamed.from.name !== renamed.to.name && PIN_CLASSES.has(renamed.from.varClass)) {
    const moved = pinRenameChanges(after, callee.name, renamed.from.name, renamed.to.name);
    out.push(...moved);
    after = applyChanges(after, moved);
  }
  out.push(...makeRoomForCalls(project, after, callee.name));
  return out;
}
