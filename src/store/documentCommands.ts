// The document commands that edit elements, networks, variables and project settings, built
// over the store's commit/editNetwork primitives (see the list at the top of documentStore.ts).
import type { LdElement } from '../model/elements';
import { elementSize, newNetwork } from '../model/factory';
import { stableLibrary } from './stableLibrary';
import { newId, type ElementId, type NetworkId, type PouId } from '../model/ids';
import type { Network, Pou, Project, Variable } from '../model/project';
import { diffNetwork, type Change, type VariableScope } from './changes';
import type { TaskCommands } from './taskCommands';
import type { DataTypeCommands } from './dataTypeCommands';
import type { DocumentState, NetworkPatch } from './documentStore';
import * as edits from './networkEdits';
import { transferElements } from './networkTransfer';
import * as units from './networkUnits';
import { followInterface } from './pouEdits';
import { declaresLocally, renameInElement } from './variableEdits';
import { stRenameEdits } from '../engine/st/services/rename';

export const newElementId = () => newId<'ElementId'>('e') as ElementId;

export function locate(
  project: Project,
  network: NetworkId,
): { pou: Pou; net: Network; index: number } | undefined {
  for (const pou of project.pous) {
    const index = pou.networks.findIndex((n) => n.id === network);
    if (index >= 0) return { pou, net: pou.networks[index]!, index };
  }
  return undefined;
}

function locateElement(
  project: Project,
  pouId: PouId,
  id: ElementId,
): { pou: Pou; net: Network; el: LdElement } | undefined {
  const pous = [...project.pous].sort((a, b) => (a.id === pouId ? -1 : b.id === pouId ? 1 : 0));
  for (const pou of pous) {
    for (const net of pou.networks) {
      const el = net.elements.find((e) => e.id === id);
      if (el) return { pou, net, el };
    }
  }
  return undefined;
}

export interface CommandOps {
  get(): DocumentState;
  commit(name: string, changes: readonly Change[]): void;
  editNetwork(name: string, network: NetworkId, fn: (n: Network) => Network | undefined): boolean;
}

type Commands = Omit<
  DocumentState,
  | 'project'
  | 'activePouId'
  | 'dirty'
  | 'revision'
  | 'opened'
  | 'history'
  | 'canUndo'
  | 'canRedo'
  | 'undoName'
  | 'redoName'
  | 'loadProject'
  | 'setWatchList'
  | 'setPlant'
  | 'newProject'
  | 'markSaved'
  | 'setActivePou'
  | 'openPouIds'
  | 'closePou'
  | 'addPou'
  | 'renamePou'
  | 'duplicatePou'
  | 'deletePou'
  | keyof DataTypeCommands
  | keyof TaskCommands
  | 'updatePou'
  | 'setPouSource'
  | 'undo'
  | 'redo'
  | 'mark'
  | 'squash'
  | 'lastStep'
  | 'joinSince'
  | 'batch'
>;

export function documentCommands({ get, commit, editNetwork }: CommandOps): Commands {
  /** The project's blocks (standard and its own FBs/functions): box sizes and pins come from it. */
  const lib = () => stableLibrary(get().project);
  const scopeVars = (
    scope: VariableScope | undefined,
  ): { scope: VariableScope; vars: readonly Variable[] } => {
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

  return {
    placeElement: (network, cell, t) => {
      const id = newElementId();
      const ok = editNetwork(
        'placeElement',
        network,
        (n) =>
          edits.placeBoxOffRail(n, cell, t, id, newElementId, lib()) ??
          edits.placeElement(n, cell, t, id, lib()) ??
          edits.insertInSeries(n, cell, t, id, lib()),
      );
      return ok ? id : undefined;
    },
    insertInSeries: (network, cell, t) => {
      const id = newElementId();
      return editNetwork(
        'insertInSeries',
        network,
        (n) =>
          edits.placeBoxOffRail(n, cell, t, id, newElementId, lib()) ??
          edits.insertInSeries(n, cell, t, id, lib()),
      )
        ? id
        : undefined;
    },
    wrapInParallelBranch: (network, ids) =>
      editNetwork('wrapInParallelBranch', network, (n) =>
        edits.wrapInParallelBranch(n, ids, newElementId, lib()),
      ),
    moveElements: (network, ids, dRow, dCol) =>
      editNetwork('moveElements', network, (n) => edits.moveElements(n, ids, dRow, dCol, lib(), newElementId)),
    moveElementsToNetwork: (from, ids, to, at) => {
      const project = get().project;
      const src = locate(project, from);
      const dst = locate(project, to);
      if (!src || !dst) return false;
      const t = transferElements(src.net, dst.net, ids, at, lib(), newElementId);
      if (!t) return false;
      commit('moveElementsToNetwork', [
        ...diffNetwork(src.pou.id, src.net, t.source),
        ...diffNetwork(dst.pou.id, dst.net, t.target),
      ]);
      return true;
    },
    deleteElements: (network, ids) => {
      editNetwork('deleteElements', network, (n) => edits.deleteElements(n, ids));
    },
    updateElement: (id, patch) => {
      const s = get();
      const found = locateElement(s.project, s.activePouId, id);
      if (!found) return;
      const after = { ...found.el, ...patch, id: found.el.id, kind: found.el.kind } as LdElement;
      // A patch that changes nothing (Enter on an unchanged name) records nothing.
      if (JSON.stringify(after) === JSON.stringify(found.el)) return;
      commit(
        'updateElement',
        diffNetwork(found.pou.id, found.net, {
          ...found.net,
          elements: found.net.elements.map((e) => (e.id === id ? after : e)),
        }),
      );
    },
    pasteElements: (network, clip, at) => {
      let ids: ElementId[] = [];
      editNetwork('pasteElements', network, (n) => {
        const r = edits.pasteElements(n, clip, at, newElementId, lib());
        ids = r.ids;
        return r.network;
      });
      return ids;
    },
    duplicateElements: (network, ids) => {
      const found = locate(get().project, network);
      const clip = found && edits.copyElements(found.net, ids, lib());
      if (!found || !clip) return [];
      const b = edits.boundsOf(
        found.net.elements.filter((e) => ids.includes(e.id)),
        lib(),
      )!;
      let out: ElementId[] = [];
      editNetwork('duplicateElements', network, (n) => {
        const below = Math.max(...n.elements.map((e) => e.row + elementSize(e, lib()).rows));
        const r = edits.pasteElements(n, clip, { row: below, col: b.left }, newElementId, lib());
        out = r.ids;
        return r.network;
      });
      return out;
    },
    addVLink: (network, v) => {
      editNetwork('addVLink', network, (n) => edits.addVLink(n, v, lib()));
    },
    removeVLink: (network, v) => {
      editNetwork('removeVLink', network, (n) => edits.removeVLink(n, v));
    },
    toggleVLink: (network, v) => {
      editNetwork('toggleVLink', network, (n) =>
        n.vlinks.some((w) => w.row === v.row && w.boundary === v.boundary)
          ? edits.removeVLink(n, v)
          : edits.addVLink(n, v, lib()),
      );
    },

    insertRow: (network, at) => {
      editNetwork('insertRow', network, (n) => edits.insertRow(n, at, lib()));
    },
    deleteRow: (network, at) => editNetwork('deleteRow', network, (n) => edits.deleteRow(n, at, lib())),
    addNetwork: (partial) => {
      const s = get();
      const pou = s.project.pous.find((p) => p.id === s.activePouId);
      return insertNetworkAt(pou?.networks.length ?? 0, partial);
    },
    insertNetwork: (index, partial) => insertNetworkAt(index, partial),
    deleteNetwork: (id) => {
      const found = locate(get().project, id);
      if (found)
        commit('deleteNetwork', [
          { type: 'network.remove', pou: found.pou.id, index: found.index, network: found.net },
        ]);
    },
    moveNetwork: (from, to) => {
      const s = get();
      const pou = s.project.pous.find((p) => p.id === s.activePouId);
      if (!pou || from === to || !pou.networks[from] || to < 0 || to >= pou.networks.length) return;
      commit('moveNetwork', [{ type: 'network.move', pou: pou.id, from, to }]);
    },
    pasteNetworks: (pouId, index, clip, mode) => {
      const project = get().project;
      const pou = project.pous.find((p) => p.id === pouId);
      if (!pou) return [];
      const prepared = units.preparePaste(project, pou, clip, mode);
      const changes = units.pasteChanges(pou, index, prepared);
      commit('pasteNetworks', [...changes, ...followInterface(project, pou.id, changes)]);
      return prepared.networks.map((n) => n.id);
    },
    duplicateNetworks: (ids, mode) => {
      const found = ids.length ? locate(get().project, ids[0]!) : undefined;
      const clip = found && units.copyNetworks(found.pou, ids);
      if (!found || !clip) return [];
      const last = Math.max(...clip.networks.map((n) => found.pou.networks.indexOf(n)));
      const prepared = units.preparePaste(get().project, found.pou, clip, mode);
      const changes = units.pasteChanges(found.pou, last + 1, prepared);
      commit('duplicateNetworks', [...changes, ...followInterface(get().project, found.pou.id, changes)]);
      return prepared.networks.map((n) => n.id);
    },
    deleteNetworks: (ids) => {
      const found = ids.length ? locate(get().project, ids[0]!) : undefined;
      if (found) commit('deleteNetworks', units.deleteChanges(found.pou, ids));
    },
    moveNetworks: (ids, delta) => {
      const found = ids.length ? locate(get().project, ids[0]!) : undefined;
      const changes = found && units.moveChanges(found.pou, ids, delta);
      if (!changes) return false;
      commit('moveNetworks', changes);
      return true;
    },
    moveNetworksTo: (ids, before) => {
      const found = ids.length ? locate(get().project, ids[0]!) : undefined;
      const changes = found && units.moveToChanges(found.pou, ids, before);
      if (!changes) return false;
      commit('moveNetworks', changes);
      return true;
    },
    replaceNetworks: (name, networks) => {
      const changes = networks.flatMap((x) => diffNetwork(x.pou, x.before, x.after));
      commit(name, changes);
      return changes.length > 0;
    },
    setCollapsed: (ids, collapsed) => {
      const s = get();
      const pou = s.project.pous.find((p) => p.id === s.activePouId);
      if (!pou) return;
      const set = ids === 'all' ? undefined : new Set(ids);
      const changes: Change[] = [];
      for (const net of pou.networks) {
        if ((set && !set.has(net.id)) || !!net.collapsed === collapsed) continue;
        const { collapsed: _c, ...rest } = net;
        changes.push(...diffNetwork(pou.id, net, collapsed ? { ...rest, collapsed: true } : rest));
      }
      commit(collapsed ? 'collapseNetworks' : 'expandNetworks', changes);
    },
    updateNetwork: (id, patch) => {
      const clean: { -readonly [K in keyof NetworkPatch]: NetworkPatch[K] } = { ...patch };
      if ('label' in clean && !clean.label?.trim()) clean.label = undefined;
      if ('collapsed' in clean && !clean.collapsed) clean.collapsed = undefined;
      editNetwork('updateNetwork', id, (n) => {
        const out: Record<string, unknown> = { ...n, ...clean };
        for (const k of Object.keys(clean) as (keyof NetworkPatch)[])
          if (clean[k] === undefined) delete out[k];
        const next = out as unknown as Network;
        return { ...next, rows: Math.max(1, next.rows), cols: Math.max(1, next.cols) };
      });
    },

    addVariable: (v, scope) => {
      const { scope: sc, vars } = scopeVars(scope);
      if (vars.some((w) => w.name.toUpperCase() === v.name.toUpperCase())) return false;
      const changes: Change[] = [{ type: 'variable.add', scope: sc, index: vars.length, variable: v }];
      commit('addVariable', [...changes, ...followInterface(get().project, sc, changes)]);
      return true;
    },
    addVariables: (vs, stepName, scope) => {
      const { scope: sc, vars } = scopeVars(scope);
      const taken = new Set(vars.map((w) => w.name.toUpperCase()));
      const changes: Change[] = [];
      for (const v of vs) {
        if (taken.has(v.name.toUpperCase())) continue;
        taken.add(v.name.toUpperCase());
        changes.push({ type: 'variable.add', scope: sc, index: vars.length + changes.length, variable: v });
      }
      if (changes.length > 0) commit(stepName, [...changes, ...followInterface(get().project, sc, changes)]);
      return changes.map((c) => (c.type === 'variable.add' ? c.variable.name : ''));
    },
    updateVariable: (name, patch, scope) => {
      const { scope: sc, vars } = scopeVars(scope);
      const index = vars.findIndex((v) => v.name.toUpperCase() === name.toUpperCase());
      const before = vars[index];
      if (!before) return false;
      const after: Variable = { ...before, ...patch };
      const renamed = after.name !== before.name;
      if (renamed && vars.some((v, i) => i !== index && v.name.toUpperCase() === after.name.toUpperCase()))
        return false;
      const changes: Change[] = [{ type: 'variable.update', scope: sc, index, before, after }];
      if (renamed) {
        for (const pou of get().project.pous) {
          // A POU's VAR_EXTERNAL of a renamed global names that global: renamed with it, uses and all.
          const external = sc === 'globals' ? pou.variables.findIndex((v) => v.varClass === 'external' && v.name.toUpperCase() === before.name.toUpperCase()) : -1;
          if (external >= 0) {
            const ext = pou.variables[external]!;
            if (pou.variables.some((v, i) => i !== external && v.name.toUpperCase() === after.name.toUpperCase())) return false;
            changes.push({ type: 'variable.update', scope: pou.id, index: external, before: ext, after: { ...ext, name: after.name } });
          }
          if (sc === 'globals' ? external < 0 && declaresLocally(pou, before.name) : pou.id !== sc) continue;
          for (const net of pou.networks) {
            const elements = net.elements.map((e) => renameInElement(e, before.name, after.name));
            changes.push(...diffNetwork(pou.id, net, { ...net, elements }));
          }
        }
        // ST bodies: the uses, and a block's pin in its callers (`Inst.Pin`, `F(Pin := …)`).
        for (const e of stRenameEdits(get().project, sc, before, after.name))
          changes.push({ type: 'pou.update', pou: e.pou, before: { source: e.before }, after: { source: e.after } });
      }
      commit('updateVariable', [
        ...changes,
        ...followInterface(get().project, sc, changes, { from: before, to: after }),
      ]);
      return true;
    },
    deleteVariable: (name, scope) => {
      const { scope: sc, vars } = scopeVars(scope);
      const index = vars.findIndex((v) => v.name.toUpperCase() === name.toUpperCase());
      const variable = vars[index];
      if (!variable) return;
      const changes: Change[] = [{ type: 'variable.remove', scope: sc, index, variable }];
      commit('deleteVariable', [...changes, ...followInterface(get().project, sc, changes)]);
    },
    reorderVariables: (names, scope) => {
      const { scope: sc, vars } = scopeVars(scope);
      const key = (n: string) => n.toUpperCase();
      const rank = new Map(names.map((n, i) => [key(n), i]));
      // Named variables in the given order; any not named keep their place after them.
      const target = [...vars].sort(
        (a, b) => (rank.get(key(a.name)) ?? names.length) - (rank.get(key(b.name)) ?? names.length),
      );
      const work = [...vars];
      const changes: Change[] = [];
      target.forEach((v, at) => {
        const from = work.indexOf(v);
        if (from === at) return;
        work.splice(from, 1);
        work.splice(at, 0, v);
        changes.push({ type: 'variable.remove', scope: sc, index: from, variable: v });
        changes.push({ type: 'variable.add', scope: sc, index: at, variable: v });
      });
      if (changes.length === 0) return false;
      commit('reorderVariables', [...changes, ...followInterface(get().project, sc, changes)]);
      return true;
    },
    setProjectProfile: (profile) => {
      const before = get().project.profile;
      if (before !== profile)
        commit('setProjectProfile', [
          { type: 'project.update', before: { profile: before }, after: { profile } },
        ]);
    },
    updateProject: (patch) => {
      const p = get().project;
      const before: { name?: string; description?: string; scenarios?: Project['scenarios']; libraries?: Project['libraries']; onlineChange?: Project['onlineChange'] } = {};
      if (patch.scenarios !== undefined) before.scenarios = p.scenarios ?? [];
      if (patch.libraries !== undefined) before.libraries = p.libraries ?? [];
      if (patch.onlineChange !== undefined) {
        if ((p.onlineChange ?? 'edit') === patch.onlineChange && Object.keys(patch).length === 1) return;
        before.onlineChange = p.onlineChange ?? 'edit';
      }
      if (patch.name !== undefined) before.name = p.name;
      if (patch.description !== undefined) before.description = p.description;
      commit('updateProject', [{ type: 'project.update', before, after: patch }]);
    },
  };
}
