// A generated program for bench:sim: N networks of contacts, parallel branches and coils, with a
// TON every 10 networks and a CTU every 10 networks (offset by 5), on 16 inputs and 16 outputs.
import type { LdElement } from '../src/model/elements';
import { newNetwork, newProject, variable } from '../src/model/factory';
import { newId, type ElementId } from '../src/model/ids';
import type { Network, Project, Variable } from '../src/model/project';

const COLS = 8;
const eid = () => newId<'ElementId'>('e') as ElementId;
const contact = (row: number, col: number, name: string, type: 'NO' | 'NC' = 'NO'): LdElement => ({ id: eid(), kind: 'contact', contact: type, variable: name, row, col });
const coil = (row: number, name: string): LdElement => ({ id: eid(), kind: 'coil', coil: 'COIL', variable: name, row, col: COLS - 1 });
const links = (row: number, from: number, to: number): LdElement[] =>
  Array.from({ length: Math.max(0, to - from + 1) }, (_, i) => ({ id: eid(), kind: 'link', row, col: from + i }));

export function generateSimProgram(networks: number): Project {
  const variables: Variable[] = [];
  for (let i = 0; i < 16; i++) variables.push(variable(`I${i}`, 'BOOL', { location: `%IX${i >> 3}.${i & 7}` }));
  for (let i = 0; i < 16; i++) variables.push(variable(`Q${i}`, 'BOOL', { location: `%QX${i >> 3}.${i & 7}` }));
  for (let i = 0; i < networks; i++) variables.push(variable(`M${i}`, 'BOOL'));
  const nets: Network[] = [];
  for (let i = 0; i < networks; i++) {
    const input = `I${i % 16}`;
    const prev = `M${(i + networks - 1) % networks}`;
    const target = i % 50 === 49 ? `Q${(i / 50) % 16 | 0}` : `M${i}`;
    if (i % 10 === 0) {
      const t = `T${i / 10}`;
      variables.push(variable(t, 'TON'));
      nets.push(
        newNetwork({
          rows: 2,
          cols: COLS,
          elements: [contact(0, 0, input), contact(0, 1, prev, 'NC'), { id: eid(), kind: 'box', blockType: 'TON', instance: t, row: 0, col: 2, inputs: { PT: 'T#50ms' }, outputs: {} }, ...links(0, 4, COLS - 2), coil(0, target)],
          vlinks: [],
        }),
      );
    } else if (i % 10 === 5) {
      const c = `C${(i - 5) / 10}`;
      variables.push(variable(c, 'CTU'));
      nets.push(
        newNetwork({
          rows: 3,
          cols: COLS,
          elements: [contact(0, 0, input), contact(0, 1, prev), { id: eid(), kind: 'box', blockType: 'CTU', instance: c, row: 0, col: 2, inputs: { R: `I${(i + 3) % 16}`, PV: '100' }, outputs: {} }, ...links(0, 4, COLS - 2), coil(0, target)],
          vlinks: [],
        }),
      );
    } else {
      nets.push(
        newNetwork({
          rows: 2,
          cols: COLS,
          elements: [contact(0, 0, input), contact(0, 1, prev, 'NC'), contact(0, 2, `M${(i + 7) % networks}`), ...links(0, 3, COLS - 2), coil(0, target), contact(1, 0, `M${i}`), links(1, 1, 1)[0]!],
          vlinks: [{ row: 0, boundary: 2 }],
        }),
      );
    }
  }
  const p = newProject(`bench ${networks} networks`);
  return { ...p, pous: [{ ...p.pous[0]!, variables, networks: nets }] };
}
