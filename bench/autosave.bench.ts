// Figures for the autosave journal (issue 22, item 2.1): what one change costs the page in a
// 10,000-network project (the patch against the last snapshot and its JSON text, written to
// localStorage synchronously), beside what a full snapshot's text costs.
// Run: `npx tsx bench/autosave.bench.ts`.
import { newNetwork, newPou, newProject } from '../src/model/factory';
import type { ElementId } from '../src/model/ids';
import { createDocumentStore } from '../src/store/documentStore';
import { makeJournal, projectPatch } from '../src/editor/files/autosaveJournal';
import { median } from './median';

const NETWORKS = 10_000;
const networks = Array.from({ length: NETWORKS }, (_, i) =>
  newNetwork({
    title: `Network ${i}`,
    rows: 1,
    cols: 3,
    elements: [
      { kind: 'contact', contact: 'NO', variable: `In${i}`, id: `c${i}` as ElementId, row: 0, col: 0 },
      { kind: 'link', id: `l${i}` as ElementId, row: 0, col: 1 },
      { kind: 'coil', coil: 'COIL', variable: `Out${i}`, id: `o${i}` as ElementId, row: 0, col: 2 },
    ],
  }),
);
const store = createDocumentStore(newProject('Big', { pous: [newPou('Main', { networks })] }));
const base = store.getState().project;
let k = 0;
const perChange = median(41, () => {
  k += 1;
  store.getState().updateNetwork(networks[(k * 7919) % NETWORKS]!.id, { title: `Edited ${k}` });
  const { patch } = projectPatch(base, store.getState().project);
  JSON.stringify(makeJournal({ slot: 'a', id: 'x' }, patch, true, k));
});
const text = JSON.stringify(makeJournal({ slot: 'a', id: 'x' }, projectPatch(base, store.getState().project).patch, true, k));
const full = median(11, () => JSON.stringify(store.getState().project));
console.log(
  `${NETWORKS} networks: one change journalled in ${perChange.toFixed(2)} ms (median of 41; the command included), ` +
    `journal ${text.length} chars after ${k} changes; a full snapshot's text ${full.toFixed(1)} ms, ` +
    `${JSON.stringify(base).length} chars`,
);
