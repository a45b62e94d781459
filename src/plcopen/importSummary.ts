// What the import report says about an imported project: which POU to open first (the program the
// configuration's resource runs, not the first POU of the file, which is often a function) and how
// many POUs there are in each body language (an ST function is not an "LD POU").
import type { PouId } from '../model/ids';
import { bodyLanguage, libraryInfo } from '../model/codesysUtil';
import { POU_LANGUAGES, type Project } from '../model/project';

/**
 * The POU to open after an import: the program of the first task's first program instance (the
 * first task that runs one whose POU is in the project); else the first PROGRAM; else the first
 * LD POU; else the first POU.
 */
export function pouToOpen(project: Project): PouId | undefined {
  const byName = (name: string) => project.pous.find((p) => p.name.toUpperCase() === name.trim().toUpperCase());
  // A program whose body the simulator runs first (a CODESYS task runs a CFC PLC_PRG beside an LD program).
  for (const runs of [true, false])
    for (const task of project.tasks)
      for (const inst of task.programs) {
        const pou = byName(inst.pou);
        if (pou && (!runs || pou.language !== 'FBD')) return pou.id;
      }
  return (
    project.pous.find((p) => p.kind === 'PROGRAM')?.id ??
    project.pous.find((p) => p.language === 'LD')?.id ??
    project.pous[0]?.id
  );
}

/**
 * "1 POU (LD)", "7 POUs (3 LD, 2 ST, 1 SFC, 1 FBD)": POUs counted by their body language (a
 * CODESYS CFC body as CFC); blocks of a vendor library the import added count as "library".
 */
export function pouCountText(project: Project): string {
  const n = project.pous.length;
  const own = project.pous.filter((p) => !libraryInfo(p));
  const counts = [...POU_LANGUAGES, 'CFC']
    .map((lang) => [lang, own.filter((p) => bodyLanguage(p) === lang).length] as const)
    .concat([['library', n - own.length] as const])
    .filter(([, k]) => k > 0);
  const head = `${n} POU${n === 1 ? '' : 's'}`;
  if (!counts.length) return head;
  if (counts.length === 1) return `${head} (${counts[0]![0]})`;
  return `${head} (${counts.map(([lang, k]) => `${k} ${lang}`).join(', ')})`;
}

/**
 * "Libraries: Conveyors (2 blocks). 2 test scenarios." — what a Rungsmith export brought back
 * besides POUs (rungsmithData.ts); empty when nothing.
 */
export function extrasText(project: Project): string {
  const libs = project.libraries ?? [];
  const n = project.scenarios?.length ?? 0;
  return [
    libs.length ? `Libraries: ${libs.map((l) => `${l.name} (${l.pous.length} block${l.pous.length === 1 ? '' : 's'})`).join(', ')}.` : '',
    n ? `${n} test scenario${n === 1 ? '' : 's'}.` : '',
    project.plant ? `Machine: ${project.plant.id}.` : '',
  ]
    .filter(Boolean)
    .join(' ');
}
