// Programs for bench:engine's user-FB case: N calls of a 3-network Motor FB against the same logic
// written inline (3 networks per motor), with the same variables and results.
import type { LdElement } from '../src/model/elements';
import { newNetwork, newPou, newProject, variable } from '../src/model/factory';
import type { ElementId } from '../src/model/ids';
import type { Network, Project, Variable } from '../src/model/project';

let ids = 0;
const id = (): ElementId => `b${++ids}` as ElementId;
const contact = (row: number, col: number, v: string, nc = false): LdElement => ({ id: id(), kind: 'contact', row, col, contact: nc ? 'NC' : 'NO', variable: v });
const coil = (row: number, col: number, v: string): LdElement => ({ id: id(), kind: 'coil', row, col, coil: 'COIL', variable: v });
const link = (row: number, col: number): LdElement => ({ id: id(), kind: 'link', row, col });

/** The Motor logic over variable names: seal-in, an on-delay, a permissive. */
function motorNetworks(n: { start: string; stop: string; run: string; timer: string; ready: string; fault: string; out: string }): Network[] {
  return [
    // Run := (Start OR Run) AND NOT Stop
    newNetwork({
      rows: 2,
      cols: 4,
      elements: [contact(0, 0, n.start), contact(0, 1, n.stop, true), link(0, 2), coil(0, 3, n.run), contact(1, 0, n.run)],
      vlinks: [{ row: 0, boundary: 0 }, { row: 0, boundary: 1 }],
    }),
    // Ready := TON(IN := Run, PT := T#50ms).Q
    newNetwork({
      rows: 2,
      cols: 4,
      elements: [
        contact(0, 0, n.run),
        { id: id(), kind: 'box', row: 0, col: 1, blockType: 'TON', instance: n.timer, inputs: { PT: 'T#50ms' }, outputs: {} },
        coil(0, 3, n.ready),
      ],
      vlinks: [],
    }),
    // Out := Ready AND NOT Fault
    newNetwork({ rows: 1, cols: 3, elements: [contact(0, 0, n.ready), contact(0, 1, n.fault, true), coil(0, 2, n.out)], vlinks: [] }),
  ];
}

const v = (name: string, type: string, varClass: Variable['varClass'] = 'local') => variable(name, type, { varClass });

/** Inputs every motor reads: Start cycles with the scan count (the bench drives Tick). */
export function inlineProject(count: number): Project {
  const variables: Variable[] = [v('Tick', 'BOOL'), v('Stop', 'BOOL'), v('Fault', 'BOOL')];
  const networks: Network[] = [];
  for (let k = 0; k < count; k++) {
    variables.push(v(`Run${k}`, 'BOOL'), v(`T${k}`, 'TON'), v(`Ready${k}`, 'BOOL'), v(`Out${k}`, 'BOOL'));
    networks.push(...motorNetworks({ start: 'Tick', stop: 'Stop', run: `Run${k}`, timer: `T${k}`, ready: `Ready${k}`, fault: 'Fault', out: `Out${k}` }));
  }
  return newProject('Inline', { pous: [newPou('Main', { variables, networks })] });
}

export function fbProject(count: number): Project {
  const motor = newPou('Motor', {
    kind: 'FUNCTION_BLOCK',
    variables: [
      v('Start', 'BOOL', 'input'),
      v('Stop', 'BOOL', 'input'),
      v('Fault', 'BOOL', 'input'),
      v('Out', 'BOOL', 'output'),
      v('Run', 'BOOL'),
      v('Ready', 'BOOL'),
      v('T', 'TON'),
    ],
    networks: motorNetworks({ start: 'Start', stop: 'Stop', run: 'Run', timer: 'T', ready: 'Ready', fault: 'Fault', out: 'Out' }),
  });
  const variables: Variable[] = [v('Tick', 'BOOL'), v('Stop', 'BOOL'), v('Fault', 'BOOL')];
  const networks: Network[] = [];
  for (let k = 0; k < count; k++) {
    variables.push(v(`M${k}`, 'Motor'), v(`Out${k}`, 'BOOL'));
    networks.push(
      newNetwork({
        rows: 3,
        cols: 3,
        elements: [
          contact(0, 0, 'Tick'),
          { id: id(), kind: 'box', row: 0, col: 1, blockType: 'Motor', instance: `M${k}`, inputs: { Stop: 'Stop', Fault: 'Fault' }, outputs: { Out: `Out${k}` } },
        ],
        vlinks: [],
      }),
    );
  }
  return newProject('Calls', { pous: [newPou('Main', { variables, networks }), motor] });
}
