// The lift's exercise (issue 26): answer six calls of a three-floor lift, stopping level with
// the floors, the door open only at rest and the car moving only with the door closed; the
// reference solution in ladder, a classic wrong one, and the scenario run in CI.
import { box, coil, contact, line, network } from '../model/examples';
import type { Example } from '../model/examples';
import type { LdElement, VLink } from '../model/elements';
import { newPou, newProject, variable } from '../model/factory';
import type { Network, Project, Scenario } from '../model/project';
import { plantVariables, taskText } from './exerciseKit';
import { lift } from './lift';

/**
 * Six calls answered in 100 s of PLC time (20 ms scans): 3 then 2 on the way up (the car stops at
 * 2 first), 1 and 2 on the way down (it stops at 2 first), then 3, then 1; the longest wait 26 s
 * (up to 30 s for a program that waits longer at rest). Any overrun, crash, move with the door open
 * or both contactors on fails the scenario at the scan it happens.
 */
export const LIFT_SCENARIO: Scenario = {
  name: 'Six calls answered, level with the floors',
  csv: `# plant: lift
# cycle: 20ms
# Each call button is pressed for 0.1 s. The car starts at floor 1 with its door closed.
# At 10 s the car stands at floor 2 with its door fully open (held open 2 s once fully open).
# A crash, an overrun, a move with the door not closed or both contactors on fails the scenario where it happens.
scan,lift.Call1,lift.Call2,lift.Call3,expect CallLamp1,expect CallLamp2,expect CallLamp3,expect lift.served,expect lift.floor,expect lift.misstops,expect lift.max_wait ~ 4,expect DoorOpened
1,,,1,0,0,1,0,1,0,,
6,,,0,0,0,1,0,1,0,,
200,,1,,,,,,,,,
205,,0,,0,1,1,0,0,0,,
500,,,,0,0,1,1,2,0,,1
1000,1,,,1,0,1,1,3,0,,
1005,0,,,,,,,,,,
1250,,1,,,,,,,,,
1255,,0,,1,1,0,2,*,0,,
3000,,,,0,0,0,4,1,0,,
3100,,,1,,,,,,,,
3105,,,0,0,0,1,4,1,0,,
4000,,,,0,0,0,5,3,0,,
4100,1,,,,,,,,,,
4105,0,,,1,0,0,5,3,0,,
5000,,,,0,0,0,6,1,0,26.1,
`,
};

/** Contacts on `r` from the left rail, a line across, the coil in the last column. */
const row = (r: number, contacts: LdElement[], end: LdElement): LdElement[] => [
  ...contacts,
  ...line(r, contacts.length, 8),
  end,
];
/** Series pairs of contacts in parallel, one pair a row, joined after column 1 into the coil on row 0. */
const pairs = (
  title: string,
  comment: string,
  branches: [string, string][],
  end: string,
  type: 'COIL' | 'SET' | 'RESET' = 'COIL',
): Network => {
  const elements: LdElement[] = [];
  const vlinks: VLink[] = [];
  branches.forEach(([a, b], r) => {
    elements.push(contact(r, 0, a), contact(r, 1, b));
    if (r > 0) vlinks.push({ row: r - 1, boundary: 2 });
  });
  elements.push(...line(0, 2, 8), coil(0, end, type));
  return network(title, comment, elements, { rows: branches.length, vlinks });
};
/** Calls N in three rows: one rung per floor. */
const perFloor = (
  title: string,
  comment: string,
  contacts: (n: number, r: number) => LdElement[],
  end: (n: number) => LdElement,
): Network =>
  network(
    title,
    comment,
    [0, 1, 2].flatMap((r) => row(r, contacts(r + 1, r), end(r))),
    { rows: 3 },
  );
/** A TON fed by the contacts on row 0; its Q is read elsewhere as `<instance>.Q`. */
const timer = (
  title: string,
  comment: string,
  contacts: LdElement[],
  instance: string,
  pt: string,
): Network =>
  network(title, comment, [
    ...contacts,
    box(0, contacts.length, 'TON', instance, { PT: pt }),
    ...line(0, contacts.length + 2, 9),
  ]);

function networks(waitForClosedDoor: boolean): Network[] {
  const start = (dir: 'MotorUp' | 'MotorDown', calls: string, other: string): LdElement[] => {
    const cs = [
      contact(0, 0, calls),
      contact(0, 1, 'Here', 'NC'),
      ...(waitForClosedDoor ? [contact(0, 2, 'DoorClosed')] : []),
    ];
    cs.push(contact(0, cs.length, 'DoorOpen', 'NC'), contact(0, cs.length + 1, other, 'NC'));
    return row(0, cs, coil(0, dir, 'SET'));
  };
  return [
    perFloor(
      'Register the calls',
      'A call button press registers a call at its floor until it is answered.',
      (n, r) => [contact(r, 0, `Call${n}`)],
      (r) => coil(r, `Req${r + 1}`, 'SET'),
    ),
    perFloor(
      'Answer the calls',
      'The door fully open at a floor answers its call.',
      (n, r) => [contact(r, 0, `AtFloor${n}`), contact(r, 1, 'DoorOpened')],
      (r) => coil(r, `Req${r + 1}`, 'RESET'),
    ),
    perFloor(
      'Call lamps',
      'Each landing lamp shows its call is registered.',
      (n, r) => [contact(r, 0, `Req${n}`)],
      (r) => coil(r, `CallLamp${r + 1}`),
    ),
    pairs(
      'Call here',
      'The car is at a floor with a registered call.',
      [
        ['AtFloor1', 'Req1'],
        ['AtFloor2', 'Req2'],
        ['AtFloor3', 'Req3'],
      ],
      'Here',
    ),
    pairs(
      'Calls above',
      'A call waits above the floor the car is at.',
      [
        ['AtFloor1', 'Req2'],
        ['AtFloor1', 'Req3'],
        ['AtFloor2', 'Req3'],
      ],
      'Above',
    ),
    pairs(
      'Calls below',
      'A call waits below the floor the car is at.',
      [
        ['AtFloor3', 'Req2'],
        ['AtFloor3', 'Req1'],
        ['AtFloor2', 'Req1'],
      ],
      'Below',
    ),
    timer(
      'Car at rest',
      'Both contactors off for 0.3 s: the brake has stopped the car (it needs 0.1 s).',
      [contact(0, 0, 'MotorUp', 'NC'), contact(0, 1, 'MotorDown', 'NC')],
      'Standstill',
      'T#300ms',
    ),
    network(
      'Open the door',
      'At rest at a floor with a call: open the door.',
      row(0, [contact(0, 0, 'Here'), contact(0, 1, 'Standstill.Q')], coil(0, 'DoorOpen', 'SET')),
      { rows: 1 },
    ),
    timer(
      'Door dwell',
      'The door stays fully open for 2 s.',
      [contact(0, 0, 'DoorOpen'), contact(0, 1, 'DoorOpened')],
      'Dwell',
      'T#2s',
    ),
    network(
      'Close the door',
      'After the dwell the door closes (a new call here opens it again).',
      row(0, [contact(0, 0, 'Dwell.Q')], coil(0, 'DoorOpen', 'RESET')),
      { rows: 1 },
    ),
    network(
      'Go up',
      waitForClosedDoor
        ? 'A call above, none here, the door closed and not opening, not going down: go up.'
        : 'A call above, none here, the door not opening, not going down: go up.',
      start('MotorUp', 'Above', 'MotorDown'),
      { rows: 1 },
    ),
    network(
      'Go down',
      waitForClosedDoor
        ? 'A call below, none here, the door closed and not opening, not going up: go down.'
        : 'A call below, none here, the door not opening, not going up: go down.',
      start('MotorDown', 'Below', 'MotorUp'),
      { rows: 1 },
    ),
    network(
      'Stop going up',
      'At floor 2 with a call there, or at the top floor: stop.',
      [
        contact(0, 0, 'AtFloor2'),
        contact(0, 1, 'Req2'),
        ...line(0, 2, 8),
        coil(0, 'MotorUp', 'RESET'),
        contact(1, 0, 'AtFloor3'),
        ...line(1, 1, 1),
      ],
      { vlinks: [{ row: 0, boundary: 2 }] },
    ),
    network(
      'Stop going down',
      'At floor 2 with a call there, or at the bottom floor: stop.',
      [
        contact(0, 0, 'AtFloor2'),
        contact(0, 1, 'Req2'),
        ...line(0, 2, 8),
        coil(0, 'MotorDown', 'RESET'),
        contact(1, 0, 'AtFloor1'),
        ...line(1, 1, 1),
      ],
      { vlinks: [{ row: 0, boundary: 2 }] },
    ),
  ];
}

function liftProject(name: string, waitForClosedDoor: boolean): Project {
  const description = taskText(lift);
  const main = newPou('Main', {
    variables: [
      ...plantVariables(lift),
      variable('Req1', 'BOOL', { comment: 'Call registered at floor 1' }),
      variable('Req2', 'BOOL', { comment: 'Call registered at floor 2' }),
      variable('Req3', 'BOOL', { comment: 'Call registered at floor 3' }),
      variable('Here', 'BOOL', { comment: 'A call at the floor the car is at' }),
      variable('Above', 'BOOL', { comment: 'A call above the floor the car is at' }),
      variable('Below', 'BOOL', { comment: 'A call below the floor the car is at' }),
      variable('Standstill', 'TON', { comment: 'The car at rest: both contactors off for 0.3 s' }),
      variable('Dwell', 'TON', { comment: 'Times the door held fully open (2 s)' }),
    ],
    networks: networks(waitForClosedDoor),
    comment: description,
  });
  return newProject(name, {
    description,
    scenarios: [LIFT_SCENARIO],
    plant: { id: lift.id },
    pous: [main],
    tasks: [
      {
        name: 'MainTask',
        cycleMs: 20,
        priority: 1,
        programs: [{ instance: 'MainInstance', pou: main.name }],
      },
    ],
  });
}

/** The reference solution: answers the calls, stops level, moves only with the door closed. */
export function liftReference(): Project {
  return liftProject('Three-floor lift', true);
}

/** A classic mistake: the car leaves as soon as the door is told to close, not once it is closed. */
export function liftWrong(): Project {
  return liftProject('Three-floor lift (wrong: leaves before the door is closed)', false);
}

export const LIFT_EXAMPLE: Example = {
  id: 'lift',
  title: 'Three-floor lift (machine: lift)',
  description:
    'Exercise: answer the calls of a three-floor lift; the reference solution, with the lift in the Plant panel.',
  build: liftReference,
};
