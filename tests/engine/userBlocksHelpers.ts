// Test helper: projects with user FUNCTION_BLOCKs and FUNCTIONs written in LD.
import { newPou, newProject } from '../../src/model/factory';
import type { Network, Pou, PouKind, Profile, Project, VarClass, Variable } from '../../src/model/project';
import { vars } from './ladder';

/** `vars` specs of one variable class: `io('input', 'Start BOOL', 'Stop BOOL')`. */
export function io(varClass: VarClass, ...specs: string[]): Variable[] {
  return vars(...specs).map((v) => ({ ...v, varClass }));
}

export function pou(
  name: string,
  kind: PouKind,
  variables: readonly Variable[],
  networks: readonly Network[],
  returnType?: string,
): Pou {
  return newPou(name, { kind, variables, networks, ...(returnType ? { returnType } : {}) });
}

/** A project whose first POU is the program Main. */
export function multiProject(pous: readonly Pou[], profile: Profile = 'iec', globals: readonly Variable[] = []): Project {
  return newProject('Test', { pous, profile, globals });
}
