// What the import report says about an imported project: which POU to open first (the program the
// configuration's resource runs, not the first POU of the file, which is often a function) and how
// many POUs there are in each body language (an ST function is not an "LD POU").
import type { PouId } from '../model/ids';
import { POU_LANGUAGES, type Project } from '../model/project';

/**
 * The POU to open after an import: the program of the first task's first program instance (the
 * first task that runs one whose POU is in the project); else the first PROGRAM; else the first
 * LD POU; else the first POU.
 */
export function pouToOpen(project: Project): PouId | undefined {
  const byName = (name: string) => project.pous.find((p) => p.name.toUpperCase() === name.trim().toUpperCase());
  for (const task of project.tasks)
    for (const inst of task.programs) {
      const pou = byName(inst.pou);
      if (pou) return pou.id;
    }
  return (
    project.pous.find((p) => p.kind === 'PROGRAM')?.id ??
    project.pous.find((p) => p.language === 'LD')?.id ??
    project.pous[0]?.id
  );
}

/** "1 POU (LD)", "7 POUs (3 LD, 2 ST, 1 SFC, 1 FBD)": POUs counted by their body language. */
export function pouCountText(project: Project): string {
  const n = project.pous.length;
  const counts = POU_LANGUAGES.map((lang) => [lang, project.pous.filter((p) => p.language === lang).length] as const).filter(
    ([, k]) => k > 0,
  );
  const head = `${n} POU${n === 1 ? '' : 's'}`;
  if (!counts.length) return head;
  if (counts.length === 1) return `${head} (${counts[0]![0]})`;
  return `${head} (${counts.map(([lang, k]) => `${k} ${lang}`).join(', ')})`;
}
