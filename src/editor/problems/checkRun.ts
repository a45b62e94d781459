// One run of the engine's checks, with a checker failure reported as a diagnostic, not thrown.
// Shared by the checker worker and the in-page fallback.
import type { Diagnostic } from '../../engine/api';
import { checkProject } from '../../engine/check';
import type { Project } from '../../model/project';

export function runChecks(project: Project): Diagnostic[] {
  try {
    return checkProject(project);
  } catch (e) {
    return [
      {
        severity: 'error',
        rule: 'LD-E000',
        pou: project.pous[0]?.name ?? '',
        network: -1,
        message: `The checker stopped on this program (${(e as Error).message}); please report it with the project file.`,
      },
    ];
  }
}
