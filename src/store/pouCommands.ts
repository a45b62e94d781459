// The POU commands (add, rename, duplicate, delete, properties): each is one undo step, and
// references follow a rename (calls' block types, instance types, task entries). See the list at
// the top of documentStore.ts.
import { newNetwork, newPou } from '../model/factory';
import type { PouId } from '../model/ids';
import type { Pou, PouKind, Project, Task } from '../model/project';
import { applyChanges, type Change, type PouProps } from './changes';
import { copyPou, freshPouName, makeRoomForCalls, pouNameProblem, renamePouChanges } from './pouEdits';

export interface PouCommandOps {
  project(): Project;
  commit(name: string, changes: readonly Change[]): void;
  /** Opens the POU in a tab and shows it. */
  open(id: PouId): void;
}

/** Editable POU properties: `returnType` only for a FUNCTION (`undefined` removes it). */
export type PouPatch = Partial<Pick<PouProps, 'comment' | 'returnType' | 'kind'>>;

/** The languages a new POU can be written in (its body: LD networks or ST text). */
export type NewPouLanguage = 'LD' | 'ST';

/**
 * Where a new PROGRAM runs: in a task of its own (`T_<name>`, cyclic `cycleMs`, 10 ms unless said),
 * in the existing task at `task` (its index), or in none. Without it: the first task, if any.
 */
export type RunIn =
  | { readonly kind: 'own'; readonly cycleMs?: number }
  | { readonly kind: 'task'; readonly task: number }
  | { readonly kind: 'none' };

/** The cyclic interval of a task made for a new program (ms). */
export const OWN_TASK_MS = 10;

export interface PouCommands {
  /** A new POU (LD by default: one empty network; ST: an empty body text), opened; a PROGRAM runs where `run` says. */
  addPou(kind: PouKind, name?: string, language?: NewPouLanguage, run?: RunIn): PouId | undefined;
  renamePou(id: PouId, name: string): boolean;
  duplicatePou(id: PouId): PouId | undefined;
  deletePou(id: PouId): boolean;
  updatePou(id: PouId, patch: PouPatch): boolean;
  /**
   * The body text of an ST (or IL) POU, one undo step named `name` (the ST editor commits a typing
   * burst as "Edit ST body of Scale"). False when the POU has no text body or nothing changed.
   */
  setPouSource(id: PouId, text: string, name: string): boolean;
}

const DEFAULT_NAMES: Record<PouKind, string> = {
  PROGRAM: 'Program',
  FUNCTION_BLOCK: 'FB',
  FUNCTION: 'Function',
};

export function pouCommands({ project, commit, open }: PouCommandOps): PouCommands {
  const find = (id: PouId) => project().pous.find((p) => p.id === id);

  return {
    addPou: (kind, name, language = 'LD', run) => {
      const p = project();
      const chosen = name?.trim() || freshPouName(p, DEFAULT_NAMES[kind]);
      if (pouNameProblem(p, chosen)) return undefined;
      const pou = newPou(chosen, {
        kind,
        ...(language === 'ST' ? { language: 'ST' as const, networks: [], source: '' } : { networks: [newNetwork()] }),
        ...(kind === 'FUNCTION' ? { returnType: 'BOOL' } : {}),
      });
      const changes: Change[] = [{ type: 'pou.add', index: p.pous.length, pou }];
      // A new program runs: in a task of its own, a task chosen, or (by default) the first task.
      const where: RunIn = run ?? (p.tasks.length ? { kind: 'task', task: 0 } : { kind: 'none' });
      if (kind === 'PROGRAM' && where.kind !== 'none') {
        const taken = new Set(
          [...p.tasks.flatMap((t) => t.programs.map((x) => x.instance)), ...p.globals.map((g) => g.name)].map((n) =>
            n.toUpperCase(),
          ),
        );
        let instance = `${chosen}Instance`;
        for (let i = 2; taken.has(instance.toUpperCase()); i++) instance = `${chosen}Instance${i}`;
        const entry = { instance, pou: chosen };
        let tasks: Task[] | undefined;
        if (where.kind === 'own') {
          const names = new Set(p.tasks.map((t) => t.name.toUpperCase()));
          let taskName = `T_${chosen}`;
          for (let i = 2; names.has(taskName.toUpperCase()); i++) taskName = `T_${chosen}${i}`;
          tasks = [...p.tasks, { name: taskName, cycleMs: where.cycleMs ?? OWN_TASK_MS, priority: 1, programs: [entry] }];
        } else if (p.tasks[where.task])
          tasks = p.tasks.map((t, i) => (i === where.task ? { ...t, programs: [...t.programs, entry] } : t));
        if (tasks) changes.push({ type: 'tasks.update', before: p.tasks, after: tasks });
      }
      commit('addPou', changes);
      open(pou.id);
      return pou.id;
    },
    renamePou: (id, name) => {
      const p = project();
      const pou = find(id);
      const to = name.trim();
      if (!pou || pouNameProblem(p, to, id)) return false;
      if (to === pou.name) return true;
      commit('renamePou', renamePouChanges(p, pou, to));
      return true;
    },
    duplicatePou: (id) => {
      const p = project();
      const pou = find(id);
      if (!pou) return undefined;
      const copy = copyPou(pou, freshPouName(p, `${pou.name}_copy`));
      commit('duplicatePou', [{ type: 'pou.add', index: p.pous.indexOf(pou) + 1, pou: copy }]);
      open(copy.id);
      return copy.id;
    },
    deletePou: (id) => {
      const p = project();
      const index = p.pous.findIndex((x) => x.id === id);
      const pou = p.pous[index];
      // The project keeps at least one POU to edit.
      if (!pou || p.pous.length <= 1) return false;
      const changes: Change[] = [{ type: 'pou.remove', index, pou }];
      const key = pou.name.toUpperCase();
      if (p.tasks.some((t) => t.programs.some((x) => x.pou.toUpperCase() === key))) {
        const tasks = p.tasks.map((t) => ({
          ...t,
          programs: t.programs.filter((x) => x.pou.toUpperCase() !== key),
        }));
        changes.push({ type: 'tasks.update', before: p.tasks, after: tasks });
      }
      commit('deletePou', changes);
      return true;
    },
    setPouSource: (id, text, name) => {
      const pou = find(id);
      if (!pou || (pou.language !== 'ST' && pou.language !== 'IL') || pou.source === text) return false;
      commit(name, [{ type: 'pou.update', pou: id, before: { source: pou.source }, after: { source: text } }]);
      return true;
    },
    updatePou: (id, patch) => {
      const p = project();
      const pou = find(id);
      if (!pou) return false;
      const before: Partial<PouProps> = {};
      const after: Partial<PouProps> = {};
      const set = <K extends keyof PouPatch>(k: K, v: Pou[K]) => {
        if (pou[k] === v) return;
        (before as Record<string, unknown>)[k] = pou[k];
        (after as Record<string, unknown>)[k] = v;
      };
      if ('comment' in patch && patch.comment !== undefined) set('comment', patch.comment);
      const kind = patch.kind ?? pou.kind;
      if (patch.kind) set('kind', patch.kind);
      if (kind === 'FUNCTION') set('returnType', patch.returnType?.trim() || pou.returnType || 'BOOL');
      else if (pou.returnType !== undefined) set('returnType', undefined);
      if (Object.keys(after).length === 0) return false;
      const changes: Change[] = [{ type: 'pou.update', pou: id, before, after }];
      // A function's result pin or a new kind changes the calls' boxes: make room for them.
      changes.push(...makeRoomForCalls(p, applyChanges(p, changes), pou.name));
      commit('updatePou', changes);
      return true;
    },
  };
}
