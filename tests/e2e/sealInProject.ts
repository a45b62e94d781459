// A generated project of `count` seal-in rungs (3 contacts, 6 links, a coil and a parallel contact
// each: 11 elements, 2 rows, 4 BOOL variables), for the editor benchmark and the print tests.
import type { LdElement } from '../../src/model/elements';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Network, Project, Variable } from '../../src/model/project';

export function sealInProject(count: number, name = 'Bench'): Project {
  const networks: Network[] = [];
  const variables: Variable[] = [];
  for (let i = 0; i < count; i++) {
    const id = (k: string) => `b${i}_${k}` as ElementId;
    const names = [`Start${i}`, `Stop${i}`, `Guard${i}`, `Motor${i}`];
    for (const n of names) variables.push(variable(n, 'BOOL'));
    const elements: LdElement[] = [
      { kind: 'contact', contact: 'NO', variable: names[0]!, id: id('a'), row: 0, col: 0 },
      { kind: 'contact', contact: 'NC', variable: names[1]!, id: id('b'), row: 0, col: 1 },
      { kind: 'contact', contact: 'NO', variable: names[2]!, id: id('c'), row: 0, col: 2 },
      ...[3, 4, 5, 6, 7, 8].map((col) => ({ kind: 'link' as const, id: id(`l${col}`), row: 0, col })),
      { kind: 'coil', coil: 'COIL', variable: names[3]!, id: id('q'), row: 0, col: 9 },
      { kind: 'contact', contact: 'NO', variable: names[3]!, id: id('m'), row: 1, col: 0 },
    ];
    networks.push(
      newNetwork({
        title: `Motor ${i}`,
        comment: i % 5 === 0 ? `Seal-in circuit number ${i}` : '',
        rows: 2,
        elements,
        vlinks: [{ row: 0, boundary: 1 }],
      }),
    );
  }
  return newProject(name, { pous: [newPou('Main', { networks, variables })] });
}
