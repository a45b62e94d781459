// Example projects the editor offers in its menu; each passes checkProject with no error and
// no warning (tests/engine/examples.test.ts runs them).
import type { BoxElement, CoilType, ContactType, LdElement, VLink } from './elements';
import { newNetwork, newPou, newProject, variable } from './factory';
import { newId, type ElementId } from './ids';
import type { Network, Project, Scenario, Variable } from './project';

export interface Example {
  readonly id: string;
  readonly title: string;
  readonly description: string;
  build(): Project;
}

const COLS = 10;
const eid = (): ElementId => newId<'ElementId'>('e');

/** The ladder parts the examples are drawn with (also the benches' generated programs). */
export const contact = (row: number, col: number, name: string, type: ContactType = 'NO'): LdElement => ({
  id: eid(),
  kind: 'contact',
  contact: type,
  variable: name,
  row,
  col,
});
/** A coil in the last column, touching the right rail. */
export const coil = (row: number, name: string, type: CoilType = 'COIL'): LdElement => ({
  id: eid(),
  kind: 'coil',
  coil: type,
  variable: name,
  row,
  col: COLS - 1,
});
/** A jump in the last column, touching the right rail. */
export const jump = (row: number, target: string): LdElement => ({
  id: eid(),
  kind: 'jump',
  target,
  row,
  col: COLS - 1,
});
/** Horizontal lines on `row` over columns from..to (inclusive). */
export const line = (row: number, from: number, to: number): LdElement[] =>
  Array.from({ length: Math.max(0, to - from + 1) }, (_, i) => ({
    id: eid(),
    kind: 'link',
    row,
    col: from + i,
  }));
/** Contacts in series on row 0 from the left rail (columns 0, 1, ...), wired across to `end` in the last column. */
export const rung = (contacts: LdElement[], end: LdElement): LdElement[] => [
  ...contacts,
  ...line(0, contacts.length, COLS - 2),
  end,
];
export const box = (
  row: number,
  col: number,
  blockType: string,
  instance: string | undefined,
  inputs: Record<string, string>,
  outputs: Record<string, string> = {},
): BoxElement => ({
  id: eid(),
  kind: 'box',
  blockType,
  ...(instance ? { instance } : {}),
  row,
  col,
  inputs,
  outputs,
});

export function network(
  title: string,
  comment: string,
  elements: LdElement[],
  extra: { rows?: number; vlinks?: VLink[]; label?: string } = {},
): Network {
  return newNetwork({
    title,
    comment,
    rows: extra.rows ?? 2,
    cols: COLS,
    elements,
    vlinks: extra.vlinks ?? [],
    ...(extra.label ? { label: extra.label } : {}),
  });
}

function program(
  name: string,
  description: string,
  variables: Variable[],
  networks: Network[],
  cycleMs = 10,
  scenarios: Scenario[] = [],
): Project {
  const main = newPou('Main', { variables, networks, comment: description });
  return newProject(name, {
    description,
    ...(scenarios.length ? { scenarios } : {}),
    pous: [main],
    tasks: [
      { name: 'MainTask', cycleMs, priority: 1, programs: [{ instance: 'MainInstance', pou: main.name }] },
    ],
  });
}

const v = (name: string, type: string, comment: string, location?: string, initial?: string): Variable =>
  variable(name, type, { comment, ...(location ? { location } : {}), ...(initial ? { initial } : {}) });

function motorStartStop(): Project {
  return program(
    'Motor start/stop',
    'The classic seal-in circuit: Start runs the motor, the motor keeps itself running through its own contact until Stop is pressed.',
    [
      v('Start', 'BOOL', 'Start push button (normally open, TRUE while pressed)', '%IX0.0'),
      v(
        'Stop',
        'BOOL',
        'Stop push button (TRUE while pressed; read through a normally closed contact)',
        '%IX0.1',
      ),
      v('Motor', 'BOOL', 'Motor contactor', '%QX0.0'),
    ],
    [
      network(
        'Motor seal-in',
        'Start OR Motor (seal-in), AND NOT Stop, drives the motor. Stop wins when both buttons are pressed.',
        [
          ...rung([contact(0, 0, 'Start'), contact(0, 1, 'Stop', 'NC')], coil(0, 'Motor')),
          contact(1, 0, 'Motor'),
        ],
        { vlinks: [{ row: 0, boundary: 1 }] },
      ),
    ],
    10,
    [MOTOR_SCENARIO],
  );
}

/** Test scenario (docs/scenarios.md): Start seals in, Stop wins, Stop held blocks Start. */
const MOTOR_SCENARIO: Scenario = {
  name: 'Start seals in, Stop wins',
  csv: `# Inputs are set before the scan's input read; expect columns are checked after the scan.
scan,Start,Stop,expect Motor
1,0,0,0
2,1,0,1
3,0,,1
10,,,1
11,,1,0
12,,0,0
13,1,1,0
14,,0,1
`,
};

function trafficLight(): Project {
  const timerNet = (title: string, comment: string, condition: LdElement, timer: string, pt: string) =>
    network(title, comment, [
      condition,
      ...line(0, 1, 1),
      box(0, 2, 'TON', timer, { PT: pt }),
      ...line(0, 4, COLS - 1),
    ]);
  const lampNet = (title: string, lamp: string, contacts: LdElement[]) =>
    network(title, `${lamp} lamp.`, rung(contacts, coil(0, lamp)), { rows: 1 });
  return program(
    'Traffic light',
    'Three on-delay timers in a chain: red for 5 s, green for 4 s, yellow for 1 s, then red again (the restart takes two scans: the end of yellow resets the chain in the next scan).',
    [
      v('Red', 'BOOL', 'Red lamp', '%QX0.0'),
      v('Yellow', 'BOOL', 'Yellow lamp', '%QX0.1'),
      v('Green', 'BOOL', 'Green lamp', '%QX0.2'),
      v('RedTime', 'TON', 'Times the red phase (5 s)'),
      v('GreenTime', 'TON', 'Times the green phase (4 s), started when red is over'),
      v('YellowTime', 'TON', 'Times the yellow phase (1 s), started when green is over'),
    ],
    [
      timerNet(
        'Red phase',
        'Red runs until its timer is done; the end of yellow restarts the cycle.',
        contact(0, 0, 'YellowTime.Q', 'NC'),
        'RedTime',
        'T#5s',
      ),
      timerNet(
        'Green phase',
        'Green starts when the red phase is over.',
        contact(0, 0, 'RedTime.Q'),
        'GreenTime',
        'T#4s',
      ),
      timerNet(
        'Yellow phase',
        'Yellow starts when the green phase is over.',
        contact(0, 0, 'GreenTime.Q'),
        'YellowTime',
        'T#1s',
      ),
      lampNet('Red lamp', 'Red', [contact(0, 0, 'RedTime.Q', 'NC')]),
      lampNet('Green lamp', 'Green', [contact(0, 0, 'RedTime.Q'), contact(0, 1, 'GreenTime.Q', 'NC')]),
      lampNet('Yellow lamp', 'Yellow', [contact(0, 0, 'GreenTime.Q')]),
    ],
    10,
    [TRAFFIC_SCENARIO],
  );
}

/** Test scenario: one full cycle, red 5 s, green 4 s, yellow 1 s, red again (100 ms scans). */
const TRAFFIC_SCENARIO: Scenario = {
  name: 'One full light cycle',
  csv: `# cycle: 100ms
scan,expect Red,expect Green,expect Yellow,expect RedTime.ET ~ 100ms
1,1,0,0,0
26,1,0,0,2500
50,1,0,0,4900
51,0,1,0,*
91,0,0,1,*
101,0,0,1,*
102,1,0,0,*
`,
};

function partsCounter(): Project {
  return program(
    'Parts counter',
    'An up counter counts parts passing a sensor; after 10 parts the Done lamp lights until Reset is pressed.',
    [
      v('PartSensor', 'BOOL', 'Part present sensor (one pulse per part)', '%IX0.0'),
      v('Reset', 'BOOL', 'Reset push button: clears the count', '%IX0.1'),
      v('Done', 'BOOL', 'Batch complete lamp', '%QX0.0'),
      v('Parts', 'CTU', 'Counts rising edges of PartSensor'),
      v('PartCount', 'INT', 'Parts counted so far'),
    ],
    [
      network(
        'Count parts',
        'Each rising edge of the sensor adds one; Reset clears the count; Q (Done) when 10 parts are counted.',
        [
          contact(0, 0, 'PartSensor'),
          ...line(0, 1, 1),
          box(0, 2, 'CTU', 'Parts', { R: 'Reset', PV: '10' }, { CV: 'PartCount' }),
          ...line(0, 4, COLS - 2),
          coil(0, 'Done'),
        ],
        { rows: 3 },
      ),
    ],
  );
}

function jumpLabel(): Project {
  return program(
    'Jump over a network',
    'While the maintenance key is on, a jump skips the conveyor network: the conveyor keeps its last state and the maintenance lamp lights.',
    [
      v('Maintenance', 'BOOL', 'Maintenance key switch', '%IX0.0'),
      v('PartWaiting', 'BOOL', 'Part waiting at the conveyor entry', '%IX0.1'),
      v('Conveyor', 'BOOL', 'Conveyor motor', '%QX0.0'),
      v('MaintenanceLamp', 'BOOL', 'Maintenance mode lamp', '%QX0.1'),
    ],
    [
      network(
        'Maintenance?',
        'In maintenance mode, skip the conveyor network.',
        rung([contact(0, 0, 'Maintenance')], jump(0, 'MAINT')),
        { rows: 1 },
      ),
      network(
        'Conveyor',
        'Runs the conveyor while a part is waiting (skipped in maintenance).',
        rung([contact(0, 0, 'PartWaiting')], coil(0, 'Conveyor')),
        { rows: 1 },
      ),
      network(
        'Maintenance lamp',
        'The jump lands here.',
        rung([contact(0, 0, 'Maintenance')], coil(0, 'MaintenanceLamp')),
        { rows: 1, label: 'MAINT' },
      ),
    ],
  );
}

export const EXAMPLES: readonly Example[] = [
  {
    id: 'motor-start-stop',
    title: 'Motor start/stop (seal-in)',
    description: 'Start and Stop push buttons with a self-holding motor contact.',
    build: motorStartStop,
  },
  {
    id: 'traffic-light',
    title: 'Traffic light (TON chain)',
    description: 'Red 5 s, green 4 s, yellow 1 s with three on-delay timers.',
    build: trafficLight,
  },
  {
    id: 'parts-counter',
    title: 'Parts counter (CTU)',
    description: 'Counts parts from a sensor, lights Done at 10, Reset clears.',
    build: partsCounter,
  },
  {
    id: 'jump-label',
    title: 'Jump and label',
    description: 'A conditional jump skips a network and lands on a labelled one.',
    build: jumpLabel,
  },
];
