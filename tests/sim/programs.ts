// Small programs for the simulator tests, built from the project model.
import type { LdElement, VLink } from '../../src/model/elements';
import { newNetwork, newProject, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Network, Project, Variable } from '../../src/model/project';

let n = 0;
const id = () => `e${++n}` as ElementId;
const contact = (row: number, col: number, v: string, type: 'NO' | 'NC' = 'NO'): LdElement => ({ id: id(), kind: 'contact', contact: type, variable: v, row, col });
const coil = (row: number, col: number, v: string): LdElement => ({ id: id(), kind: 'coil', coil: 'COIL', variable: v, row, col });
const link = (row: number, col: number): LdElement => ({ id: id(), kind: 'link', row, col });

const net = (rows: number, cols: number, elements: LdElement[], vlinks: VLink[] = [], label?: string): Network =>
  newNetwork({ rows, cols, elements, vlinks, ...(label ? { label } : {}) });

function program(variables: Variable[], networks: Network[]): Project {
  const p = newProject('test');
  const main = p.pous[0]!;
  return { ...p, pous: [{ ...main, variables, networks }] };
}

const motorVariables = (): Variable[] => [
  variable('Start', 'BOOL', { location: '%IX0.0' }),
  variable('Stop', 'BOOL', { location: '%IX0.1' }),
  variable('Motor', 'BOOL', { location: '%QX0.0' }),
];

/** Start (NO) OR Motor (seal-in), then Stop (NC), drives Motor. */
export const motorNetwork = (): Network =>
  net(2, 4, [contact(0, 0, 'Start'), contact(0, 1, 'Stop', 'NC'), link(0, 2), coil(0, 3, 'Motor'), contact(1, 0, 'Motor')], [{ row: 0, boundary: 1 }]);

export const motorProgram = (): Project => program(motorVariables(), [motorNetwork()]);

/** Motor, then a copy of Motor into Lamp, then a copy of Lamp into Horn: three networks to break in. */
export const threeNetworks = (): Project =>
  program(
    [...motorVariables(), variable('Lamp', 'BOOL', { location: '%QX0.1' }), variable('Horn', 'BOOL')],
    [motorNetwork(), net(1, 2, [contact(0, 0, 'Motor'), coil(0, 1, 'Lamp')]), net(1, 2, [contact(0, 0, 'Lamp'), coil(0, 1, 'Horn')])],
  );

/** Enable drives TON T1 (PT 100 ms); T1.Q drives Lamp. */
export const timerProgram = (): Project =>
  program(
    [variable('Enable', 'BOOL', { location: '%IX0.0', initial: 'TRUE' }), variable('Lamp', 'BOOL', { location: '%QX0.0' }), variable('T1', 'TON')],
    [
      net(2, 4, [
        contact(0, 0, 'Enable'),
        { id: id(), kind: 'box', blockType: 'TON', instance: 'T1', row: 0, col: 1, inputs: { PT: 'T#100ms' }, outputs: {} },
        coil(0, 3, 'Lamp'),
      ]),
    ],
  );

/** Network 2 (label LOOP) jumps to itself unconditionally: a runaway scan. */
export const runawayProgram = (): Project =>
  program(motorVariables(), [motorNetwork(), net(1, 2, [{ id: id(), kind: 'jump', target: 'LOOP', row: 0, col: 0 }], [], 'LOOP')]);

/** A coil on an undeclared variable: LD-R08. */
export const brokenProgram = (): Project => program(motorVariables(), [net(1, 2, [contact(0, 0, 'Start'), coil(0, 1, 'Nowhere')])]);
