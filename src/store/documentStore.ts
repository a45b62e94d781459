// The document store: the open project, its undo/redo history, and every edit as a named command.
//
// One store per editor: `createDocumentStore(project)`, provided by `<DocumentStoreProvider store>`,
// read with `useDocument(selector)` (use the narrow module-level selectors below, never the whole
// state) and driven with `useDocumentStore().getState().<command>(...)` (or `store.getState()`).
//
// State
//   project       the Project (plain data, src/model/project.ts)
//   activePouId   the POU shown on the canvas (not part of history)
//   dirty         true when the document changed since the last loadProject/newProject/markSaved
//   revision      increments on every document change (commands, undo, redo, load)
//   canUndo/canRedo, undoName/redoName   for menus ("Undo Place contact")
//
// Commands. Each is recorded as a list of serialisable changes (src/store/changes.ts), one undo
// step per command; a command that changes nothing records nothing. Network/element commands
// find the network by id in any POU. Commands that cannot apply return false/undefined and
// leave the document untouched.
//   loadProject(p)                    replace the document, clear history, dirty = false
//   newProject(name?)                 a fresh project with one PROGRAM "Main" and one network
//   markSaved()                       dirty = false
//   setActivePou(id)
//   placeElement(net, cell, t)        put element template `t` at `cell`; links there are replaced;
//                                     on another element it inserts in series. Returns the new id.
//   insertInSeries(net, cell, t)      always inserts in series (see src/store/networkEdits.ts)
//   wrapInParallelBranch(net, ids)    new row below with links, vertical links at both ends
//   moveElements(net, ids, dRow, dCol)   whole cells; false if blocked/off-grid (a drag commits once)
//   deleteElements(net, ids)          leaves the cells empty
//   updateElement(id, patch)          e.g. { variable: 'Start' }, { inputs: { PT: 'T#5s' } }
//   pasteElements(net, clip, cell)    clip from copyElements(); returns the new ids
//   duplicateElements(net, ids)       pastes a copy below the network's content; returns new ids
//   addVLink / removeVLink / toggleVLink (net, {row, boundary})
//   addNetwork(partial?) / insertNetwork(index, partial?)  return the new NetworkId
//   deleteNetwork(id), moveNetwork(from, to), updateNetwork(id, {label,title,comment,collapsed,rows,cols})
//                                     (label: '' or undefined removes the label)
//   addVariable(v, scope?)            false when the name is taken (case-insensitive) in that scope
//   updateVariable(name, patch, scope?)  renaming RENAMES EVERY REFERENCE too (contacts, coils,
//                                     box instances and operands incl. `Name.Pin`) in the POU, or
//                                     for a global in every POU that does not shadow it
//   deleteVariable(name, scope?)      references stay (the checks report them)
//   setProjectProfile(profile), updateProject({name, description})
//   undo(), redo()                    never touch selection (src/store/uiStore.ts)
//   mark() / squash(mark, name)       merge the steps since mark into one (e.g. a typing burst)
//   batch(name, fn)                   run several commands as one undo step
// `scope` is the active POU by default, or 'globals'.
import { createElement, createContext, useContext, type ReactNode } from 'react';
import { createStore, useStore, type StoreApi } from 'zustand';
import type { LdElement, VLink } from '../model/elements';
import { elementSize, newNetwork, newProject as makeProject } from '../model/factory';
import type { Cell } from '../model/grid';
import { newId, type ElementId, type NetworkId, type PouId } from '../model/ids';
import type { Network, Pou, Profile, Project, Variable } from '../model/project';
import { applyChanges, diffNetwork, invertChanges, type Change, type NetworkProps, type VariableScope } from './changes';
import { EMPTY_HISTORY, record, squash as squashHistory, type History } from './history';
import * as edits from './networkEdits';
import type { ClipContent, ElementTemplate } from './networkEdits';
import { declaresLocally, renameInElement } from './variableEdits';

type DistributivePatch<T> = T extends unknown ? Partial<Omit<T, 'id' | 'kind'>> : never;
/** Fields of one element kind: `{ variable: 'Start' }`, `{ inputs: { PT: 'T#5s' } }`, `{ row: 2 }`. */
export type ElementPatch = DistributivePatch<LdElement>;
export type NetworkPatch = Partial<Pick<NetworkProps, 'label' | 'title' | 'comment' | 'collapsed' | 'rows' | 'cols'>>;

export interface DocumentState {
  readonly project: Project;
  readonly activePouId: PouId;
  readonly dirty: boolean;
  readonly revision: number;
  readonly history: History;
  readonly canUndo: boolean;
  readonly canRedo: boolean;
  readonly undoName: string | undefined;
  readonly redoName: string | undefined;

  loadProject(p: Project): void;
  newProject(name?: string): void;
  markSaved(): void;
  setActivePou(id: PouId): void;

  placeElement(network: NetworkId, cell: Cell, t: ElementTemplate): ElementId | undefined;
  insertInSeries(network: NetworkId, cell: Cell, t: ElementTemplate): ElementId | undefined;
  wrapInParallelBranch(network: NetworkId, ids: readonly ElementId[]): boolean;
  moveElements(network: NetworkId, ids: readonly ElementId[], dRow: number, dCol: number): boolean;
  deleteElements(network: NetworkId, ids: readonly ElementId[]): void;
  updateElement(id: ElementId, patch: ElementPatch): void;
  pasteElements(network: NetworkId, clip: ClipContent, at: Cell): ElementId[];
  duplicateElements(network: NetworkId, ids: readonly ElementId[]): ElementId[];
  addVLink(network: NetworkId, v: VLink): void;
  removeVLink(network: NetworkId, v: VLink): void;
  toggleVLink(network: NetworkId, v: VLink): void;

  addNetwork(partial?: Partial<Network>): NetworkId;
  insertNetwork(index: number, partial?: Partial<Network>): NetworkId;
  deleteNetwork(id: NetworkId): void;
  moveNetwork(from: number, to: number): void;
  updateNetwork(id: NetworkId, patch: NetworkPatch): void;

  addVariable(v: Variable, scope?: VariableScope): boolean;
  updateVariable(name: string, patch: Partial<Variable>, scope?: VariableScope): boolean;
  deleteVariable(name: string, scope?: VariableScope): void;
  setProjectProfile(profile: Profile): void;
  updateProject(patch: Partial<Pick<Project, 'name' | 'description'>>): void;

  undo(): void;
  redo(): void;
  mark(): number;
  squash(mark: number, name: string): void;
  batch<T>(name: string, fn: () => T): T;
}

export type DocumentStore = StoreApi<DocumentState>;

const newElementId = () => newId<'ElementId'>('e') as ElementId;

function locate(project: Project, network: NetworkId): { pou: Pou; net: Network; index: number } | undefined {
  for (const pou of project.pous) {
    const index = pou.networks.findIndex((n) => n.id === network);
    if (index >= 0) return { pou, net: pou.networks[index]!, index };
  }
  return undefined;
}

function locateElement(project: Project, pouId: PouId, id: ElementId): { pou: Pou; net: Network; el: LdElement } | undefined {
  const pous = [...project.pous].sort((a, b) => (a.id === pouId ? -1 : b.id === pouId ? 1 : 0));
  for (const pou of pous) {
    for (const net of pou.networks) {
      const el = net.elements.find((e) => e.id === id);
      if (el) return { pou, net, el };
    }
  }
  return undefined;
}

const historyFlags = (history: History) => ({
  history,
  canUndo: history.undo.length > 0,
  canRedo: history.redo.length > 0,
  undoName: history.undo[history.undo.length - 1]?.name,
  redoName: history.redo[history.redo.length - 1]?.name,
});

export function createDocumentStore(initial: Project = makeProject()): DocumentStore {
  /** Inside batch(): changes collect here and are recorded once at the end. */
  let pending: { name: string; changes: Change[] } | undefined;

  return createStore<DocumentState>()((set, get) => {
    const commit = (name: string, changes: readonly Change[]) => {
      if (changes.length === 0) return;
      const s = get();
      const project = applyChanges(s.project, changes);
      if (pending) {
        pending.changes.push(...changes);
        set({ project, dirty: true, revision: s.revision + 1 });
        return;
      }
      set({ project, dirty: true, revision: s.revision + 1, ...historyFlags(record(s.history, { name, changes })) });
    };

    const editNetwork = (name: string, network: NetworkId, fn: (n: Network) => Network | undefined): boolean => {
      const found = locate(get().project, network);
      if (!found) return false;
      const after = fn(found.net);
      if (!after) return false;
      commit(name, diffNetwork(found.pou.id, found.net, after));
      return true;
    };

    const scopeVars = (scope: VariableScope | undefined): { scope: VariableScope; vars: readonly Variable[] } => {
      const s = get();
      const sc = scope ?? s.activePouId;
      if (sc === 'globals') return { scope: sc, vars: s.project.globals };
      return { scope: sc, vars: s.project.pous.find((p) => p.id === sc)?.variables ?? [] };
    };

    const insertNetworkAt = (index: number, partial?: Partial<Network>): NetworkId => {
      const s = get();
      const net = newNetwork(partial);
      const pou = s.project.pous.find((p) => p.id === s.activePouId);
      if (!pou) return net.id;
      const at = Math.max(0, Math.min(index, pou.networks.length));
      commit('insertNetwork', [{ type: 'network.add', pou: pou.id, index: at, network: net }]);
      return net.id;
    };

    const reset = (project: Project) => ({
      project,
      activePouId: project.pous[0]?.id ?? ('' as PouId),
      dirty: false,
      revision: get().revision + 1,
      ...historyFlags(EMPTY_HISTORY),
    });

    return {
      project: initial,
      activePouId: initial.pous[0]?.id ?? ('' as PouId),
      dirty: false,
      revision: 0,
      ...historyFlags(EMPTY_HISTORY),

      loadProject: (p) => set(reset(p)),
      newProject: (name) => set(reset(makeProject(name))),
      markSaved: () => set({ dirty: false }),
      setActivePou: (id) => {
        if (get().project.pous.some((p) => p.id === id)) set({ activePouId: id });
      },

      placeElement: (network, cell, t) => {
        const id = newElementId();
        const ok = editNetwork('placeElement', network, (n) => edits.placeElement(n, cell, t, id) ?? edits.insertInSeries(n, cell, t, id));
        return ok ? id : undefined;
      },
      insertInSeries: (network, cell, t) => {
        const id = newElementId();
        return editNetwork('insertInSeries', network, (n) => edits.insertInSeries(n, cell, t, id)) ? id : undefined;
      },
      wrapInParallelBranch: (network, ids) =>
        editNetwork('wrapInParallelBranch', network, (n) => edits.wrapInParallelBranch(n, ids, newElementId)),
      moveElements: (network, ids, dRow, dCol) => editNetwork('moveElements', network, (n) => edits.moveElements(n, ids, dRow, dCol)),
      deleteElements: (network, ids) => {
        editNetwork('deleteElements', network, (n) => edits.deleteElements(n, ids));
      },
      updateElement: (id, patch) => {
        const s = get();
        const found = locateElement(s.project, s.activePouId, id);
        if (!found) return;
        const after = { ...found.el, ...patch, id: found.el.id, kind: found.el.kind } as LdElement;
        commit('updateElement', diffNetwork(found.pou.id, found.net, {
          ...found.net,
          elements: found.net.elements.map((e) => (e.id === id ? after : e)),
        }));
      },
      pasteElements: (network, clip, at) => {
        let ids: ElementId[] = [];
        editNetwork('pasteElements', network, (n) => {
          const r = edits.pasteElements(n, clip, at, newElementId);
          ids = r.ids;
          return r.network;
        });
        return ids;
      },
      duplicateElements: (network, ids) => {
        const found = locate(get().project, network);
        const clip = found && edits.copyElements(found.net, ids);
        if (!found || !clip) return [];
        const b = edits.boundsOf(found.net.elements.filter((e) => ids.includes(e.id)))!;
        let out: ElementId[] = [];
        editNetwork('duplicateElements', network, (n) => {
          const below = Math.max(...n.elements.map((e) => e.row + elementSize(e).rows));
          const r = edits.pasteElements(n, clip, { row: below, col: b.left }, newElementId);
          out = r.ids;
          return r.network;
        });
        return out;
      },
      addVLink: (network, v) => {
        editNetwork('addVLink', network, (n) => edits.addVLink(n, v));
      },
      removeVLink: (network, v) => {
        editNetwork('removeVLink', network, (n) => edits.removeVLink(n, v));
      },
      toggleVLink: (network, v) => {
        editNetwork('toggleVLink', network, (n) =>
          n.vlinks.some((w) => w.row === v.row && w.boundary === v.boundary) ? edits.removeVLink(n, v) : edits.addVLink(n, v),
        );
      },

      addNetwork: (partial) => {
        const s = get();
        const pou = s.project.pous.find((p) => p.id === s.activePouId);
        return insertNetworkAt(pou?.networks.length ?? 0, partial);
      },
      insertNetwork: (index, partial) => insertNetworkAt(index, partial),
      deleteNetwork: (id) => {
        const found = locate(get().project, id);
        if (found) commit('deleteNetwork', [{ type: 'network.remove', pou: found.pou.id, index: found.index, network: found.net }]);
      },
      moveNetwork: (from, to) => {
        const s = get();
        const pou = s.project.pous.find((p) => p.id === s.activePouId);
        if (!pou || from === to || !pou.networks[from] || to < 0 || to >= pou.networks.length) return;
        commit('moveNetwork', [{ type: 'network.move', pou: pou.id, from, to }]);
      },
      updateNetwork: (id, patch) => {
        const clean: { -readonly [K in keyof NetworkPatch]: NetworkPatch[K] } = { ...patch };
        if ('label' in clean && !clean.label?.trim()) clean.label = undefined;
        if ('collapsed' in clean && !clean.collapsed) clean.collapsed = undefined;
        editNetwork('updateNetwork', id, (n) => {
          const out: Record<string, unknown> = { ...n, ...clean };
          for (const k of Object.keys(clean) as (keyof NetworkPatch)[]) if (clean[k] === undefined) delete out[k];
          const next = out as unknown as Network;
          return { ...next, rows: Math.max(1, next.rows), cols: Math.max(1, next.cols) };
        });
      },

      addVariable: (v, scope) => {
        const { scope: sc, vars } = scopeVars(scope);
        if (vars.some((w) => w.name.toUpperCase() === v.name.toUpperCase())) return false;
        commit('addVariable', [{ type: 'variable.add', scope: sc, index: vars.length, variable: v }]);
        return true;
      },
      updateVariable: (name, patch, scope) => {
        const { scope: sc, vars } = scopeVars(scope);
        const index = vars.findIndex((v) => v.name.toUpperCase() === name.toUpperCase());
        const before = vars[index];
        if (!before) return false;
        const after: Variable = { ...before, ...patch };
        const renamed = after.name !== before.name;
        if (renamed && vars.some((v, i) => i !== index && v.name.toUpperCase() === after.name.toUpperCase())) return false;
        const changes: Change[] = [{ type: 'variable.update', scope: sc, index, before, after }];
        if (renamed) {
          for (const pou of get().project.pous) {
            if (sc === 'globals' ? declaresLocally(pou, before.name) : pou.id !== sc) continue;
            for (const net of pou.networks) {
              const elements = net.elements.map((e) => renameInElement(e, before.name, after.name));
              changes.push(...diffNetwork(pou.id, net, { ...net, elements }));
            }
          }
        }
        commit('updateVariable', changes);
        return true;
      },
      deleteVariable: (name, scope) => {
        const { scope: sc, vars } = scopeVars(scope);
        const index = vars.findIndex((v) => v.name.toUpperCase() === name.toUpperCase());
        const variable = vars[index];
        if (variable) commit('deleteVariable', [{ type: 'variable.remove', scope: sc, index, variable }]);
      },
      setProjectProfile: (profile) => {
        const before = get().project.profile;
        if (before !== profile) commit('setProjectProfile', [{ type: 'project.update', before: { profile: before }, after: { profile } }]);
      },
      updateProject: (patch) => {
        const p = get().project;
        const before: { name?: string; description?: string } = {};
        if (patch.name !== undefined) before.name = p.name;
        if (patch.description !== undefined) before.description = p.description;
        commit('updateProject', [{ type: 'project.update', before, after: patch }]);
      },

      undo: () => {
        const s = get();
        const entry = s.history.undo[s.history.undo.length - 1];
        if (!entry) return;
        const history = { undo: s.history.undo.slice(0, -1), redo: [...s.history.redo, entry] };
        set({ project: applyChanges(s.project, invertChanges(entry.changes)), dirty: true, revision: s.revision + 1, ...historyFlags(history) });
      },
      redo: () => {
        const s = get();
        const entry = s.history.redo[s.history.redo.length - 1];
        if (!entry) return;
        const history = { undo: [...s.history.undo, entry], redo: s.history.redo.slice(0, -1) };
        set({ project: applyChanges(s.project, entry.changes), dirty: true, revision: s.revision + 1, ...historyFlags(history) });
      },
      mark: () => get().history.undo.length,
      squash: (mark, name) => set(historyFlags(squashHistory(get().history, mark, name))),
      batch: (name, fn) => {
        if (pending) return fn();
        pending = { name, changes: [] };
        try {
          return fn();
        } finally {
          const done = pending;
          pending = undefined;
          if (done.changes.length > 0) set(historyFlags(record(get().history, { name: done.name, changes: done.changes })));
        }
      },
    };
  });
}

// ---- narrow selectors (module-level so components re-render only when their slice changes) ----
export const selectProject = (s: DocumentState) => s.project;
export const selectActivePou = (s: DocumentState): Pou | undefined => s.project.pous.find((p) => p.id === s.activePouId);
export const selectNetworks = (s: DocumentState): readonly Network[] => selectActivePou(s)?.networks ?? [];
export const selectVariables = (s: DocumentState): readonly Variable[] => selectActivePou(s)?.variables ?? [];
export const selectGlobals = (s: DocumentState) => s.project.globals;
export const selectDirty = (s: DocumentState) => s.dirty;
export const selectRevision = (s: DocumentState) => s.revision;
export const selectCanUndo = (s: DocumentState) => s.canUndo;
export const selectCanRedo = (s: DocumentState) => s.canRedo;

// ---- React binding ----
const DocumentStoreContext = createContext<DocumentStore | null>(null);

export function DocumentStoreProvider({ store, children }: { store: DocumentStore; children?: ReactNode }) {
  return createElement(DocumentStoreContext.Provider, { value: store }, children);
}

export function useDocumentStore(): DocumentStore {
  const store = useContext(DocumentStoreContext);
  if (!store) throw new Error('useDocumentStore needs a <DocumentStoreProvider> above it');
  return store;
}

/** Subscribes to one slice of the document: `useDocument(selectNetworks)`. */
export function useDocument<T>(selector: (s: DocumentState) => T): T {
  return useStore(useDocumentStore(), selector);
}
