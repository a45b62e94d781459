// The project's block library for the editor, kept as the same object while no block interface
// changes. blockLibrary() (model/library.ts) is memoised on the `pous` array, so every edit of a
// network (or of a program's variables) gave a new library: every network's column widths were
// measured again and every network on screen was redrawn on each keystroke. The signatures of the
// project's own blocks depend only on each block POU's name, kind, return type, variables and
// comment, and on the external blocks, data types and libraries (a PROGRAM is no block: its name and kind
// count, its variables do not): while those are the same objects, the library is the same object.
// `userPou` (the body of a block) always answers from the newest project this was asked for.
import { blockLibrary, type BlockLibrary } from '../model/library';
import type { Project } from '../model/project';

const interfaceKey = (p: Project): unknown[] => {
  const key: unknown[] = [p.externalBlocks, p.dataTypes, p.libraries];
  // A PROGRAM is no block: its variables (a name declared from the canvas) change no signature.
  for (const pou of p.pous)
    if (pou.kind === 'PROGRAM') key.push(pou.name, pou.kind);
    else key.push(pou.name, pou.kind, pou.returnType, pou.variables, pou.comment);
  return key;
};

const sameKey = (a: readonly unknown[], b: readonly unknown[]) =>
  a.length === b.length && a.every((x, i) => Object.is(x, b[i]));

interface Entry {
  readonly key: readonly unknown[];
  project: Project;
  readonly lib: BlockLibrary;
}

let last: Entry | undefined;

/** The block library of `project`: the previous object when no block interface changed since. */
export function stableLibrary(project: Project): BlockLibrary {
  if (last?.project === project) return last.lib;
  const key = interfaceKey(project);
  if (last && sameKey(last.key, key)) {
    last.project = project;
    return last.lib;
  }
  const built = blockLibrary(project);
  const entry: Entry = {
    key,
    project,
    lib: { ...built, userPou: (name) => blockLibrary(entry.project).userPou(name) },
  };
  last = entry;
  return entry.lib;
}
