// Autosave keeps the last change: a reload at any moment after a change (or an undo) brings the
// project back as it was, not an older one (issue 22, 2.1). Run against the real server.
import { expect, test } from 'vitest';
import { openApp, useChromium, waitForApp } from './appPage';
import { DrawPage } from './drawPage';
import { EditorPage } from './panelsPage';
import { sealInProject } from './sealInProject';

const browser = useChromium();

/** Delays before the reload, ms: spread over 0–1.5 s, from a seed printed so a failure can be replayed. */
function delays(seed: number, count: number): number[] {
  let s = seed;
  return Array.from({ length: count }, (_, i) => {
    s = (s * 1103515245 + 12345) % 2 ** 31;
    return i === 0 ? 0 : s % 1500;
  });
}

test('a reload right after a change or an undo keeps it, at any delay up to 1.5 s', async () => {
  const { page, errors } = await openApp(browser());
  const draw = new DrawPage(page);
  const names = async () => (await draw.elements(0)).filter((e) => e.kind === 'contact').map((e) => e.name);
  const reload = async (expected: string[]) => {
    await page.reload();
    await waitForApp(page);
    // The restore reads the browser's storage after the app mounts; an older project would never match.
    await expect.poll(names, { timeout: 10_000 }).toEqual(expected);
  };
  const seed = Date.now() % 100_000;
  const trials = 5;
  const [keep, undo] = [delays(seed, trials), delays(seed + 1, trials)];
  console.log(`autosave reload delays (seed ${seed}): after a change ${keep.join(', ')} ms; after an undo ${undo.join(', ')} ms`);
  const kept: string[] = [];
  for (let t = 0; t < trials; t++) {
    // A change, then a reload after a random wait (the first trial: at once).
    await draw.pickPalette('contact-NO');
    await draw.clickCell(0, 0, 2 * t);
    await draw.typeName(`Keep${t}`);
    await page.keyboard.press('Escape');
    kept.push(`Keep${t}`);
    if (keep[t]) await page.waitForTimeout(keep[t]!);
    await reload(kept);

    // Another change, undone after a random wait, then a reload at once: the undone element stays gone.
    await draw.pickPalette('contact-NO');
    await draw.clickCell(0, 0, 2 * t + 1);
    await draw.typeName(`Undone${t}`);
    await page.keyboard.press('Escape');
    expect(await names()).toContain(`Undone${t}`);
    if (undo[t]) await page.waitForTimeout(undo[t]!);
    await draw.canvas().focus();
    for (let i = 0; i < 3 && (await names()).includes(`Undone${t}`); i++) await page.keyboard.press('Control+z');
    expect(await names()).toEqual(kept);
    await reload(kept);
  }
  expect(errors).toEqual([]);
  await page.close();
});

test('a 10,000-network project: a change and an undo survive a reload at once', async () => {
  const editor = await EditorPage.open(browser());
  const { page } = editor;
  const big = sealInProject(10_000, 'Ten thousand');
  await page.evaluate((p) => window.rungsmith!.documentStore!.getState().loadProject(p), big);
  await editor.waitForAutosave();
  const titles = () =>
    page.evaluate(() => {
      const n = window.rungsmith!.documentStore!.getState().project.pous[0]!.networks;
      return [n.length, n[4321]!.title, n[9999]!.title];
    });
  const reload = async (expected: unknown[]) => {
    await page.reload();
    await waitForApp(page);
    await expect.poll(titles, { timeout: 120_000 }).toEqual(expected);
  };
  // Changes made through the document's commands (the canvas would take long to scroll there).
  const retitle = (index: number, title: string) =>
    page.evaluate(
      ([i, t]) => {
        const s = window.rungsmith!.documentStore!.getState();
        s.updateNetwork(s.project.pous[0]!.networks[i as number]!.id, { title: t as string });
      },
      [index, title] as const,
    );
  await retitle(4321, 'Changed');
  await reload([10_000, 'Changed', 'Motor 9999']);
  await retitle(9999, 'Undone');
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().undo());
  await reload([10_000, 'Changed', 'Motor 9999']);
  expect(editor.errors).toEqual([]);
  await editor.close();
  // A big project on a shared, busy machine: room for loading it three times.
}, 300_000);
