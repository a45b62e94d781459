// npm run test:interop — the ST bodies of the real PLCopen files (../shared/plcopen/examples, GPL
// files the repository does not copy; see corpusDir.ts): each opens in the ST editor as written,
// is edited (a comment line added, as a user would), exports back inside <ST><xhtml:p>, imports
// again with exactly the edited text, and every program runs the same trace as before the edit,
// and as the same file exported without the edit. (Multi_Language's plc_prg runs its networks in
// another order after any export, edited or not: the LD export, not the ST text; see the report.)
import { readdirSync } from 'node:fs';
import { Text } from '@codemirror/state';
import { describe, expect, it } from 'vitest';
import type { Project } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { createDocumentStore } from '../../src/store/documentStore';
import { stEditStepName } from '../../src/editor/st/stModelSync';
import { firstDifference, traceProgram } from '../plcopen/trace';
import { corpusDir, corpusText } from './corpusDir';

function load(xml: string): Project {
  const r = importPlcopen(xml);
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return r.project;
}

/** The files with POUs written in ST (not only ST inside SFC actions and transitions). */
const FILES = readdirSync(corpusDir())
  .filter((f) => f.endsWith('.xml'))
  .filter((f) => /<ST>/.test(corpusText(f)) && load(corpusText(f)).pous.some((p) => p.language === 'ST'))
  .sort();
const NOW = new Date('2026-01-01T00:00:00Z');

describe('ST bodies of the corpus: open, edit, export back', () => {
  it('finds the files with ST bodies', () => {
    expect(FILES.length).toBeGreaterThanOrEqual(2);
  });

  for (const file of FILES)
    it(file, () => {
      const project = load(corpusText(file));
      const st = project.pous.filter((p) => p.language === 'ST');
      expect(st.length).toBeGreaterThan(0);
      const store = createDocumentStore(project);
      for (const pou of st) {
        // The editor holds the body as imported (CodeMirror's document keeps the text).
        expect(Text.of(pou.source!.split('\n')).toString()).toBe(pou.source);
        store.getState().setPouSource(pou.id, `${pou.source}\n// reviewed`, stEditStepName(pou.name));
      }
      const edited = store.getState().project;
      const back = load(exportPlcopen(edited, { now: NOW }));
      const plain = load(exportPlcopen(project, { now: NOW }));
      for (const pou of st)
        expect(back.pous.find((p) => p.name === pou.name)?.source).toBe(`${pou.source}\n// reviewed`);
      for (const program of project.pous.filter((p) => p.kind === 'PROGRAM')) {
        const before = traceProgram(project, program.name, 100);
        if (!before) continue;
        const inEditor = traceProgram(edited, program.name, 100);
        expect(firstDifference(before, inEditor!)).toBe('');
        const after = traceProgram(back, program.name, 100);
        expect(after, `${program.name} compiles after the round trip`).toBeDefined();
        expect(firstDifference(traceProgram(plain, program.name, 100)!, after!)).toBe('');
      }
    });
});
