// The body of a POU written in ST or IL, lowered like an LD body (compile/pou.ts lowerPouBody):
// one network holding the checked statements; errors are LD-E50 naming the POU, the language and
// the line and column; a pragma the simulator does not run is LD-W50.
import type { Pou, Profile, Project } from '../../model/project';
import type { Diagnostic } from '../api';
import { newPouContext } from '../compile/context';
import type { LoweredPou, Placement } from '../compile/context';
import { Reporter } from '../compile/report';
import type { SymbolTable } from '../compile/symbols';
import { bodyChunks, compileTextBody, describeStError } from './index';

/** Element and vertical-link counts per network of a body (ST/IL: networks with none, see st/index.ts bodyChunks). */
export function bodyShapes(pou: Pou): { elements: number; vlinks: number }[] {
  return pou.language === 'ST' || pou.language === 'IL'
    ? bodyChunks(pou).map(() => ({ elements: 0, vlinks: 0 }))
    : pou.networks.map((n) => ({ elements: n.elements.length, vlinks: n.vlinks.length }));
}

/** How the message of an error in a text body starts, before `line L col C: ...`. */
export const textBodyPrefix = (pou: Pick<Pou, 'language' | 'name'>): string => `the ${pou.language} body of ${pou.name} does not compile: `;

export function lowerTextBody(
  project: Project,
  pou: Pou & { language: 'ST' | 'IL' },
  profile: Profile,
  symbols: SymbolTable,
  out: Diagnostic[],
  place: Placement,
): LoweredPou {
  const ctx = newPouContext(project, pou, profile, symbols, new Map(), place);
  const r = new Reporter(out, pou.name, 0);
  const result = compileTextBody(
    pou,
    { symbols, profile, functions: ctx.functions, ...(ctx.calls ? { calls: ctx.calls } : {}), pouName: pou.name },
    place.first,
  );
  for (const p of result.pragmas) {
    const code = p.text.trim().replace(/\s+/g, ' ');
    const shown = code.length > 60 ? `${code.slice(0, 57)}...` : code;
    r.inText('warning', 'LD-W50', `the pragma {${shown}} in the ${pou.language} body of ${pou.name} (line ${p.pos.line}) is C code for the MATIEC runtime; the simulator ignores it`, p.pos);
  }
  for (const e of result.errors) r.inText('error', e.rule ?? 'LD-E50', `${textBodyPrefix(pou)}${describeStError(e)}`, e.pos);
  return { ctx, networks: result.networks ?? bodyChunks(pou).map(() => undefined), ok: !!result.networks };
}

/** LD-E51: a body in a language the simulator does not run (an FBD body the import kept as FBD). */
export function refuseBody(project: Project, pou: Pou, profile: Profile, symbols: SymbolTable, out: Diagnostic[], place: Placement): LoweredPou {
  const ctx = newPouContext(project, pou, profile, symbols, new Map(), place);
  new Reporter(out, pou.name, -1).error(
    'LD-E51',
    `the ${pou.kind === 'FUNCTION' ? 'function' : pou.kind === 'FUNCTION_BLOCK' ? 'function block' : 'program'} ${pou.name} is written in ${pou.source?.trimStart().startsWith('<CFC') ? 'CFC' : pou.language}, which the simulator does not run; its calls cannot run (redraw it in LD, or write it in ST)`,
  );
  return { ctx, networks: [], ok: false };
}
