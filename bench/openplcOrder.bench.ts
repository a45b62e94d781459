// npx tsx bench/openplcOrder.bench.ts — the cost of the openplc profile's order (LD-SEMANTICS.md
// section 6: each coil re-reads its path, late blocks at the end of the body) against the iec
// order on the same generated program: compile time, operations, power-flow nets and scan time.
// Each network: a branch of three contacts shared by two coils, a seal-in; every 10th a TON whose
// Q reaches only the rail (a late block under openplc) read by a contact in the next network.
// Prints, per size, the openplc / iec ratio of the scan times measured in this run. The late
// blocks run as units of their own called by the body's last network (codegen.ts lateUnits);
// written into that network, 10,000 networks' 1,000 late TONs made one 400 KB function that V8
// never optimised (openplc 9x iec).
import type { LdElement, VLink } from '../src/model/elements';
import { newNetwork, newPou, newProject, variable } from '../src/model/factory';
import type { ElementId } from '../src/model/ids';
import type { Network, Profile, Project } from '../src/model/project';
import { compileProgram, createPlc } from '../src/engine/plc';

let ids = 0;
const id = () => `b${++ids}` as ElementId;
const contact = (row: number, col: number, v: string): LdElement => ({ id: id(), kind: 'contact', row, col, contact: 'NO', variable: v });
const coil = (row: number, col: number, v: string): LdElement => ({ id: id(), kind: 'coil', row, col, coil: 'COIL', variable: v });
const link = (row: number, col: number): LdElement => ({ id: id(), kind: 'link', row, col });

function network(k: number): Network {
  const I = (n: number) => `I${(k * 3 + n) % 64}`;
  if (k % 10 === 9) {
    const box: LdElement = { id: id(), kind: 'box', row: 0, col: 1, blockType: 'TON', instance: `T${k}`, inputs: { PT: 'T#50ms' }, outputs: {} };
    return newNetwork({ rows: 2, cols: 4, elements: [contact(0, 0, I(0)), box, link(0, 3)], vlinks: [] });
  }
  const first = k % 10 === 0 && k > 0 ? `T${k - 1}.Q` : I(0);
  // Rail - A - B + - C - (Xk)      the branch A-B read by both coils
  //              + - (Yk)          and a seal-in on Xk
  const elements = [contact(0, 0, first), contact(0, 1, I(1)), contact(0, 2, I(2)), coil(0, 3, `X${k}`), link(1, 2), coil(1, 3, `Y${k}`), contact(2, 0, `X${k}`), link(2, 1)];
  const vlinks: VLink[] = [{ row: 0, boundary: 2 }, { row: 1, boundary: 2 }];
  return newNetwork({ rows: 3, cols: 4, elements, vlinks: [...vlinks, { row: 0, boundary: 0 }, { row: 1, boundary: 0 }] });
}

function project(count: number, profile: Profile): Project {
  const variables = [
    ...Array.from({ length: 64 }, (_, i) => variable(`I${i}`, 'BOOL')),
    ...Array.from({ length: count }, (_, k) => [variable(`X${k}`, 'BOOL'), variable(`Y${k}`, 'BOOL')]).flat(),
    ...Array.from({ length: count }, (_, k) => k).filter((k) => k % 10 === 9).map((k) => variable(`T${k}`, 'TON')),
  ];
  return newProject('bench', { pous: [newPou('Main', { variables, networks: Array.from({ length: count }, (_, k) => network(k)) })], profile });
}

for (const count of [1_000, 10_000]) {
  const scanUs: Partial<Record<Profile, number>> = {};
  for (const profile of ['iec', 'openplc'] as const) {
    const t0 = performance.now();
    const { program, diagnostics } = compileProgram(project(count, profile));
    if (!program) throw new Error(diagnostics.find((d) => d.severity === 'error')?.message);
    const plc = createPlc(program, { cycleMs: 10, maxScanMs: 60_000 });
    const compileMs = performance.now() - t0;
    const ops = program.networks.reduce((n, ir) => n + ir.ops.length + (ir.late?.length ?? 0), 0);
    const nets = program.networks.reduce((n, ir) => n + ir.netCount, 0);
    const scans = count >= 10_000 ? 200 : 2_000;
    plc.scans(scans * 5); // warm up (tiering moves segments to straight-line code)
    let best = Infinity;
    for (let round = 0; round < 5; round++) {
      const t = performance.now();
      plc.scans(scans);
      best = Math.min(best, performance.now() - t);
    }
    scanUs[profile] = (best * 1000) / scans;
    console.log(
      `${count} networks, ${profile.padEnd(7)}: compile ${compileMs.toFixed(0)} ms, ${ops} operations, ${nets} power-flow nets, scan ${scanUs[profile].toFixed(1)} µs (${((best * 1e6) / (scans * count)).toFixed(1)} ns per network)`,
    );
  }
  console.log(`${count} networks: scan openplc / iec = ${(scanUs.openplc! / scanUs.iec!).toFixed(2)}x`);
}
