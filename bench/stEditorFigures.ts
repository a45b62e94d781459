// The ST editor on a 2,000-line body (bench/stServices.ts stBenchProject), in the built app in
// Chromium, from the user's input event (its timeStamp) to the painted frame showing the result:
//   st-keystroke-ms  a character typed at the end of the body (shown in the editor)
//   st-check-ms      the keystroke that makes the body wrong (`;` after `Zz := 1`, Zz undeclared) to
//                    the frame where the compiler's finding is underlined at its place
//   st-commit-ms     a typing burst committed to the document (the 2,000-line text as one undo step)
//                    to the next painted frame
// Used by bench/editor.bench.ts (`npm run bench:editor`), which opens the built app in Chromium.
import type { Page } from 'playwright-core';
import type { Project } from '../src/model/project';
import { stBenchProject } from './stServices';

interface Probe {
  __frame?: Promise<number>;
}
declare const window: Window & Probe;

/** ms from the next `keydown` to the painted frame where the page expression `until` is true. */
async function timedKey(page: Page, key: string, until: string): Promise<number> {
  // tsx names the functions declared inside the callbacks through a helper the page lacks.
  await page.evaluate('window.__name ??= (f) => f');
  await page.evaluate(
    ({ until }) => {
      const holds = new Function(`return (${until});`) as () => boolean;
      window.__frame = new Promise<number>((resolve, reject) => {
        const on = (e: KeyboardEvent) => {
          if (['Control', 'Shift', 'Alt', 'Meta'].includes(e.key)) return;
          window.removeEventListener('keydown', on, true);
          const t0 = e.timeStamp;
          const frame = () =>
            requestAnimationFrame(() =>
              setTimeout(
                () =>
                  holds()
                    ? resolve(performance.now() - t0)
                    : performance.now() - t0 > 20_000
                      ? reject(
                          new Error(
                            `not shown after 20 s: ${until}; shown: ${document.querySelector('[data-testid="st-editor"]')?.textContent?.slice(-200)} / ${[...document.querySelectorAll('.cm-lintRange-error, .cm-lintPoint-error')].map((e) => e.outerHTML).join(' ')}`,
                          ),
                        )
                      : frame(),
                0,
              ),
            );
          frame();
        };
        window.addEventListener('keydown', on, true);
      });
    },
    { until },
  );
  await page.keyboard.press(key);
  return page.evaluate(() => window.__frame!);
}

const LAST_LINE = `[...document.querySelectorAll('[data-testid="st-editor"] .cm-line')].at(-1)?.textContent ?? ''`;
const UNDERLINED = `[...document.querySelectorAll('[data-testid="st-editor"] .cm-lintRange-error')].map((e) => e.textContent).join('|')`;

const medianOf = (xs: readonly number[]) => [...xs].sort((a, b) => a - b)[Math.floor((xs.length - 1) / 2)]!;
const pause = (page: Page, ms: number) => page.evaluate((t) => new Promise((r) => setTimeout(r, t)), ms);

export interface StEditorFigures {
  readonly lines: number;
  readonly keystrokeMs: number;
  readonly checkMs: number;
  readonly commitMs: number;
}

/** Loads the 2,000-line ST body, then measures typing and the check after it (`repeats` times). */
export async function stEditorFigures(page: Page, repeats = 5, lines = 2000): Promise<StEditorFigures> {
  const project: Project = stBenchProject(lines);
  const keys: number[] = [];
  const checks: number[] = [];
  for (let k = 0; k < repeats; k++) {
    await page.evaluate((p: Project) => {
      const s = window.rungsmith!.documentStore!.getState();
      s.loadProject(p);
      s.setActivePou(s.project.pous[0]!.id);
    }, project);
    const content = page.getByTestId('st-editor').locator('.cm-content');
    await content.waitFor();
    await pause(page, 1500);
    await content.click();
    await page.keyboard.press('Control+End');
    await page.keyboard.press('Enter');
    await pause(page, 300);
    let typed = '';
    for (const ch of 'Zz := 1') {
      typed += ch;
      keys.push(
        await timedKey(
          page,
          ch === ' ' ? 'Space' : ch,
          `(${LAST_LINE}).trim() === ${JSON.stringify(typed.trim())}`,
        ),
      );
      await pause(page, 40);
    }
    // The body is now wrong twice over (no ";" yet): wait until that is shown, then complete the statement.
    await page.waitForFunction(
      `document.querySelector('[data-testid="st-editor"] .cm-lint-marker-error')`,
      undefined,
      { timeout: 30_000 },
    );
    checks.push(await timedKey(page, ';', `(${UNDERLINED}) === 'Zz'`));
    // The typing burst is committed after its pause: let it be, so the next round starts afresh.
    await pause(page, 1500);
  }
  // A burst committed to the document, as the editor commits it after a pause (one undo step).
  const commits: number[] = [];
  for (let k = 0; k < repeats; k++) {
    commits.push(
      await page.evaluate(async (n) => {
        const s = window.rungsmith!.documentStore!.getState();
        const pou = s.project.pous.find((p) => p.language === 'ST')!;
        const t0 = performance.now();
        s.setPouSource(pou.id, `${pou.source ?? ''}\n// commit ${n}`, `Edit ST body of ${pou.name}`);
        await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
        return performance.now() - t0;
      }, k),
    );
    await pause(page, 200);
  }
  return { lines, keystrokeMs: medianOf(keys), checkMs: medianOf(checks), commitMs: medianOf(commits) };
}
