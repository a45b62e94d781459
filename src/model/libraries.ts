// Libraries kept with the project (Project.libraries, docs/libraries.md): adding one (its names must
// not clash), telling what an update changes, removing one (refused while the project uses its
// blocks), finding the uses of its blocks, and the project the engine compiles (the libraries'
// POUs and data types beside the project's own). Reading a file as a library is in
// src/plcopen/libraryFile.ts. Pure: no DOM.
import { blockSignature } from './blocks';
import { pouSignature } from './library';
import type { PouId } from './ids';
import type { DataType, Pou, Project, ProjectLibrary } from './project';
import { sha256 } from '@noble/hashes/sha2.js';
import { bytesToHex } from '@noble/hashes/utils.js';
import { VENDOR_BLOCKS } from './vendorBlocks';

/** A place where the project uses a library's block or data type. */
export interface LibraryUse {
  /** The POU that uses it ("globals" for a global variable), or `Library.Pou` inside another library. */
  readonly pou: string;
  /** The block or data type used. */
  readonly name: string;
  /** 1-based network number of an LD box. */
  readonly network?: number;
  readonly elementId?: string;
  /** The variable declared of that type (an FB instance or a variable of a data type). */
  readonly variable?: string;
  /** 1-based line of an ST or IL body that names it. */
  readonly line?: number;
}

/** "POU Main, network 2: box Conveyor (instance Belt1)" */
export function describeUse(u: LibraryUse): string {
  if (u.network !== undefined) return `${u.pou}, network ${u.network}: box ${u.name}`;
  if (u.variable !== undefined) return `${u.pou}: variable ${u.variable} : ${u.name}`;
  return `${u.pou}${u.line !== undefined ? `, line ${u.line}` : ''}: calls ${u.name}`;
}

const upper = (s: string) => s.trim().toUpperCase();

/** The names a library defines: its POUs, then its data types. */
export const libraryNames = (lib: Pick<ProjectLibrary, 'pous' | 'dataTypes'>): string[] => [
  ...lib.pous.map((p) => p.name),
  ...(lib.dataTypes ?? []).map((d) => d.name),
];

const escapeRe = (s: string) => s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');

/** Where the POUs (and globals) use any of `names`: LD boxes, variables of those types, ST/IL bodies that name them. */
function usesIn(pous: readonly Pou[], names: readonly string[], prefix = ''): LibraryUse[] {
  if (!names.length) return [];
  const keys = new Set(names.map(upper));
  const byKey = new Map(names.map((n) => [upper(n), n]));
  const word = new RegExp(`(?<![A-Za-z0-9_])(${names.map(escapeRe).join('|')})(?![A-Za-z0-9_])`, 'i');
  const out: LibraryUse[] = [];
  for (const pou of pous) {
    const where = `${prefix}${pou.name}`;
    for (const v of pou.variables) {
      const t = upper(v.type);
      if (keys.has(t)) out.push({ pou: where, name: byKey.get(t)!, variable: v.name });
    }
    pou.networks.forEach((net, i) => {
      for (const el of net.elements)
        if (el.kind === 'box' && keys.has(upper(el.blockType)))
          out.push({ pou: where, name: byKey.get(upper(el.blockType))!, network: i + 1, elementId: el.id });
    });
    if ((pou.language === 'ST' || pou.language === 'IL') && pou.source) {
      // Comments and strings aside, a name in the text is a call or a declaration of it.
      const text = pou.source.replace(/\(\*[\s\S]*?\*\)/g, (c) => c.replace(/[^\n]/g, ' ')).replace(/\/\/[^\n]*/g, '');
      text.split('\n').forEach((line, i) => {
        const m = word.exec(line);
        if (m) out.push({ pou: where, name: byKey.get(upper(m[1]!))!, line: i + 1 });
      });
    }
  }
  return out;
}

/**
 * Where the project uses any of `names`: its POUs, its globals and the POUs of its other libraries
 * (`except`: the library the names belong to).
 */
export function usesOf(project: Project, names: readonly string[], except?: string): LibraryUse[] {
  const keys = new Set(names.map(upper));
  const globals: LibraryUse[] = project.globals
    .filter((g) => keys.has(upper(g.type)))
    .map((g) => ({ pou: 'globals', name: names.find((n) => upper(n) === upper(g.type))!, variable: g.name }));
  const others = (project.libraries ?? []).filter((l) => except === undefined || upper(l.name) !== upper(except));
  return [...usesIn(project.pous, names), ...globals, ...others.flatMap((l) => usesIn(l.pous, names, `${l.name}.`))];
}

/** Where the project uses the blocks and data types of the library named `name`. */
export function libraryUses(project: Project, name: string): LibraryUse[] {
  const lib = findLibrary(project, name);
  return lib ? usesOf(project, libraryNames(lib), lib.name) : [];
}

export const findLibrary = (project: Pick<Project, 'libraries'>, name: string): ProjectLibrary | undefined =>
  project.libraries?.find((l) => upper(l.name) === upper(name));

/** What a library holds, for the manager: "2 function blocks, 1 function, 1 data type". */
export function libraryContents(lib: Pick<ProjectLibrary, 'pous' | 'dataTypes'>): string {
  const count = (n: number, what: string) => (n ? [`${n} ${what}${n === 1 ? '' : 's'}`] : []);
  const parts = [
    ...count(lib.pous.filter((p) => p.kind === 'FUNCTION_BLOCK').length, 'function block'),
    ...count(lib.pous.filter((p) => p.kind === 'FUNCTION').length, 'function'),
    ...count(lib.dataTypes?.length ?? 0, 'data type'),
  ];
  return parts.join(', ') || 'nothing';
}

const KIND_WORD = { PROGRAM: 'PROGRAM', FUNCTION_BLOCK: 'function block', FUNCTION: 'function' } as const;

/**
 * Why the library cannot be added as it is (empty: it can). `replacing`: the library it updates
 * (its own names do not clash). Names are compared as IEC compares them, ignoring case.
 */
export function libraryClashes(project: Project, lib: Pick<ProjectLibrary, 'name' | 'pous' | 'dataTypes'>, replacing?: string): string[] {
  const errors: string[] = [];
  const name = lib.name.trim();
  if (!/^[A-Za-z_][A-Za-z0-9_ .-]*$/.test(name))
    errors.push(`"${lib.name}" is not a usable library name: start with a letter or _, then letters, digits, spaces, _ . -`);
  const others = (project.libraries ?? []).filter((l) => replacing === undefined || upper(l.name) !== upper(replacing));
  const same = others.find((l) => upper(l.name) === upper(name));
  if (same) errors.push(`the project already has a library named ${same.name}; remove it, update it, or give this one another name`);
  if (!lib.pous.length && !lib.dataTypes?.length) errors.push('the file has no function block, function or data type to use as a library');
  const seen = new Set<string>();
  const check = (n: string, what: string) => {
    const key = upper(n);
    if (seen.has(key)) {
      errors.push(`the library defines ${n} twice`);
      return;
    }
    seen.add(key);
    const std = blockSignature(key);
    if (std) errors.push(`${what} ${n} has the name of the standard ${std.kind === 'fb' ? 'function block' : 'function'} ${std.name}, which calls would always run`);
    const pou = project.pous.find((p) => upper(p.name) === key);
    if (pou) errors.push(`${what} ${n} clashes with the ${KIND_WORD[pou.kind]} ${pou.name} of the project; rename one of them first`);
    const dt = project.dataTypes?.find((d) => upper(d.name) === key);
    if (dt) errors.push(`${what} ${n} clashes with the data type ${dt.name} of the project; rename one of them first`);
    for (const other of others) {
      const hit = libraryNames(other).find((o) => upper(o) === key);
      if (hit) errors.push(`${what} ${n} is already defined by the library ${other.name}`);
    }
  };
  for (const p of lib.pous) check(p.name, KIND_WORD[p.kind]);
  for (const d of lib.dataTypes ?? []) check(d.name, 'data type');
  return errors;
}

/** What adding the library hides (not refused): OpenPLC blocks and the project's external blocks of the same name. */
export function libraryShadows(project: Project, lib: Pick<ProjectLibrary, 'pous'>): string[] {
  const notes: string[] = [];
  for (const p of lib.pous) {
    const key = upper(p.name);
    const ext = project.externalBlocks?.find((b) => upper(b.name) === key);
    if (ext) notes.push(`${p.name} replaces the external block of the same name: its calls now run the library's ${KIND_WORD[p.kind]}`);
    const vendor = VENDOR_BLOCKS.find((b) => upper(b.name) === key);
    if (vendor && !ext) notes.push(`${p.name} hides ${vendor.vendor ?? 'the vendor'} block ${vendor.name} (${vendor.library} library): calls of ${p.name} run the library's ${KIND_WORD[p.kind]}`);
  }
  return notes;
}

export type LibraryResult = { ok: true; project: Project } | { ok: false; errors: string[] };

/** Adds a library (refused, with every reason, when a name clashes). */
export function addLibrary(project: Project, lib: ProjectLibrary): LibraryResult {
  const errors = libraryClashes(project, lib);
  if (errors.length) return { ok: false, errors };
  return { ok: true, project: { ...project, libraries: [...(project.libraries ?? []), lib] } };
}

/** The interface of a block as text: "FUNCTION_BLOCK Conveyor (Run : BOOL; Speed : INT -> Moving : BOOL)". */
export function interfaceText(pou: Pou, dataTypes: readonly DataType[] = []): string {
  const sig = pouSignature(pou, dataTypes);
  const pins = (list: readonly { name: string; type: string; declaredType?: string }[]) =>
    list.map((p) => `${p.name} : ${p.declaredType ?? p.type}`).join('; ');
  return `${pou.kind} ${pou.name} (${sig ? `${pins(sig.inputs)} -> ${pins(sig.outputs)}` : ''})`;
}

export interface LibraryDiff {
  readonly added: readonly string[];
  readonly removed: readonly string[];
  /** Blocks whose interface (kind, pins, their types or order, result type) changed. */
  readonly changed: readonly { readonly name: string; readonly was: string; readonly now: string }[];
  /** Blocks with the same interface and a different body or comment. */
  readonly bodyChanged: readonly string[];
  readonly typesAdded: readonly string[];
  readonly typesRemoved: readonly string[];
  readonly typesChanged: readonly string[];
}

const pouBody = (p: Pou) => JSON.stringify([p.comment, p.source ?? '', p.networks.map((n) => [n.elements, n.vlinks, n.rows, n.cols]), p.variables.filter((v) => v.varClass === 'local' || v.varClass === 'temp'), p.sfc ?? null]);

/** What replacing `old` by `next` changes. */
export function diffLibrary(old: Pick<ProjectLibrary, 'pous' | 'dataTypes'>, next: Pick<ProjectLibrary, 'pous' | 'dataTypes'>): LibraryDiff {
  const oldBy = new Map(old.pous.map((p) => [upper(p.name), p]));
  const nextBy = new Map(next.pous.map((p) => [upper(p.name), p]));
  const changed: { name: string; was: string; now: string }[] = [];
  const bodyChanged: string[] = [];
  for (const [key, p] of nextBy) {
    const before = oldBy.get(key);
    if (!before) continue;
    const was = interfaceText(before, old.dataTypes);
    const now = interfaceText(p, next.dataTypes);
    if (was !== now || (before.returnType ?? '') !== (p.returnType ?? '')) changed.push({ name: p.name, was, now });
    else if (pouBody(before) !== pouBody(p)) bodyChanged.push(p.name);
  }
  const oldTypes = new Map((old.dataTypes ?? []).map((d) => [upper(d.name), d]));
  const nextTypes = new Map((next.dataTypes ?? []).map((d) => [upper(d.name), d]));
  return {
    added: next.pous.filter((p) => !oldBy.has(upper(p.name))).map((p) => p.name),
    removed: old.pous.filter((p) => !nextBy.has(upper(p.name))).map((p) => p.name),
    changed,
    bodyChanged,
    typesAdded: [...nextTypes.values()].filter((d) => !oldTypes.has(upper(d.name))).map((d) => d.name),
    typesRemoved: [...oldTypes.values()].filter((d) => !nextTypes.has(upper(d.name))).map((d) => d.name),
    typesChanged: [...nextTypes.values()]
      .filter((d) => oldTypes.has(upper(d.name)) && JSON.stringify([d.def, d.initial ?? '']) !== JSON.stringify([oldTypes.get(upper(d.name))!.def, oldTypes.get(upper(d.name))!.initial ?? '']))
      .map((d) => d.name),
  };
}

export type LibraryUpdate =
  | {
      ok: true;
      project: Project;
      diff: LibraryDiff;
      /** Uses of blocks or types the update removes or whose interface it changes: they need attention. */
      affected: readonly LibraryUse[];
      /** True when the file is the one the library was read from (same hash): nothing to do. */
      same: boolean;
    }
  | { ok: false; errors: string[] };

/**
 * Replaces the library named `name` by `next` (read from a newer file). Keeps its name (and place
 * in the list). Refused when a name of `next` clashes with the project or another library.
 * Uses of what it removes become LD-E01 errors at the boxes (the engine's check); `affected` lists
 * them, and the uses of blocks whose interface changed, beforehand.
 */
export function updateLibrary(project: Project, name: string, next: ProjectLibrary): LibraryUpdate {
  const old = findLibrary(project, name);
  if (!old) return { ok: false, errors: [`the project has no library named ${name}`] };
  const renamed: ProjectLibrary = { ...next, name: old.name, pous: next.pous.map((p) => libraryPou(old.name, p)) };
  const errors = libraryClashes(project, renamed, old.name);
  if (errors.length) return { ok: false, errors };
  const diff = diffLibrary(old, renamed);
  const touched = [...diff.removed, ...diff.changed.map((c) => c.name), ...diff.typesRemoved, ...diff.typesChanged];
  return {
    ok: true,
    project: { ...project, libraries: project.libraries!.map((l) => (l === old ? renamed : l)) },
    diff,
    affected: usesOf(project, touched, old.name),
    same: old.hash === next.hash,
  };
}

export type LibraryRemoval = { ok: true; project: Project } | { ok: false; uses: readonly LibraryUse[]; errors: string[] };

/** Removes the library: refused while the project (or another library) uses one of its blocks or types. */
export function removeLibrary(project: Project, name: string): LibraryRemoval {
  const lib = findLibrary(project, name);
  if (!lib) return { ok: false, uses: [], errors: [`the project has no library named ${name}`] };
  const uses = libraryUses(project, lib.name);
  if (uses.length)
    return {
      ok: false,
      uses,
      errors: [`the library ${lib.name} is still used in ${uses.length} place${uses.length === 1 ? '' : 's'}; remove those uses first`],
    };
  const rest = project.libraries!.filter((l) => l !== lib);
  const { libraries: _dropped, ...without } = project;
  return { ok: true, project: rest.length ? { ...project, libraries: rest } : without };
}

/** A library POU's id: stable over updates, never one of the project's. */
export const libraryPouId = (library: string, pou: string): PouId => `library:${library}:${pou}` as PouId;

/** The POU as a library keeps it: its library id. */
export function libraryPou(library: string, pou: Pou): Pou {
  return { ...pou, id: libraryPouId(library, pou.name) };
}

/** The library POU of that id (`library:<library>:<pou>`), with its library. */
export function findLibraryPou(project: Pick<Project, 'libraries'>, id: string): { library: ProjectLibrary; pou: Pou } | undefined {
  for (const library of project.libraries ?? []) {
    const pou = library.pous.find((p) => p.id === id);
    if (pou) return { library, pou };
  }
  return undefined;
}

/** The library that defines the block or data type `name`, if one does. */
export function libraryOf(project: Pick<Project, 'libraries'>, name: string): ProjectLibrary | undefined {
  return project.libraries?.find((l) => libraryNames(l).some((n) => upper(n) === upper(name)));
}

const expanded = new WeakMap<Project, Project>();

/**
 * The project the engine compiles and checks: the libraries' POUs after the project's own, their
 * data types after the project's. Memoised per project (projects are immutable).
 */
export function withLibraries(project: Project): Project {
  const libs = project.libraries;
  if (!libs?.length) return project;
  let out = expanded.get(project);
  if (!out) {
    // `libraries` stays for the messages that name them; its blocks resolve as the POUs here first.
    const types = [...(project.dataTypes ?? []), ...libs.flatMap((l) => l.dataTypes ?? [])];
    out = { ...project, pous: [...project.pous, ...libs.flatMap((l) => l.pous)], ...(types.length ? { dataTypes: types } : {}) };
    expanded.set(project, out);
  }
  return out;
}

/**
 * `sha256:` and the hex SHA-256 of the text (UTF-8): a library's version. Computed with
 * @noble/hashes rather than Web Crypto, which exists only in a secure context (https, localhost),
 * while the gateway may be reached over plain http on a plant network.
 */
export async function libraryHash(text: string): Promise<string> {
  return Promise.resolve(`sha256:${bytesToHex(sha256(new TextEncoder().encode(text)))}`);
}

/** The short form of a hash shown in lists: its first 12 hex digits. */
export const shortHash = (hash: string): string => hash.replace(/^sha256:/, '').slice(0, 12);
