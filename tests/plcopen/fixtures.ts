// Reading fixture files and running imported programs.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { Plc } from '../../src/engine/api';
import type { Project } from '../../src/model/project';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import type { ImportReport } from '../../src/plcopen/types';

export const fixture = (name: string): string =>
  readFileSync(fileURLToPath(new URL(`../fixtures/plcopen/${name}`, import.meta.url)), 'utf8');

export function imported(name: string): { project: Project; report: ImportReport } {
  const r = importPlcopen(fixture(name));
  if (!r.ok) throw new Error(`${name}: ${JSON.stringify(r.errors)}`);
  return r;
}

export function run(project: Project, pou: string, cycleMs = 10): Plc {
  const { program, diagnostics } = compileProgram(project, { pou });
  if (!program) throw new Error(diagnostics.map((d) => d.message).join('\n'));
  return createPlc(program, { cycleMs });
}

/** Ids replaced by their order of first appearance (they are fresh on every import). */
export function canonical(p: Project): string {
  const ids = new Map<string, string>();
  const collect = (v: unknown): void => {
    if (Array.isArray(v)) v.forEach(collect);
    else if (v && typeof v === 'object')
      for (const [k, x] of Object.entries(v)) {
        if (k === 'id' && typeof x === 'string' && !ids.has(x)) ids.set(x, `#${ids.size}`);
        collect(x);
      }
  };
  collect(p);
  let json = JSON.stringify(p);
  for (const [id, n] of ids) json = json.split(id).join(n);
  return json;
}
