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
//   setActivePou(id)                  shows the POU on the canvas and opens its tab
//   closePou(id)                      closes its tab (the last open tab stays)
//   openPouIds                        the POUs open as tabs above the canvas (not part of history)
//   addPou(kind, name?, language?, run?)  a new PROGRAM / FUNCTION_BLOCK / FUNCTION with one network
//                                     (or, language 'ST', an empty ST body), opened; a new PROGRAM runs
//                                     in a task of its own, a chosen one or none (RunIn; default: the first task)
//   renamePou(id, name)               references follow: calls' blockType, instance variable types
//                                     (POUs and globals), task program entries; false if the name
//                                     is taken or not an identifier (pouNameProblem)
//   duplicatePou(id)                  a copy "<name>_copy" with new ids, opened
//   deletePou(id)                     also drops its task entries; calls stay (checks report them);
//                                     never the last POU (see pouUsages() for what uses it)
//   updatePou(id, {comment, kind, returnType})   a FUNCTION always has a return type
//   setPouSource(id, text, name)      the body text of an ST/IL POU, one step named `name`
//   addDataType(kind, name?) / renameDataType(name, to) / duplicateDataType(name) /
//   deleteDataType(name) / updateDataType(name, {def, initial, comment})   user data types
//                                     (src/store/dataTypeCommands.ts); a rename retypes every
//                                     declaration, return type and data type naming it
//   Editing the variables of a FUNCTION_BLOCK/FUNCTION updates its calls: a renamed interface
//   variable renames the pin's operands on every box and `Instance.Pin` operands; a box that grows
//   (new pin) gets room (rows inserted below it when something is in the way).
//   placeElement(net, cell, t)        put element template `t` at `cell`; links there are replaced;
//                                     on another element it inserts in series. Returns the new id.
//   insertInSeries(net, cell, t)      always inserts in series (see src/store/networkEdits.ts)
//   wrapInParallelBranch(net, ids)    new row below with links, vertical links at both ends
//   moveElements(net, ids, dRow, dCol)   whole cells; false if blocked/off-grid (a drag commits once)
//   moveElementsToNetwork(from, ids, to, at)  drag into another network: the selection's top-left
//                                     goes to cell `at` of `to`, one undo step (src/store/networkTransfer.ts)
//   deleteElements(net, ids)          leaves the cells empty
//   updateElement(id, patch)          e.g. { variable: 'Start' }, { inputs: { PT: 'T#5s' } }
//   pasteElements(net, clip, cell)    clip from copyElements(); returns the new ids
//   duplicateElements(net, ids)       pastes a copy below the network's content; returns new ids
//   addVLink / removeVLink / toggleVLink (net, {row, boundary})
//   insertRow(net, at)                empty row at `at`, vertical links crossing it extended
//   deleteRow(net, at)                only an empty row; false otherwise
//   addNetwork(partial?) / insertNetwork(index, partial?)  return the new NetworkId
//   deleteNetwork(id), moveNetwork(from, to), updateNetwork(id, {label,title,comment,collapsed,rows,cols})
//                                     (label: '' or undefined removes the label)
//   pasteNetworks(pou, index, clip, mode)  whole networks (src/store/networkUnits.ts): new ids,
//                                     labels kept unique (jumps follow), FB instances kept or
//                                     renamed to the next free name ('keep' | 'new'), missing
//                                     declarations added; returns the new ids. One undo step.
//   duplicateNetworks(ids, mode)      a copy of the networks below the last of them
//   deleteNetworks(ids), moveNetworks(ids, ±1), moveNetworksTo(ids, before)  sets of networks
//   setCollapsed(ids | 'all', collapsed)  collapse/expand networks of the shown POU
//   replaceNetworks(name, [{pou, before, after}])  networks of any POUs rewritten (find/replace,
//                                     src/store/find.ts) as one undo step
//   addVariable(v, scope?)            false when the name is taken (case-insensitive) in that scope
//   updateVariable(name, patch, scope?)  renaming RENAMES EVERY REFERENCE too (contacts, coils,
//                                     box instances and operands incl. `Name.Pin`, ST bodies) in the
//                                     POU, or for a global in every POU that does not shadow it
//   deleteVariable(name, scope?)      references stay (the checks report them)
//   reorderVariables(names, scope?)   the variables in this order (by name; others after them);
//                                     false when already so (the declaration text's order)
//   setProjectProfile(profile), updateProject({name, description})
//   undo(), redo()                    never touch selection (src/store/uiStore.ts)
//   mark() / squash(mark, name)       merge the steps since mark into one (e.g. a typing burst)
//   lastStep() / joinSince(step, name)  the newest undo step (an opaque token), and merging it with
//                                     every step after it into one (placing + naming an element)
//   batch(name, fn)                   run several commands as one undo step
// `scope` is the active POU by default, or 'globals'.
import { createElement, createContext, useContext, type ReactNode } from 'react';
import { createStore, useStore, type StoreApi } from 'zustand';
import type { LdElement, VLink } from '../model/elements';
import { newProject as makeProject } from '../model/factory';
import { stableLibrary } from './stableLibrary';
import type { Cell } from '../model/grid';
import type { ElementId, NetworkId, PouId } from '../model/ids';
import type { Network, Pou, Profile, Project, ProjectPlant, Variable } from '../model/project';
import {
  applyChanges,
  diffNetwork,
  invertChanges,
  type Change,
  type NetworkProps,
  type VariableScope,
} from './changes';
import { documentCommands, locate } from './documentCommands';
import { pouCommands, type PouCommands } from './pouCommands';
import { dataTypeCommands, type DataTypeCommands } from './dataTypeCommands';
import { taskCommands, type TaskCommands } from './taskCommands';
import {
  EMPTY_HISTORY,
  record,
  squash as squashHistory,
  squashFrom,
  type History,
  type HistoryEntry,
} from './history';
import type { ClipContent, ElementTemplate } from './networkEdits';
import type { InstanceMode, NetworkClip } from './networkUnits';

type DistributivePatch<T> = T extends unknown ? Partial<Omit<T, 'id' | 'kind'>> : never;
/** Fields of one element kind: `{ variable: 'Start' }`, `{ inputs: { PT: 'T#5s' } }`, `{ row: 2 }`. */
export type ElementPatch = DistributivePatch<LdElement>;
export type NetworkPatch = Partial<
  Pick<NetworkProps, 'label' | 'title' | 'comment' | 'collapsed' | 'rows' | 'cols'>
>;

export interface DocumentState {
  readonly project: Project;
  readonly activePouId: PouId;
  readonly openPouIds: readonly PouId[];
  readonly dirty: boolean;
  readonly revision: number;
  /** Increments when another project is opened (loadProject, newProject), not on edits. */
  readonly opened: number;
  readonly history: History;
  readonly canUndo: boolean;
  readonly canRedo: boolean;
  readonly undoName: string | undefined;
  readonly redoName: string | undefined;

  loadProject(p: Project): void;
  /** The simulator's watch list kept with the project (not an undo step: no edit of the program). */
  setWatchList(names: readonly string[]): void;
  /**
   * The machine the simulator runs against and its changed addresses, kept with the project: one
   * undo step named `name` (choosing a machine or rewiring a point is what the user undoes next;
   * without a step of its own Undo would take back the edit before it instead). No step when
   * nothing changes.
   */
  setPlant(plant: ProjectPlant | undefined, name?: string): void;
  newProject(name?: string): void;
  markSaved(): void;
  setActivePou(id: PouId): void;
  closePou(id: PouId): void;
  addPou: PouCommands['addPou'];
  renamePou: PouCommands['renamePou'];
  duplicatePou: PouCommands['duplicatePou'];
  deletePou: PouCommands['deletePou'];
  updatePou: PouCommands['updatePou'];
  setPouSource: PouCommands['setPouSource'];
  addDataType: DataTypeCommands['addDataType'];
  renameDataType: DataTypeCommands['renameDataType'];
  duplicateDataType: DataTypeCommands['duplicateDataType'];
  deleteDataType: DataTypeCommands['deleteDataType'];
  updateDataType: DataTypeCommands['updateDataType'];
  setTasks: TaskCommands['setTasks'];
  addTask: TaskCommands['addTask'];
  deleteTask: TaskCommands['deleteTask'];
  addProgramInstance: TaskCommands['addProgramInstance'];

  placeElement(network: NetworkId, cell: Cell, t: ElementTemplate): ElementId | undefined;
  insertInSeries(network: NetworkId, cell: Cell, t: ElementTemplate): ElementId | undefined;
  wrapInParallelBranch(network: NetworkId, ids: readonly ElementId[]): boolean;
  moveElements(network: NetworkId, ids: readonly ElementId[], dRow: number, dCol: number): boolean;
  moveElementsToNetwork(from: NetworkId, ids: readonly ElementId[], to: NetworkId, at: Cell): boolean;
  deleteElements(network: NetworkId, ids: readonly ElementId[]): void;
  updateElement(id: ElementId, patch: ElementPatch): void;
  pasteElements(network: NetworkId, clip: ClipContent, at: Cell): ElementId[];
  duplicateElements(network: NetworkId, ids: readonly ElementId[]): ElementId[];
  addVLink(network: NetworkId, v: VLink): void;
  removeVLink(network: NetworkId, v: VLink): void;
  toggleVLink(network: NetworkId, v: VLink): void;
  insertRow(network: NetworkId, at: number): void;
  deleteRow(network: NetworkId, at: number): boolean;

  addNetwork(partial?: Partial<Network>): NetworkId;
  insertNetwork(index: number, partial?: Partial<Network>): NetworkId;
  deleteNetwork(id: NetworkId): void;
  moveNetwork(from: number, to: number): void;
  updateNetwork(id: NetworkId, patch: NetworkPatch): void;
  pasteNetworks(pou: PouId, index: number, clip: NetworkClip, mode: InstanceMode): NetworkId[];
  duplicateNetworks(ids: readonly NetworkId[], mode: InstanceMode): NetworkId[];
  deleteNetworks(ids: readonly NetworkId[]): void;
  moveNetworks(ids: readonly NetworkId[], delta: number): boolean;
  moveNetworksTo(ids: readonly NetworkId[], before: number): boolean;
  setCollapsed(ids: readonly NetworkId[] | 'all', collapsed: boolean): void;
  replaceNetworks(
    name: string,
    networks: readonly { pou: PouId; before: Network; after: Network }[],
  ): boolean;

  addVariable(v: Variable, scope?: VariableScope): boolean;
  /**
   * Adds several variables as one undo step named `stepName` (Declare the machine's I/O). Those
   * whose name is taken in the scope are left out; returns the names added.
   */
  addVariables(vs: readonly Variable[], stepName: string, scope?: VariableScope): string[];
  updateVariable(name: string, patch: Partial<Variable>, scope?: VariableScope): boolean;
  deleteVariable(name: string, scope?: VariableScope): void;
  reorderVariables(names: readonly string[], scope?: VariableScope): boolean;
  setProjectProfile(profile: Profile): void;
  updateProject(patch: Partial<Pick<Project, 'name' | 'description' | 'scenarios' | 'libraries' | 'onlineChange'>>): void;

  undo(): void;
  redo(): void;
  mark(): number;
  squash(mark: number, name: string): void;
  lastStep(): HistoryEntry | undefined;
  joinSince(step: HistoryEntry | undefined, name: string): void;
  batch<T>(name: string, fn: () => T): T;
}

export type DocumentStore = StoreApi<DocumentState>;

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
  /** joinSince() called inside batch(): applied once the batch's step is recorded. */
  let joinAfterBatch: { step: HistoryEntry; name: string } | undefined;

  return createStore<DocumentState>()((set, get) => {
    const commit = (name: string, changes: readonly Change[]) => {
      if (changes.length === 0) return;
      const s = get();
      const project = applyChanges(s.project, changes);
      if (pending) {
        pending.changes.push(...changes);
        set({ project, dirty: true, revision: s.revision + 1, ...viewOf(s, project) });
        return;
      }
      set({
        project,
        dirty: true,
        revision: s.revision + 1,
        ...viewOf(s, project),
        ...historyFlags(record(s.history, { name, changes })),
      });
    };
    const open = (id: PouId) => {
      const s = get();
      if (!s.project.pous.some((p) => p.id === id)) return;
      set({ activePouId: id, openPouIds: s.openPouIds.includes(id) ? s.openPouIds : [...s.openPouIds, id] });
    };

    const editNetwork = (
      name: string,
      network: NetworkId,
      fn: (n: Network) => Network | undefined,
    ): boolean => {
      const found = locate(get().project, network);
      if (!found) return false;
      const after = fn(found.net);
      if (!after) return false;
      commit(name, diffNetwork(found.pou.id, found.net, after));
      return true;
    };

    const reset = (project: Project) => ({
      project,
      activePouId: project.pous[0]?.id ?? ('' as PouId),
      openPouIds: project.pous[0] ? [project.pous[0].id] : [],
      dirty: false,
      revision: get().revision + 1,
      opened: get().opened + 1,
      ...historyFlags(EMPTY_HISTORY),
    });

    return {
      project: initial,
      activePouId: initial.pous[0]?.id ?? ('' as PouId),
      openPouIds: initial.pous[0] ? [initial.pous[0].id] : [],
      dirty: false,
      revision: 0,
      opened: 0,
      ...historyFlags(EMPTY_HISTORY),

      loadProject: (p) => set(reset(p)),
      setWatchList: (names) => {
        const s = get();
        const { watch: _old, ...rest } = s.project;
        const project: Project = names.length > 0 ? { ...rest, watch: [...names] } : rest;
        set({ project, dirty: true, revision: s.revision + 1 });
      },
      setPlant: (plant, name) => {
        const before = get().project.plant;
        if (JSON.stringify(before ?? null) === JSON.stringify(plant ?? null)) return;
        commit(name ?? (plant ? 'Choose the machine' : 'Choose no machine'), [
          { type: 'project.update', before: { plant: before }, after: { plant } },
        ]);
      },
      newProject: (name) => set(reset(makeProject(name))),
      markSaved: () => set({ dirty: false }),
      setActivePou: open,
      closePou: (id) => {
        const s = get();
        const i = s.openPouIds.indexOf(id);
        if (i < 0 || s.openPouIds.length <= 1) return;
        const openPouIds = s.openPouIds.filter((x) => x !== id);
        const activePouId = s.activePouId === id ? openPouIds[Math.max(0, i - 1)]! : s.activePouId;
        set({ openPouIds, activePouId });
      },

      ...documentCommands({ get, commit, editNetwork }),
      ...pouCommands({ project: () => get().project, commit, open }),
      ...dataTypeCommands({ project: () => get().project, commit }),
      ...taskCommands({ project: () => get().project, commit }),

      undo: () => {
        const s = get();
        const entry = s.history.undo[s.history.undo.length - 1];
        if (!entry) return;
        const history = { undo: s.history.undo.slice(0, -1), redo: [...s.history.redo, entry] };
        const project = applyChanges(s.project, invertChanges(entry.changes));
        set({
          project,
          ...viewOf(s, project),
          dirty: true,
          revision: s.revision + 1,
          ...historyFlags(history),
        });
      },
      redo: () => {
        const s = get();
        const entry = s.history.redo[s.history.redo.length - 1];
        if (!entry) return;
        const history = { undo: [...s.history.undo, entry], redo: s.history.redo.slice(0, -1) };
        const project = applyChanges(s.project, entry.changes);
        set({
          project,
          ...viewOf(s, project),
          dirty: true,
          revision: s.revision + 1,
          ...historyFlags(history),
        });
      },
      mark: () => get().history.undo.length,
      squash: (mark, name) => set(historyFlags(squashHistory(get().history, mark, name))),
      lastStep: () => get().history.undo[get().history.undo.length - 1],
      joinSince: (step, name) => {
        if (step && pending) joinAfterBatch = { step, name };
        else if (step) set(historyFlags(squashFrom(get().history, step, name)));
      },
      batch: (name, fn) => {
        if (pending) return fn();
        pending = { name, changes: [] };
        try {
          return fn();
        } finally {
          const done = pending;
          pending = undefined;
          if (done.changes.length > 0)
            set(historyFlags(record(get().history, { name: done.name, changes: done.changes })));
          const join = joinAfterBatch;
          joinAfterBatch = undefined;
          if (join) set(historyFlags(squashFrom(get().history, join.step, join.name)));
        }
      },
    };
  });
}

/** Open tabs and the shown POU kept to POUs that exist (after a delete, or undoing an add). */
function viewOf(s: DocumentState, project: Project): Pick<DocumentState, 'activePouId' | 'openPouIds'> {
  const exists = (id: PouId) => project.pous.some((p) => p.id === id);
  if (exists(s.activePouId) && s.openPouIds.every(exists))
    return { activePouId: s.activePouId, openPouIds: s.openPouIds };
  const openPouIds = s.openPouIds.filter(exists);
  const activePouId = exists(s.activePouId)
    ? s.activePouId
    : (openPouIds[openPouIds.length - 1] ?? project.pous[0]?.id ?? ('' as PouId));
  if (activePouId && !openPouIds.includes(activePouId)) openPouIds.push(activePouId);
  return { activePouId, openPouIds };
}

// ---- narrow selectors (module-level so components re-render only when their slice changes) ----
export const selectProject = (s: DocumentState) => s.project;
export const selectActivePou = (s: DocumentState): Pou | undefined =>
  s.project.pous.find((p) => p.id === s.activePouId);
const NO_NETWORKS: readonly Network[] = [];
const NO_VARIABLES: readonly Variable[] = [];
export const selectNetworks = (s: DocumentState): readonly Network[] =>
  selectActivePou(s)?.networks ?? NO_NETWORKS;
export const selectVariables = (s: DocumentState): readonly Variable[] =>
  selectActivePou(s)?.variables ?? NO_VARIABLES;
export const selectGlobals = (s: DocumentState) => s.project.globals;
export const selectOpenPouIds = (s: DocumentState) => s.openPouIds;
export const selectActivePouId = (s: DocumentState) => s.activePouId;
/**
 * The project's block library (standard blocks and its own FBs and functions): the same object
 * while no block interface changes (stableLibrary.ts), so an edit redraws only what it changed.
 */
export const selectLibrary = (s: DocumentState) => stableLibrary(s.project);
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
