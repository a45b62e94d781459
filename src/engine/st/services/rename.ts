// Renaming a variable in ST bodies: the uses of a variable (not members `X.name`, not a call's
// parameter names `F(name := …)`), and when the variable is an input or output of a FUNCTION_BLOCK
// or FUNCTION, the callers' `Inst.Pin` and named arguments `Inst(Pin := …)`, `F(Pin := …)`.
// Token by token (comments, strings and pragmas are left alone), so the rest of the text stays
// byte for byte. `planStRename` checks a new name before anything changes and says why it cannot.
import { IEC_DECLARATION_WORDS, ST_OPERATOR_WORDS, ST_STATEMENT_WORDS } from '../lexer';
import { blockSignature } from '../../../model/blocks';
import type { PouId } from '../../../model/ids';
import { IDENTIFIER_RE } from '../../../model/iecTypes';
import type { Pou, Project, Variable } from '../../../model/project';
import { findDataType } from '../../../model/dataTypes';
import { enumValuesInScope, serviceScope } from './scope';
import { symbolAt } from './navigate';
import { positionOf, readBody, sameName, type BodyText } from './text';

/** What to rename in one text: uses of `variable`, and the pin `pin` of instances/calls named in `pins`. */
export interface TextRename {
  readonly to: string;
  /** A variable whose uses are renamed (absent: none in this text). */
  readonly variable?: string;
  /** The pin `from` of the instances `instances` and of calls of `callees` (upper-cased names). */
  readonly pins?: {
    readonly from: string;
    readonly instances: ReadonlySet<string>;
    readonly callees: ReadonlySet<string>;
  };
}

/** Is token k a call's parameter name (`(x :=`, `, x =>`, `NOT x =>`)? Returns the callee's name. */
function parameterOf(b: BodyText, k: number, callStack: readonly (string | undefined)[]): string | undefined {
  const next = b.tokens[k + 1]?.text;
  const prev = b.tokens[k - 1];
  if ((next !== ':=' && next !== '=>') || !prev) return undefined;
  if (!(prev.text === '(' || prev.text === ',' || (prev.upper === 'NOT' && next === '=>'))) return undefined;
  if (callStack.length === 0) return undefined;
  return callStack[callStack.length - 1] ?? '';
}

/** The text with the renames done; the same string when nothing changed. Undefined when the text does not read to its end (an unclosed comment or string). */
export function renameInText(text: string, r: TextRename): string | undefined {
  const b = readBody(text);
  if (b.open !== undefined) return undefined;
  const edits: { from: number; to: number }[] = [];
  const calls: (string | undefined)[] = [];
  const variable = r.variable?.toUpperCase();
  const pin = r.pins?.from.toUpperCase();
  b.tokens.forEach((t, k) => {
    if (t.kind === 'symbol') {
      if (t.text === '(') {
        const callee = b.tokens[k - 1];
        calls.push(callee?.kind === 'ident' ? callee.upper : undefined);
      } else if (t.text === ')') calls.pop();
      return;
    }
    if (t.kind !== 'ident') return;
    const param = parameterOf(b, k, calls);
    if (param !== undefined) {
      if (pin && t.upper === pin && (r.pins!.instances.has(param) || r.pins!.callees.has(param)))
        edits.push(t);
      return;
    }
    const prev = b.tokens[k - 1];
    if (prev?.text === '.' && prev.kind === 'symbol') {
      const owner = b.tokens[k - 2];
      // `Inst.Pin` where Inst is itself a name (not a member of something else).
      if (
        pin &&
        t.upper === pin &&
        owner?.kind === 'ident' &&
        r.pins!.instances.has(owner.upper) &&
        b.tokens[k - 3]?.text !== '.'
      )
        edits.push(t);
      return;
    }
    if (variable && t.upper === variable) edits.push(t);
  });
  if (edits.length === 0) return text;
  let out = '';
  let at = 0;
  for (const e of edits) {
    out += text.slice(at, e.from) + r.to;
    at = e.to;
  }
  return out + text.slice(at);
}

const isTextBody = (p: Pou): boolean => p.language === 'ST';
const PIN_CLASSES = new Set(['input', 'output', 'inOut']);

/** The ST bodies a rename of `from` (declared in `scope`) to `to` changes: before and after. */
export function stRenameEdits(
  project: Project,
  scope: PouId | 'globals',
  from: Variable,
  to: string,
): { pou: PouId; before: string; after: string }[] {
  const out: { pou: PouId; before: string; after: string }[] = [];
  const owner = scope === 'globals' ? undefined : project.pous.find((p) => p.id === scope);
  const interfacePin = owner && owner.kind !== 'PROGRAM' && PIN_CLASSES.has(from.varClass);
  for (const pou of project.pous) {
    if (!isTextBody(pou) || !pou.source) continue;
    const usesVariable =
      scope === 'globals'
        ? !pou.variables.some((v) => v.varClass !== 'external' && sameName(v.name, from.name))
        : pou === owner;
    let pins: TextRename['pins'];
    if (interfacePin) {
      const locals = new Set(
        pou.variables.filter((v) => v.varClass !== 'external').map((v) => v.name.toUpperCase()),
      );
      const instances = new Set<string>();
      for (const v of pou.variables)
        if (sameName(v.type.trim(), owner.name)) instances.add(v.name.toUpperCase());
      for (const g of project.globals)
        if (sameName(g.type.trim(), owner.name) && !locals.has(g.name.toUpperCase()))
          instances.add(g.name.toUpperCase());
      const callees = new Set(owner.kind === 'FUNCTION' ? [owner.name.toUpperCase()] : []);
      if (instances.size || callees.size) pins = { from: from.name, instances, callees };
    }
    if (!usesVariable && !pins) continue;
    const after = renameInText(pou.source, {
      to,
      ...(usesVariable ? { variable: from.name } : {}),
      ...(pins ? { pins } : {}),
    });
    if (after !== undefined && after !== pou.source) out.push({ pou: pou.id, before: pou.source, after });
  }
  return out;
}

const ST_WORDS = new Set<string>([...ST_STATEMENT_WORDS, ...ST_OPERATOR_WORDS, ...IEC_DECLARATION_WORDS]);

export type RenamePlan =
  | {
      readonly ok: true;
      readonly scope: PouId | 'globals';
      readonly from: string;
      readonly to: string;
      readonly bodies: number;
    }
  | { readonly ok: false; readonly reason: string };

/** Why `to` cannot name a variable at all; undefined when it can. */
export function variableNameProblem(project: Project, to: string): string | undefined {
  if (!IDENTIFIER_RE.test(to)) return `"${to}" is not a valid name (a letter or _, then letters, digits, _)`;
  const upper = to.toUpperCase();
  if (ST_WORDS.has(upper)) return `"${to}" is a keyword of IEC 61131-3`;
  const sig = blockSignature(to);
  if (sig) return `"${to}" is the standard ${sig.kind === 'fb' ? 'function block' : 'function'} ${sig.name}`;
  if (
    /^(BOOL|BYTE|WORD|DWORD|LWORD|SINT|INT|DINT|LINT|USINT|UINT|UDINT|ULINT|REAL|LREAL|TIME|DATE|TOD|DT|TIME_OF_DAY|DATE_AND_TIME)$/.test(
      upper,
    )
  )
    return `"${to}" is an elementary type`;
  const pou = project.pous.find((p) => sameName(p.name, to));
  if (pou)
    return `"${to}" is the name of the ${pou.kind === 'FUNCTION' ? 'function' : pou.kind === 'FUNCTION_BLOCK' ? 'function block' : 'program'} ${pou.name}`;
  if (findDataType(project, to)) return `"${to}" is the name of a data type`;
  return undefined;
}

/**
 * The rename of the variable at `offset` of the body `text` of POU `pouId` to `to`: which
 * declaration, or why not (not a variable of the project, the name taken or hiding another).
 */
export function planStRename(
  project: Project,
  pouId: string,
  text: string,
  offset: number,
  to: string,
): RenamePlan {
  const pou = project.pous.find((p) => p.id === pouId);
  if (!pou) return { ok: false, reason: 'the POU is gone' };
  const s = serviceScope(project, pou);
  const found = symbolAt(s, text, offset)?.symbol;
  if (!found) return { ok: false, reason: 'put the cursor on a variable to rename it' };
  let scope: PouId | 'globals';
  let variable: Variable;
  switch (found.k) {
    case 'variable':
      if (found.v.variable.varClass === 'external' && found.v.owner !== 'globals')
        return { ok: false, reason: `${found.v.variable.name} is VAR_EXTERNAL: rename the global it names` };
      scope = found.v.owner === 'globals' ? 'globals' : found.v.owner.id;
      variable = found.v.variable;
      break;
    case 'member':
    case 'parameter':
      if (!found.decl) {
        const of = found.k === 'member' ? found.m.of : found.sig.name;
        return {
          ok: false,
          reason: `${found.k === 'member' ? found.m.name : found.name} belongs to ${of}, which is not a POU of this project: it cannot be renamed here`,
        };
      }
      scope = found.decl.pou.id;
      variable = found.decl.variable;
      break;
    case 'result':
      return {
        ok: false,
        reason: `${found.pou.name} is the function's result: rename the function in the project tree`,
      };
    case 'block':
      return {
        ok: false,
        reason: `${found.sig.name} is a ${found.sig.kind === 'fb' ? 'function block' : 'function'}, not a variable${found.pou ? ': rename it in the project tree' : ''}`,
      };
    case 'enum':
      return { ok: false, reason: `${found.value} is a value of ${found.type}: rename it in the data type` };
  }
  return checkRename(project, scope, variable, to);
}

/** Checks renaming the variable `variable` of `scope` to `to`. */
export function checkRename(
  project: Project,
  scope: PouId | 'globals',
  variable: Variable,
  to: string,
): RenamePlan {
  const from = variable.name;
  if (to === from) return { ok: false, reason: `the variable is already named ${from}` };
  const problem = variableNameProblem(project, to);
  if (problem) return { ok: false, reason: problem };
  const owner = scope === 'globals' ? undefined : project.pous.find((p) => p.id === scope);
  const same = (v: Variable) => sameName(v.name, to) && !sameName(v.name, from);
  if (owner) {
    if (owner.variables.some(same))
      return { ok: false, reason: `"${to}" is already declared in ${owner.name}` };
    if (owner.kind === 'FUNCTION' && sameName(owner.name, to))
      return { ok: false, reason: `"${to}" is the result of the function ${owner.name}` };
    const g = project.globals.find(same);
    if (g)
      return {
        ok: false,
        reason: `"${to}" would hide the global variable ${g.name} in ${owner.name} (LD-W05)`,
      };
    const e = enumValuesInScope(serviceScope(project, owner)).find((x) => sameName(x.value, to));
    if (e) return { ok: false, reason: `"${to}" is a value of the enumeration ${e.type}` };
  } else {
    if (project.globals.some(same)) return { ok: false, reason: `"${to}" is already a global variable` };
    const hiding = project.pous.find(
      (p) =>
        p.variables.some((v) => v.varClass !== 'external' && same(v)) &&
        !p.variables.some((v) => v.varClass !== 'external' && sameName(v.name, from)),
    );
    if (hiding)
      return {
        ok: false,
        reason: `${hiding.name} declares its own "${to}": its uses of the global ${from} would then mean that variable`,
      };
  }
  // Every ST body the rename may touch must read to its end (an unclosed comment or string hides its uses).
  const pinOfBlock = !!owner && owner.kind !== 'PROGRAM' && PIN_CLASSES.has(variable.varClass);
  for (const p of project.pous) {
    if (!isTextBody(p) || !p.source || !(scope === 'globals' || p.id === scope || pinOfBlock)) continue;
    const b = readBody(p.source);
    if (b.open === undefined) continue;
    const at = positionOf(b, b.open);
    return {
      ok: false,
      reason: `the ST body of ${p.name} has a comment or string left open at line ${at.line} col ${at.col}: close it first`,
    };
  }
  return { ok: true, scope, from, to, bodies: stRenameEdits(project, scope, variable, to).length };
}
