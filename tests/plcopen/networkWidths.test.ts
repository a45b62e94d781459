// Each imported network is as wide as its own elements need (issue 12: "networks are as wide as
// they need to be"), its coils at its own right rail; the meaning stays exactly the file's.
import { describe, expect, it } from 'vitest';
import { elementSize } from '../../src/model/factory';
import { blockLibrary } from '../../src/model/library';
import type { Network, Project } from '../../src/model/project';
import { exportBehaviour } from '../../src/plcopen/exportBehaviour';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { connections, trace } from './behaviour';
import { bool, box, coil, contact, links, net, pou, project } from './build';
import { canonical, fixture } from './fixtures';

function load(xml: string): Project {
  const r = importPlcopen(xml);
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  expect(r.report.warnings.filter((w) => /cannot be drawn|differs/i.test(w.message))).toEqual([]);
  return r.project;
}

/** The columns a network's elements reach (at least 3, the narrowest imported network). */
function usedCols(n: Network, p: Project): number {
  const lib = blockLibrary(p);
  let cols = 3;
  for (const e of n.elements) cols = Math.max(cols, e.col + elementSize(e, lib).cols);
  for (const v of n.vlinks) cols = Math.max(cols, v.boundary);
  return cols;
}

/** Coils with nothing right of them on their row stand in the network's last column. */
function coilsAtRail(n: Network, p: Project): boolean {
  const lib = blockLibrary(p);
  return n.elements.every(
    (c) =>
      c.kind !== 'coil' ||
      c.col === n.cols - 1 ||
      n.elements.some((e) => e !== c && e.kind !== 'link' && e.row <= c.row && e.row + elementSize(e, lib).rows > c.row && e.col > c.col),
  );
}

/** A POU drawn with one shared width (as the import used to lay it out): a wide network and a narrow one. */
function sharedWidth(): Project {
  const wide = net(2, 9, [
    ...Array.from({ length: 5 }, (_, k) => contact(0, k, `B${k}`)),
    box(0, 5, 'TON', { PT: 'T#1s' }, {}, 'T1'),
    ...links(0, 7, 8),
    coil(0, 8, 'W'),
  ]);
  const narrow = net(1, 9, [contact(0, 0, 'A'), ...links(0, 1, 8), coil(0, 8, 'Q')]);
  return project([
    pou(
      'Main',
      [bool('A'), bool('Q'), bool('W'), ...Array.from({ length: 5 }, (_, k) => bool(`B${k}`)), { ...bool('T1'), type: 'TON' }],
      [wide, narrow],
    ),
  ]);
}

describe('per-network widths', () => {
  it('a wide and a narrow network: widths differ, graph and trace unchanged', () => {
    const original = sharedWidth();
    const imported = load(exportPlcopen(original));
    const [wide, narrow] = imported.pous[0]!.networks;
    expect(wide!.cols).toBeGreaterThanOrEqual(8);
    expect(narrow!.cols).toBe(3);
    for (const n of [wide!, narrow!]) {
      expect(n.cols).toBe(usedCols(n, imported));
      expect(coilsAtRail(n, imported)).toBe(true);
    }
    expect(connections(imported)).toEqual(connections(original));
    expect(trace(imported, 'Main')).toEqual(trace(original, 'Main'));
  });

  it('export and import again change nothing', () => {
    const once = load(exportPlcopen(sharedWidth()));
    const twice = load(exportPlcopen(once));
    expect(canonical(twice)).toBe(canonical(once));
  });

  it.each([
    ['corpus/godardhi0__dancinglights.xml', 'program0'],
    ['corpus/sakunamary__roaster.xml', 'program0'],
    ['corpus/estidlore__parking_automation.xml', 'Examen_Fin'],
  ])('%s: each network as wide as it needs, coils at its own rail; round trip unchanged', (file, name) => {
    const p = load(fixture(file));
    const nets = p.pous.find((x) => x.name === name)!.networks;
    expect(new Set(nets.map((n) => n.cols)).size).toBeGreaterThan(1);
    for (const n of nets) {
      expect(n.cols).toBe(usedCols(n, p));
      expect(coilsAtRail(n, p)).toBe(true);
    }
    const again = load(exportPlcopen(p));
    expect(again.pous.find((x) => x.name === name)!.networks.map((n) => n.cols)).toEqual(nets.map((n) => n.cols));
    expect(connections(again)).toEqual(connections(p));
    // The export draws networks one under another: Beremiz then runs them network by network, so
    // networks imported side by side (Network.turns, dancinglights) lose their interleaved order
    // (the export review says so, LD-X08); the program is otherwise the same.
    const plain = { ...p, pous: p.pous.map((x) => ({ ...x, networks: x.networks.map(({ turns: _t, ...n }) => n) })) };
    expect(exportBehaviour(p).some((w) => w.rule === 'LD-X08')).toBe(nets.some((n) => n.turns !== undefined));
    expect(trace(again, name)).toEqual(trace(plain, name));
  });
});
