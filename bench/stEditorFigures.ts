// ST editor figures for `npm run bench:editor` (issue 25): a FUNCTION_BLOCK whose ST body has
// 2,000 lines (IF / CASE / FOR blocks, comments, literals of every kind) opened in the ST editor;
//   st-keystroke-ms  a character typed in the middle of the body: from the keydown to the painted
//                    frame that shows it (highlighting, keyword matching, folding markers updated)
//   st-commit-ms     the typing burst committed to the document (one undo step with the 2,000-line
//                    text): from the commit to the next painted frame
// Medians over the repeats.
import type { Page } from 'playwright-core';
import { newPou, newProject, variable } from '../src/model/factory';
import type { Project } from '../src/model/project';

declare const window: Window & { __stFrame?: Promise<number> };

/** About `lines` lines of varied ST (each block of 20 lines is different by its index). */
export function longStBody(lines = 2000): string {
  const out: string[] = [];
  for (let k = 0; out.length < lines; k++)
    out.push(
      `(* block ${k}: scale, limit and count *)`,
      `IF In > High + ${k}.5 THEN`,
      `    Q := TRUE; // above the band`,
      `    Count := Count + 1;`,
      `ELSIF In < Low - 1.5E-2 THEN`,
      `    Q := FALSE;`,
      `ELSE`,
      `    Mask := Mask OR 16#${(k % 255).toString(16).toUpperCase()};`,
      `END_IF;`,
      `CASE Mode OF`,
      `    0: Delay := T#${(k % 50) + 1}s;`,
      `    1, 2: Delay := TIME#1h2m;`,
      `ELSE`,
      `    Delay := T#0s;`,
      `END_CASE;`,
      `FOR i := 0 TO 3 DO`,
      `    Sum := Sum + INT_TO_REAL(i) * 0.25;`,
      `END_FOR;`,
      `Msg := 'block ${k} done';`,
      ``,
    );
  return out.slice(0, lines).join('\n');
}

export function longStProject(lines = 2000): Project {
  const vars = [
    variable('In', 'REAL', { varClass: 'input' }),
    variable('Low', 'REAL', { varClass: 'input' }),
    variable('High', 'REAL', { varClass: 'input' }),
    variable('Mode', 'INT', { varClass: 'input' }),
    variable('Q', 'BOOL', { varClass: 'output' }),
    variable('Count', 'DINT'),
    variable('Mask', 'WORD'),
    variable('Delay', 'TIME'),
    variable('Sum', 'REAL'),
    variable('i', 'INT'),
    variable('Msg', 'STRING'),
  ];
  return newProject('StBench', {
    pous: [
      newPou('Main', { variables: [variable('B1', 'LongSt')] }),
      newPou('LongSt', {
        kind: 'FUNCTION_BLOCK',
        language: 'ST',
        networks: [],
        source: longStBody(lines),
        variables: vars,
      }),
    ],
  });
}

const medianOf = (xs: readonly number[]) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length === 0 ? NaN : s[Math.floor((s.length - 1) / 2)]!;
};

export interface StEditorFigures {
  readonly stKeystrokeMs: number;
  readonly stCommitMs: number;
  readonly lines: number;
}

export async function stEditorFigures(page: Page, lines = 2000, repeats = 15): Promise<StEditorFigures> {
  const project = longStProject(lines);
  await page.evaluate((p: Project) => {
    const doc = window.rungsmith!.documentStore!;
    doc.getState().loadProject(p);
    doc.getState().setActivePou(doc.getState().project.pous[1]!.id);
  }, project);
  const content = page.getByTestId('st-editor').locator('.cm-content');
  await content.waitFor({ timeout: 60_000 });
  // The middle of the body: find the line, put the cursor at its end.
  await content.click();
  await page.keyboard.press('Control+Home');
  for (let k = 0; k < 10; k++) await page.keyboard.press('PageDown');
  await page.keyboard.press('End');
  await page.evaluate('window.__name ??= (f) => f');
  const keys: number[] = [];
  for (let k = 0; k < repeats; k++) {
    const ch = String.fromCharCode(97 + (k % 26));
    await page.evaluate((typed) => {
      window.__stFrame = new Promise<number>((resolve) => {
        const on = (e: KeyboardEvent) => {
          window.removeEventListener('keydown', on, true);
          const t0 = e.timeStamp;
          const shown = () => document.querySelector('.cm-activeLine')?.textContent?.endsWith(typed) ?? false;
          const frame = () =>
            requestAnimationFrame(() =>
              setTimeout(() => (shown() ? resolve(performance.now() - t0) : frame()), 0),
            );
          frame();
        };
        window.addEventListener('keydown', on, true);
      });
    }, ch);
    await page.keyboard.press(ch);
    keys.push(await page.evaluate(() => window.__stFrame!));
  }
  // Commit of the burst to the document: the 2,000-line text as one undo step, to the painted frame.
  const commits: number[] = [];
  for (let k = 0; k < 5; k++) {
    commits.push(
      await page.evaluate(async (n) => {
        const s = window.rungsmith!.documentStore!.getState();
        const pou = s.project.pous[1]!;
        const t0 = performance.now();
        s.setPouSource(pou.id, `${pou.source}\n// commit ${n}`, `Edit ST body of ${pou.name}`);
        await new Promise((r) => requestAnimationFrame(() => setTimeout(r, 0)));
        return performance.now() - t0;
      }, k),
    );
    await page.evaluate(() => new Promise((r) => setTimeout(r, 200)));
  }
  return { stKeystrokeMs: medianOf(keys), stCommitMs: medianOf(commits), lines };
}
