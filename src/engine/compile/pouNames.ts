// LD-E25: POU names. Each POU's name is an identifier, unique in the project (IEC names ignore
// case), and not the name of a standard block: a call resolves a standard block first (MATIEC
// refuses a POU that redefines one), so such a POU would never be called.
import { blockSignature } from '../../model/blocks';
import { IDENTIFIER_RE } from '../../model/iecTypes';
import type { Project } from '../../model/project';
import type { Diagnostic } from '../api';
import { Reporter } from './report';

export function checkPouNames(project: Project, out: Diagnostic[]): void {
  const seen = new Map<string, string>();
  for (const pou of project.pous) {
    const r = new Reporter(out, pou.name, -1);
    const name = pou.name.trim();
    if (!IDENTIFIER_RE.test(name) || /__/.test(name)) {
      r.error('LD-E25', `"${pou.name}" is not a valid POU name; use a letter or _, then letters, digits and single underscores`);
      continue;
    }
    const key = name.toUpperCase();
    const first = seen.get(key);
    if (first !== undefined) {
      // A library's POU (src/model/libraries.ts, id `library:<library>:<pou>`) after the project's own.
      const library = /^library:(.*):[^:]*$/.exec(pou.id)?.[1];
      r.error(
        'LD-E25',
        library !== undefined
          ? `the POU name ${first} of the project is also a block of the library ${library}; calls run the project's POU: rename the POU (or remove the library)`
          : `the POU name ${name} is already used by ${first}; POU names must be unique (case does not count)`,
      );
      continue;
    }
    seen.set(key, name);
    const standard = blockSignature(key);
    if (standard)
      r.error(
        'LD-E25',
        `the ${pou.kind} ${name} has the name of the standard ${standard.kind === 'fb' ? 'function block' : 'function'} ${standard.name}; calls of ${standard.name} run the standard block, so rename this POU`,
      );
  }
}
