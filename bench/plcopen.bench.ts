// npm run bench:plcopen — PLCopen import and export time for a generated program of 10,000
// networks (series and parallel contacts, set/reset coils, one TON and one CTU every 10 networks)
// and for the largest real file of the corpus (../shared/plcopen/examples, if present).
// Each figure is the median of several runs after a warm-up. Target: 10,000 networks imported in < 1 s.
// Also printed: the import with every network laid out on its own (no layouts shared between
// networks of one shape).
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { BoxElement, CoilType, ContactType, LdElement, VLink } from '../src/model/elements';
import { newNetwork, newPou, newProject, variable } from '../src/model/factory';
import { newId, type ElementId } from '../src/model/ids';
import type { Network, Project, Variable } from '../src/model/project';
import { exportPlcopen } from '../src/plcopen/exportPlcopen';
import { importPlcopen } from '../src/plcopen/importPlcopen';

const eid = () => newId<'ElementId'>('e') as ElementId;
const COLS = 8;
const links = (row: number, from: number, to: number): LdElement[] =>
  Array.from({ length: to - from }, (_, i) => ({ id: eid(), kind: 'link', row, col: from + i }));

/** A contact into a block into a coil, on row 0 (the block's other pins take operands). */
function blockNetwork(
  rows: number,
  contact: ContactType,
  variable: string,
  box: Pick<BoxElement, 'blockType' | 'instance' | 'inputs' | 'outputs'>,
  coil: CoilType,
  out: string,
): Network {
  const elements: LdElement[] = [
    { id: eid(), kind: 'contact', contact, variable, row: 0, col: 0 },
    { id: eid(), kind: 'box', row: 0, col: 1, ...box },
    ...links(0, 3, COLS - 1),
    { id: eid(), kind: 'coil', coil, variable: out, row: 0, col: COLS - 1 },
  ];
  return newNetwork({ rows, cols: COLS, elements, vlinks: [] });
}

function network(i: number): Network {
  const v = (k: number) => `X${(i * 7 + k) % 500}`;
  const out = `Y${i % 300}`;
  if (i % 10 === 5)
    return blockNetwork(
      2,
      'NO',
      v(1),
      { blockType: 'TON', instance: `T${i}`, inputs: { PT: 'T#500ms' }, outputs: {} },
      'COIL',
      out,
    );
  if (i % 10 === 9)
    return blockNetwork(
      3,
      'P',
      v(1),
      { blockType: 'CTU', instance: `C${i}`, inputs: { R: v(2), PV: '10' }, outputs: { CV: `N${i % 50}` } },
      'SET',
      out,
    );
  const elements: LdElement[] = [];
  const vlinks: VLink[] = [];
  // (A OR B) AND NOT C AND D -> coil, with a parallel reset coil.
  elements.push(
    { id: eid(), kind: 'contact', contact: 'NO', variable: v(1), row: 0, col: 0 },
    { id: eid(), kind: 'contact', contact: 'NO', variable: v(2), row: 1, col: 0 },
    { id: eid(), kind: 'contact', contact: 'NC', variable: v(3), row: 0, col: 1 },
    { id: eid(), kind: 'contact', contact: 'NO', variable: v(4), row: 0, col: 2 },
    ...links(0, 3, COLS - 1),
    { id: eid(), kind: 'coil', coil: 'COIL', variable: out, row: 0, col: COLS - 1 },
    ...links(1, 3, COLS - 1),
    { id: eid(), kind: 'coil', coil: 'RESET', variable: `Y${(i + 1) % 300}`, row: 1, col: COLS - 1 },
  );
  vlinks.push({ row: 0, boundary: 1 }, { row: 0, boundary: 3 });
  return newNetwork({ rows: 2, cols: COLS, elements, vlinks });
}

function program(n: number): Project {
  const vars: Variable[] = [];
  for (let k = 0; k < 500; k++) vars.push(variable(`X${k}`, 'BOOL'));
  for (let k = 0; k < 300; k++) vars.push(variable(`Y${k}`, 'BOOL'));
  for (let k = 0; k < 50; k++) vars.push(variable(`N${k}`, 'INT'));
  for (let i = 0; i < n; i++) {
    if (i % 10 === 5) vars.push(variable(`T${i}`, 'TON'));
    if (i % 10 === 9) vars.push(variable(`C${i}`, 'CTU'));
  }
  const networks = Array.from({ length: n }, (_, i) => network(i));
  const main = newPou('Main', { variables: vars, networks });
  return newProject('Bench', {
    pous: [main],
    tasks: [{ name: 'MainTask', cycleMs: 10, priority: 1, programs: [{ instance: 'I', pou: 'Main' }] }],
  });
}

function median(f: () => void, runs: number): number {
  f(); // warm-up
  const times: number[] = [];
  for (let i = 0; i < runs; i++) {
    const t0 = performance.now();
    f();
    times.push(performance.now() - t0);
  }
  times.sort((a, b) => a - b);
  return times[Math.floor(times.length / 2)]!;
}

const fmt = (ms: number) => (ms < 10 ? ms.toFixed(2) : ms.toFixed(0));

const project = program(10_000);
let xml = '';
const exportMs = median(() => (xml = exportPlcopen(project)), 5);
let networks = 0;
const importMs = median(() => {
  const r = importPlcopen(xml);
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  networks = r.project.pous[0]!.networks.length;
}, 5);
// The generated program repeats a few rung shapes, as large real programs do, and networks of one
// shape share their layout. Without that sharing every network is laid out on its own: the time a
// program whose 10,000 rungs all differ would take.
const unsharedMs = median(() => {
  const r = importPlcopen(xml, { shareLayouts: false });
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
}, 5);
console.log(`generated program: 10,000 networks, ${(xml.length / 1e6).toFixed(1)} MB of XML`);
console.log(
  `  export ${fmt(exportMs)} ms   import ${fmt(importMs)} ms (${networks} networks back; target < 1000 ms)`,
);
console.log(
  `  import without shared layouts ${fmt(unsharedMs)} ms (${(unsharedMs / importMs).toFixed(2)}x; every network laid out on its own)`,
);

const corpus = join(fileURLToPath(new URL('..', import.meta.url)), '..', 'shared', 'plcopen', 'examples');
if (existsSync(corpus)) {
  const largest = readdirSync(corpus)
    .filter((f) => f.endsWith('.xml'))
    .map((f) => ({ f, size: statSync(join(corpus, f)).size }))
    .sort((a, b) => b.size - a.size)[0]!;
  const text = readFileSync(join(corpus, largest.f), 'utf8');
  let imported: Project | undefined;
  const ci = median(() => {
    const r = importPlcopen(text);
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    imported = r.project;
  }, 9);
  const ce = median(() => exportPlcopen(imported!), 9);
  console.log(`largest corpus file: ${largest.f} (${(largest.size / 1024).toFixed(0)} KB)`);
  console.log(`  import ${fmt(ci)} ms   export ${fmt(ce)} ms`);
} else console.log(`corpus not found at ${corpus}: skipped`);

console.log(`bench:plcopen import-10k-ms=${Math.round(importMs)} export-10k-ms=${Math.round(exportMs)}`);
