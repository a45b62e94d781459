// Compact builders for test projects (grid coordinates as in src/model/grid.ts).
import type {
  BoxElement,
  CoilElement,
  CoilType,
  ContactElement,
  ContactType,
  LdElement,
  VLink,
} from '../../src/model/elements';
import { newNetwork, newProject, newPou, variable } from '../../src/model/factory';
import { newId, type ElementId } from '../../src/model/ids';
import type { Network, Pou, Project, Variable } from '../../src/model/project';

const eid = () => newId<'ElementId'>('e') as ElementId;

export const contact = (row: number, col: number, v: string, type: ContactType = 'NO'): ContactElement => ({
  id: eid(),
  kind: 'contact',
  row,
  col,
  contact: type,
  variable: v,
});
export const coil = (row: number, col: number, v: string, type: CoilType = 'COIL'): CoilElement => ({
  id: eid(),
  kind: 'coil',
  row,
  col,
  coil: type,
  variable: v,
});
export const link = (row: number, col: number): LdElement => ({ id: eid(), kind: 'link', row, col });
export const links = (row: number, from: number, to: number): LdElement[] =>
  Array.from({ length: to - from }, (_, i) => link(row, from + i));
export const jump = (row: number, col: number, target: string): LdElement => ({
  id: eid(),
  kind: 'jump',
  row,
  col,
  target,
});
export const ret = (row: number, col: number): LdElement => ({ id: eid(), kind: 'return', row, col });
export const box = (
  row: number,
  col: number,
  blockType: string,
  inputs: Record<string, string> = {},
  outputs: Record<string, string> = {},
  instance?: string,
): BoxElement => ({
  id: eid(),
  kind: 'box',
  row,
  col,
  blockType,
  inputs,
  outputs,
  ...(instance ? { instance } : {}),
});
export const vlink = (row: number, boundary: number): VLink => ({ row, boundary });

export const net = (
  rows: number,
  cols: number,
  elements: LdElement[],
  vlinks: VLink[] = [],
  extra: Partial<Network> = {},
): Network => newNetwork({ rows, cols, elements, vlinks, ...extra });

export const bool = (name: string, location?: string, extra: Partial<Variable> = {}): Variable =>
  variable(name, 'BOOL', { ...(location ? { location } : {}), ...extra });

export function project(pous: Pou[], extra: Partial<Project> = {}): Project {
  const p = newProject('Test', extra);
  const first = pous[0]!;
  return {
    ...p,
    pous,
    tasks: [
      {
        name: 'MainTask',
        cycleMs: 10,
        priority: 1,
        programs: [{ instance: 'MainInstance', pou: first.name }],
      },
    ],
    ...extra,
  };
}
export const pou = (
  name: string,
  variables: Variable[],
  networks: Network[],
  extra: Partial<Pou> = {},
): Pou => newPou(name, { variables, networks, ...extra });

/** Start (NO) and Stop (NC) in series, Motor coil, Motor seal-in in parallel with Start. */
export function motorSealIn(): Project {
  return project([
    pou(
      'Main',
      [bool('Start', '%IX0.0'), bool('Stop', '%IX0.1'), bool('Motor', '%QX0.0')],
      [
        net(
          2,
          4,
          [
            contact(0, 0, 'Start'),
            contact(0, 1, 'Stop', 'NC'),
            ...links(0, 2, 3),
            coil(0, 3, 'Motor'),
            contact(1, 0, 'Motor'),
          ],
          [vlink(0, 1)],
        ),
      ],
    ),
  ]);
}
