// Figures of the ST language services (src/engine/st/services) on a generated 2,000-line ST body:
// the check the editor runs after a keystroke (the compiler's findings for the body), completion,
// hover, go to definition and a rename. Run: npx tsx bench/stServices.ts [lines]
import { newPou, newProject, variable } from '../src/model/factory';
import type { Project, Variable } from '../src/model/project';
import {
  planStRename,
  stCompletions,
  stDefinition,
  stDiagnostics,
  stHover,
  stRenameEdits,
} from '../src/engine/st/services';
import { median } from './median';

const v = variable;

/** Ten lines of ST using the variables of motor `k` (timers, comparisons, a function, an IF). */
function block(k: number): string[] {
  return [
    `(* motor ${k} *)`,
    `T${k}(IN := Run${k} AND NOT Fault, PT := T#2s);`,
    `IF T${k}.Q AND Level > ${k % 90}.0 THEN`,
    `  Run${k} := TRUE;`,
    `  Count := Count + 1;`,
    `ELSIF Stop THEN`,
    `  Run${k} := FALSE;`,
    `END_IF;`,
    `Speed := LIMIT(0.0, Speed + 0.5 * Level, 100.0);`,
    `Total := Total + REAL_TO_DINT(Speed);`,
  ];
}

/** A PROGRAM Main whose ST body has `lines` lines (blocks of ten over `lines / 10` motors). */
export function stBenchProject(lines = 2000): Project {
  const motors = Math.ceil(lines / 10);
  const variables: Variable[] = [
    v('Level', 'REAL', { comment: 'tank level in %' }),
    v('Speed', 'REAL'),
    v('Count', 'INT'),
    v('Total', 'DINT'),
    v('Stop', 'BOOL', { varClass: 'input' }),
    v('Fault', 'BOOL', { varClass: 'input' }),
  ];
  for (let k = 0; k < motors; k++) variables.push(v(`T${k}`, 'TON'), v(`Run${k}`, 'BOOL'));
  const body = Array.from({ length: motors }, (_, k) => block(k))
    .flat()
    .slice(0, lines)
    .join('\n');
  return newProject('StBench', {
    pous: [newPou('Main', { variables, networks: [], language: 'ST', source: `${body}\n` })],
  });
}

function run(): void {
  const lines = Number(process.argv[2] ?? 2000);
  const p = stBenchProject(lines);
  const main = p.pous[0]!;
  const text = main.source!;
  // A keystroke in the middle of the body: the text as typed, checked whole.
  const mid = text.indexOf('Count := Count + 1;', Math.floor(text.length / 2));
  const typed = `${text.slice(0, mid)}Coun${text.slice(mid + 5)}`;
  // Every run on a new text (as after a keystroke), so no cache of the last text helps.
  let n = 0;
  const fresh = (t: string) => `${t}${' '.repeat(++n % 50)}`;
  median(5, () => stDiagnostics(p, main.id, fresh(typed)));
  const check = median(15, () => stDiagnostics(p, main.id, fresh(typed)));
  const found = stDiagnostics(p, main.id, typed).located;
  const complete = median(21, () => {
    const t = `${fresh(text)}x := T3.`;
    stCompletions(p, main.id, t, t.length);
  });
  const word = `${text.slice(0, mid)}Le${text.slice(mid)}`;
  const completeWord = median(21, () => stCompletions(p, main.id, fresh(word), mid + 2));
  const levelAt = text.indexOf('Level', mid);
  const hover = median(21, () => stHover(p, main.id, fresh(text), levelAt + 1));
  const definition = median(21, () => stDefinition(p, main.id, fresh(text), levelAt + 1));
  const plan = median(9, () => planStRename(p, main.id, fresh(text), levelAt + 1, 'TankLevel'));
  const edits = median(9, () => stRenameEdits(p, main.id, main.variables[0]!, 'TankLevel'));
  const fmt = (ms: number) => `${ms.toFixed(1)} ms`;
  console.log(
    `ST language services on a ${text.split('\n').length - 1}-line body (${(text.length / 1024).toFixed(0)} KiB), medians:`,
  );
  console.log(
    `  st-check-ms (compiler findings of the body as typed): ${fmt(check)} (${found.length} finding${found.length === 1 ? '' : 's'}: ${found[0]?.rule ?? '-'} line ${found[0]?.line ?? '-'})`,
  );
  console.log(`  completion after "T3.": ${fmt(complete)}; of a word mid-body: ${fmt(completeWord)}`);
  console.log(`  hover: ${fmt(hover)}; go to definition: ${fmt(definition)}`);
  console.log(`  rename Level: plan ${fmt(plan)}, body edits ${fmt(edits)}`);
}

if (process.argv[1]?.endsWith('stServices.ts')) run();
