// The canvas layout keeps each network's measures (row pitch, height, needed width) per network
// object, library and symbol lookup: an edit lays out again only the networks it replaced. These
// tests check that the memoised layout always equals one made from fresh copies of the networks.
import { describe, expect, it } from 'vitest';
import { layoutNetworks, networkMeasures, type CanvasLayout } from '../../src/editor/canvas/geometry';
import { symbolCommentLookup } from '../../src/editor/canvas/symbolComments';
import { blockLibrary } from '../../src/model/library';
import type { Network } from '../../src/model/project';
import { variable } from '../../src/model/factory';
import { sealInProject } from '../e2e/sealInProject';

const plain = (l: CanvasLayout) => ({
  tops: [...l.tops],
  heights: [...l.heights],
  pitches: [...l.pitches],
  totalHeight: l.totalHeight,
  totalWidth: l.totalWidth,
});
/** The layout of copies of the networks (new objects: nothing memoised applies). */
const fresh = (
  networks: readonly Network[],
  ...rest: Parameters<typeof layoutNetworks> extends [unknown, ...infer R] ? R : never
) => plain(layoutNetworks(structuredClone(networks), ...rest));

describe('the canvas layout memoised per network', () => {
  const project = sealInProject(30);
  const library = blockLibrary(project);
  const base = project.pous[0]!.networks;

  it('an edited network is measured again; the others keep their measures', () => {
    const first = layoutNetworks(base, library);
    expect(plain(first)).toEqual(fresh(base, library));
    const kept = networkMeasures(base[0]!, library);
    const edited = base.map((n, i) =>
      i === 3
        ? { ...n, title: `${n.title} with a title long enough to widen the whole canvas beyond its grid` }
        : n,
    );
    const second = layoutNetworks(edited, library);
    expect(plain(second)).toEqual(fresh(edited, library));
    expect(second.totalWidth).toBeGreaterThan(first.totalWidth);
    expect(networkMeasures(edited[0]!, library)).toBe(kept);
  });

  it('a comment, a collapse and room asked for below a rung change the tops of the networks below', () => {
    const edited = base.map((n, i) =>
      i === 1
        ? { ...n, comment: 'line one\nline two\nline three' }
        : i === 2
          ? { ...n, collapsed: true }
          : n,
    );
    // The keyboard cursor went below network 4's rung: it shows 5 rows (its grid keeps its own).
    const room = { network: base[4]!.id, rows: 5 };
    const before = layoutNetworks(base, library);
    const after = layoutNetworks(edited, library, undefined, room);
    expect(plain(after)).toEqual(fresh(edited, library, undefined, room));
    expect(after.heights[1]).toBeGreaterThan(before.heights[1]!);
    expect(after.heights[2]).toBeLessThan(before.heights[2]!);
    expect(after.heights[4]).toBeGreaterThan(before.heights[4]!);
    expect(after.tops[5]).not.toBe(before.tops[5]);
  });

  it('another symbol lookup or library measures the same network objects again', () => {
    const variables = [...project.pous[0]!.variables];
    variables[0] = variable(variables[0]!.name, 'BOOL', { comment: 'Start push button of line 0' });
    const symbols = symbolCommentLookup(variables, []);
    const without = layoutNetworks(base, library);
    const withComments = layoutNetworks(base, library, symbols);
    expect(plain(withComments)).toEqual(fresh(base, library, symbols));
    expect(withComments.pitches[0]).toBeGreaterThan(without.pitches[0]!);
    // Back to no lookup: the first measures again, not the lookup's.
    expect(plain(layoutNetworks(base, library))).toEqual(plain(without));
    const other = blockLibrary({ ...project });
    expect(plain(layoutNetworks(base, other))).toEqual(fresh(base, other));
  });
});
