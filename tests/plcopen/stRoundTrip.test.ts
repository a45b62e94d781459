// ST text through PLCopen (issue 25): an ST body exports as `<ST><xhtml:p>` and comes back
// unchanged, byte for byte, whatever it holds; an imported file's ST bodies the user did not touch
// are written back byte for byte, and the edited one carries exactly the edited text; the program
// behaves the same after an edit that changes no statement.
import { Text } from '@codemirror/state';
import { describe, expect, test } from 'vitest';
import { newPou, newProject, variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { createDocumentStore } from '../../src/store/documentStore';
import { fixture, imported } from './fixtures';
import { firstDifference, traceProgram } from './trace';

const NOW = new Date('2026-01-01T00:00:00Z');

function reimport(xml: string): Project {
  const r = importPlcopen(xml);
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return r.project;
}

/** The `<ST>...</ST>` (or IL) element of each POU in an exported file, by POU name. */
function bodies(xml: string): Map<string, string> {
  const out = new Map<string, string>();
  for (const m of xml.matchAll(/<pou name="([^"]+)"[\s\S]*?<\/pou>/g)) {
    const body = /<(ST|IL)>[\s\S]*?<\/\1>/.exec(m[0].slice(m[0].indexOf('<body>')));
    if (body) out.set(m[1]!, body[0]);
  }
  return out;
}

/** The text the ST editor holds for a body (CodeMirror's document). */
const editorText = (source: string) => Text.of(source.split(/\r\n?|\n/)).toString();

describe('ST text round trip', () => {
  const texts: readonly string[] = [
    '',
    'Out := In;',
    '\n\n  (* leading blank lines and indentation *)\n\tIF a THEN\n\t\tb := 1;   \n\tEND_IF;\n\n',
    "s := 'it$'s 50$$ ]]> <tag> & done'; // ]]> in a comment too\nt := \"wide\";",
    '(* Température ≥ 20 °C — Größe *)\nT := T#1h2m3s; A := %IX0.0; B := 16#FF; C := INT#-5; D := 1.5E-3;',
    '{pragma text}\n{{ C code with } inside }}\nx := 1;',
    'x := 1;\n\n\n',
    '   ',
  ];

  test('any ST text exports inside <ST><xhtml:p> and imports back unchanged, byte for byte', () => {
    for (const text of texts) {
      const project = newProject('RoundTrip', {
        pous: [
          newPou('Main', { variables: [variable('x', 'BOOL')] }),
          newPou('Body', { kind: 'FUNCTION_BLOCK', language: 'ST', networks: [], source: text }),
        ],
      });
      const xml = exportPlcopen(project, { now: NOW });
      expect(bodies(xml).get('Body')).toMatch(/^<ST><xhtml:p><!\[CDATA\[/);
      const back = reimport(xml).pous.find((p) => p.name === 'Body')!;
      expect({ text, back: back.source }).toEqual({ text, back: text });
      expect(back.language).toBe('ST');
      // And the editor holds exactly that text (its line breaks are the file's).
      expect(editorText(text)).toBe(text);
    }
  });

  test('an imported file: bodies not edited are written back byte for byte, the edited one exactly as edited', () => {
    const original = fixture('st-il-bodies.xml');
    const { project } = imported('st-il-bodies.xml');
    const before = bodies(original);
    expect([...before.keys()]).toEqual(['StepST', 'StepIL', 'Mean3', 'OneShot']);

    // Unchanged: every text body as it was in the file.
    const same = bodies(exportPlcopen(project, { now: NOW }));
    for (const [name, body] of before) expect(same.get(name)).toBe(body);

    // The user edits StepST in the ST editor (one named step); the others stay as they were.
    const store = createDocumentStore(project);
    const step = project.pous.find((p) => p.name === 'StepST')!;
    expect(editorText(step.source!)).toBe(step.source);
    const edited = `${step.source}\n// checked by the commissioning engineer`;
    store.getState().setPouSource(step.id, edited, 'Edit ST body of StepST');
    const xml = exportPlcopen(store.getState().project, { now: NOW });
    const after = bodies(xml);
    for (const name of ['StepIL', 'Mean3', 'OneShot']) expect(after.get(name)).toBe(before.get(name));
    expect(reimport(xml).pous.find((p) => p.name === 'StepST')!.source).toBe(edited);

    // The program behaves the same: a comment changes no statement.
    const cell = project.pous.find((p) => p.kind === 'PROGRAM')!.name;
    const a = traceProgram(project, cell, 120)!;
    const b = traceProgram(reimport(xml), cell, 120)!;
    expect(a.rows.length).toBe(120);
    expect(firstDifference(a, b)).toBe('');
  });
});
