// Two figures of the simulator on a large program, in a real Chromium page of the built app
// (window.rungsmith handles): how long Run takes to its first scan, and how many cycles an online
// change misses while the program runs at a 10 ms cycle.
//
//   const f = await measureRunAndOnlineChange(page, project);
//   // f.runFirstScanMs, f.onlineChangeOverruns (missed cycles), f.onlineChangeDropped, f.appliedMs
//
// `page` shows the app (any URL of it; the gateway's or vite preview's), `project` a program whose
// first PROGRAM has a contact on a BOOL in its first network (every generated bench program does).
// The page's document is replaced by `project`.
//
// Missed cycles are the worker's own count (exec.late): scans that started a cycle or more after
// their time because the worker was busy, whether caught up afterwards or dropped (overruns). A
// build before the count existed reports the app's overruns only (dropped scans), marked `late`
// undefined.
import type { Page } from 'playwright-core';
import type { Project } from '../src/model/project';

export interface OnlineChangeFigures {
  /** From the Run command to the first scan reported by the worker (document compiled and installed). */
  readonly runFirstScanMs: number;
  /** Cycles missed (started a cycle or more late, or dropped) from the edit until 1 s after the change was applied. */
  readonly onlineChangeOverruns: number;
  /** Of those, scans dropped (the app's overrun counter). */
  readonly onlineChangeDropped: number;
  /** From the edit to the change applied (300 ms typing pause included, in apply-as-you-edit mode). */
  readonly appliedMs: number;
  /** False when the build reports no missed-cycle count (only dropped scans were counted). */
  readonly lateCounted: boolean;
}

export interface MeasureOptions {
  /** Scan cycle while measuring; default 10 ms. */
  readonly cycleMs?: number;
  /** How long the program runs before the edit; default 1,000 ms. */
  readonly settleMs?: number;
}

interface Handle {
  documentStore: {
    getState(): {
      project: Project;
      loadProject(p: Project): void;
      updateElement(id: string, patch: { variable: string }): void;
    };
  };
  simStore: {
    getState(): {
      scan: number;
      mode: string;
      overruns: number;
      exec: { late?: number };
      onlineChange?: { kind: string };
      run(p: Project): void;
      pause(): void;
      reset(): void;
      unload(): void;
      setCycle(ms: number): void;
    };
    subscribe(listener: (s: { scan: number; onlineChange?: { kind: string } }) => void): () => void;
  };
}
declare const window: { rungsmith: Handle };

export async function measureRunAndOnlineChange(page: Page, project: Project, options: MeasureOptions = {}): Promise<OnlineChangeFigures> {
  const cycleMs = options.cycleMs ?? 10;
  const settleMs = options.settleMs ?? 1000;
  await page.waitForFunction(() => Boolean(window.rungsmith?.documentStore && window.rungsmith?.simStore), undefined, { timeout: 30_000 });
  await page.evaluate((p) => {
    const sim = window.rungsmith.simStore.getState();
    sim.pause();
    sim.reset();
    window.rungsmith.documentStore.getState().loadProject(p);
    // A cold Run: the worker forgets any program of an earlier measurement.
    sim.unload();
  }, project);
  // The editor's live checks of the loaded project run first (as for a user who opens a project and then presses Run).
  await page.waitForTimeout(1500);

  const runFirstScanMs = await page.evaluate(
    (cycle) =>
      new Promise<number>((resolve) => {
        const sim = window.rungsmith.simStore;
        sim.getState().setCycle(cycle);
        const t0 = performance.now();
        const off = sim.subscribe((s) => {
          if (s.scan < 1) return;
          off();
          resolve(performance.now() - t0);
        });
        sim.getState().run(window.rungsmith.documentStore.getState().project);
      }),
    cycleMs,
  );
  await page.waitForTimeout(settleMs);

  // The edit: the first contact of the first network reads another BOOL of the program, as a user would retype an operand.
  const figures = await page.evaluate(
    () =>
      new Promise<{ appliedMs: number; before: { late?: number; overruns: number } }>((resolve, reject) => {
        const doc = window.rungsmith.documentStore.getState();
        const pou = doc.project.pous.find((p) => p.kind === 'PROGRAM')!;
        const contacts = pou.networks.flatMap((n) => n.elements).filter((e) => e.kind === 'contact');
        const first = contacts[0] as { id: string; variable: string } | undefined;
        const other = contacts.find((e) => (e as { variable: string }).variable !== first?.variable) as { variable: string } | undefined;
        if (!first || !other) return reject(new Error('the program has no two contacts on different variables to swap'));
        const sim = window.rungsmith.simStore;
        const s = sim.getState();
        const before = { late: s.exec.late, overruns: s.overruns };
        const t0 = performance.now();
        const off = sim.subscribe((state) => {
          if (state.onlineChange?.kind !== 'applied') return;
          off();
          performance.mark('oc-applied');
          resolve({ appliedMs: performance.now() - t0, before });
        });
        // A mark for a trace of the change (bench/editorProfile.ts and the like).
        performance.mark('oc-edit');
        doc.updateElement(first.id, { variable: other.variable });
      }),
  );
  await page.waitForTimeout(1000);
  const after = await page.evaluate(() => {
    const s = window.rungsmith.simStore.getState();
    const out = { late: s.exec.late, overruns: s.overruns, mode: s.mode };
    s.pause();
    return out;
  });
  if (after.mode !== 'running') throw new Error(`the simulation is ${after.mode} after the online change, not running`);
  const dropped = after.overruns - figures.before.overruns;
  const lateCounted = after.late !== undefined && figures.before.late !== undefined;
  return {
    runFirstScanMs,
    onlineChangeOverruns: lateCounted ? after.late! - figures.before.late! : dropped,
    onlineChangeDropped: dropped,
    appliedMs: figures.appliedMs,
    lateCounted,
  };
}
