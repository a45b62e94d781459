// The intersection's exercise (issue 26): rest on main road green, serve the side road and the
// pedestrians on demand through yellow and all-red, for 5 minutes of PLC time with no conflict;
// the reference solution in ladder, a classic wrong one, and the scenario run in CI.
import { box, coil, contact, line, network, rung } from '../model/examples';
import type { Example } from '../model/examples';
import type { LdElement } from '../model/elements';
import { newPou, newProject, variable } from '../model/factory';
import type { Network, Project, Scenario } from '../model/project';
import { plantVariables, taskText } from './exerciseKit';
import { intersection } from './intersection';

/**
 * Five minutes of PLC time: side road traffic comes on its schedule, pedestrians press the buttons
 * now and then. A conflict, a dark signal, a green over pedestrians or a car still crossing, or a
 * wait too long fails the scenario at the scan it happens; the traffic served is checked every minute.
 */
export const INTERSECTION_SCENARIO: Scenario = {
  name: 'Side road and pedestrians served for 5 minutes, no conflict',
  csv: `# plant: intersection
# cycle: 100ms
# Pedestrians press CrossMain at 5 s, 95 s and 200 s, CrossSide at 70 s and 250 s (each for 0.2 s).
# Two come late: CrossMain at 153.3 s, 8 s into the side road green (after its WALK: crossing takes
# 8 s, the main road gets green 7 s later), and CrossSide at 179.8 s, just before the main road
# yellow (crossing takes 6 s, the side road gets green 5.6 s later): both must wait for the next WALK.
# Checked every minute: vehicles served (all, side road), pedestrians served, the longest wait of a
# vehicle (under 45 s: the side road served on demand); a longer minimum green or clearance is fine.
scan,intersection.CrossMain,intersection.CrossSide,expect intersection.served ~ 6,expect intersection.served_side ~ 4,expect intersection.ped_served ~ 1,expect intersection.max_wait ~ 20
50,1,,,,,
52,0,,,,,
600,,,17,5,1,25
700,,1,,,,
702,,0,,,,
950,1,,,,,
952,0,,,,,
1200,,,32,12,3,25
1534,1,,,,,
1536,0,,,,,
1798,,,53,17,3,25
1799,,1,,,,
1801,,0,,,,
2000,1,,,,,
2002,0,,,,,
2400,,,69,24,6,25
2500,,1,,,,
2502,,0,,,,
3000,,,89,29,7,25
`,
};

const COLS = 10;

/** A TON box timing while `condition` holds (an NC contact when `nc`), its Q read by other networks. */
const timerNet = (title: string, comment: string, condition: LdElement, timer: string, pt: string): Network =>
  network(title, comment, [
    condition,
    ...line(0, 1, 1),
    box(0, 2, 'TON', timer, { PT: pt }),
    ...line(0, 4, COLS - 1),
  ]);

const lampNet = (title: string, comment: string, lamp: string, contacts: LdElement[]): Network =>
  network(title, comment, rung(contacts, coil(0, lamp)), { rows: 1 });

/** The networks up to the side road's lamps, which the wrong solution gets wrong. */
function sequence(): Network[] {
  return [
    network(
      'Pedestrian asks to cross the main road',
      'A press of CrossMain is remembered until WALK over the main road lights.',
      rung([contact(0, 0, 'CrossMain')], coil(0, 'AskMain', 'SET')),
      { rows: 1 },
    ),
    network(
      'Pedestrian crossing the main road served',
      'WALK over the main road clears the request.',
      rung([contact(0, 0, 'WalkMain')], coil(0, 'AskMain', 'RESET')),
      { rows: 1 },
    ),
    network(
      'Pedestrian asks to cross the side road',
      'A press of CrossSide is remembered until WALK over the side road lights.',
      rung([contact(0, 0, 'CrossSide')], coil(0, 'AskSide', 'SET')),
      { rows: 1 },
    ),
    network(
      'Pedestrian crossing the side road served',
      'WALK over the side road clears the request.',
      rung([contact(0, 0, 'WalkSide')], coil(0, 'AskSide', 'RESET')),
      { rows: 1 },
    ),
    network(
      'Demand for the side phase',
      'A vehicle on the side road loop, or a pedestrian waiting at either crossing.',
      [
        ...rung([contact(0, 0, 'LoopSide')], coil(0, 'Demand')),
        contact(1, 0, 'AskMain'),
        contact(2, 0, 'AskSide'),
      ],
      {
        rows: 3,
        vlinks: [
          { row: 0, boundary: 1 },
          { row: 1, boundary: 1 },
        ],
      },
    ),
    timerNet(
      'Main road green time',
      'Times the main road green (the cycle is not running): at least 20 s before the side road.',
      contact(0, 0, 'Cycle', 'NC'),
      'MainGreenTime',
      'T#20s',
    ),
    network(
      'Start the side phase',
      'After the main road minimum green, a demand starts the cycle to the side road and back.',
      rung([contact(0, 0, 'MainGreenTime.Q'), contact(0, 1, 'Demand')], coil(0, 'Cycle', 'SET')),
      { rows: 1 },
    ),
    timerNet(
      'Main road yellow',
      'Main road yellow for 3 s.',
      contact(0, 0, 'Cycle'),
      'MainYellowTime',
      'T#3s',
    ),
    timerNet(
      'All red before the side road',
      'Both roads red for 2 s: the last car clears the intersection.',
      contact(0, 0, 'MainYellowTime.Q'),
      'AllRedTime1',
      'T#2s',
    ),
    timerNet(
      'Side road green',
      'Side road green for 10 s.',
      contact(0, 0, 'AllRedTime1.Q'),
      'SideGreenTime',
      'T#10s',
    ),
    timerNet(
      'Side road yellow',
      'Side road yellow for 3 s.',
      contact(0, 0, 'SideGreenTime.Q'),
      'SideYellowTime',
      'T#3s',
    ),
    timerNet(
      'All red before the main road',
      'Both roads red for 2 s.',
      contact(0, 0, 'SideYellowTime.Q'),
      'AllRedTime2',
      'T#2s',
    ),
    network(
      'End of the side phase',
      'Back to main road green (every timer of the cycle resets in this scan).',
      rung([contact(0, 0, 'AllRedTime2.Q')], coil(0, 'Cycle', 'RESET')),
      { rows: 1 },
    ),
    timerNet(
      'WALK over the side road',
      'The first 5 s of main road green: the last pedestrian is across (6 s) long before the side road gets green.',
      contact(0, 0, 'Cycle', 'NC'),
      'WalkSideTime',
      'T#5s',
    ),
    timerNet(
      'WALK over the main road',
      'The first 4 s of side road green: the last pedestrian is across (8 s) before the main road gets green (15 s).',
      contact(0, 0, 'AllRedTime1.Q'),
      'WalkMainTime',
      'T#4s',
    ),
    lampNet('Main road green', 'Green while the cycle is not running.', 'MainGreen', [
      contact(0, 0, 'Cycle', 'NC'),
    ]),
    lampNet('Main road yellow', 'Yellow at the start of the cycle.', 'MainYellow', [
      contact(0, 0, 'Cycle'),
      contact(0, 1, 'MainYellowTime.Q', 'NC'),
    ]),
    lampNet('Main road red', 'Red for the rest of the cycle.', 'MainRed', [
      contact(0, 0, 'Cycle'),
      contact(0, 1, 'MainYellowTime.Q'),
    ]),
  ];
}

/** The side road's green and yellow, and the lamps that follow from them. */
function sideLamps(green: Network): Network[] {
  return [
    green,
    lampNet('Side road yellow', 'Yellow after the side road green.', 'SideYellow', [
      contact(0, 0, 'Cycle'),
      contact(0, 1, 'SideGreenTime.Q'),
      contact(0, 2, 'SideYellowTime.Q', 'NC'),
    ]),
    lampNet('Side road red', 'Red whenever the side road is neither green nor yellow.', 'SideRed', [
      contact(0, 0, 'SideGreen', 'NC'),
      contact(0, 1, 'SideYellow', 'NC'),
    ]),
    lampNet('WALK over the main road', 'With the side road traffic, its first 4 s.', 'WalkMain', [
      contact(0, 0, 'Cycle'),
      contact(0, 1, 'AllRedTime1.Q'),
      contact(0, 2, 'WalkMainTime.Q', 'NC'),
    ]),
    lampNet("DON'T WALK over the main road", "DON'T WALK whenever not WALK.", 'DontWalkMain', [
      contact(0, 0, 'WalkMain', 'NC'),
    ]),
    lampNet('WALK over the side road', 'With the main road traffic, its first 5 s.', 'WalkSide', [
      contact(0, 0, 'Cycle', 'NC'),
      contact(0, 1, 'WalkSideTime.Q', 'NC'),
    ]),
    lampNet("DON'T WALK over the side road", "DON'T WALK whenever not WALK.", 'DontWalkSide', [
      contact(0, 0, 'WalkSide', 'NC'),
    ]),
  ];
}

function intersectionProject(name: string, description: string, networks: Network[]): Project {
  const timer = (n: string, comment: string) => variable(n, 'TON', { comment });
  const main = newPou('Main', {
    variables: [
      ...plantVariables(intersection),
      variable('AskMain', 'BOOL', { comment: 'A pedestrian waits to cross the main road' }),
      variable('AskSide', 'BOOL', { comment: 'A pedestrian waits to cross the side road' }),
      variable('Demand', 'BOOL', { comment: 'The side phase is wanted (vehicle or pedestrian)' }),
      variable('Cycle', 'BOOL', {
        comment: 'The side phase runs: main yellow, all red, side green, side yellow, all red',
      }),
      timer('MainGreenTime', 'Main road minimum green (20 s)'),
      timer('MainYellowTime', 'Main road yellow (3 s)'),
      timer('AllRedTime1', 'All red before the side road (2 s)'),
      timer('SideGreenTime', 'Side road green (10 s)'),
      timer('SideYellowTime', 'Side road yellow (3 s)'),
      timer('AllRedTime2', 'All red before the main road (2 s)'),
      timer('WalkSideTime', 'WALK over the side road (5 s)'),
      timer('WalkMainTime', 'WALK over the main road (4 s)'),
    ],
    networks,
    comment: description,
  });
  return newProject(name, {
    description,
    scenarios: [INTERSECTION_SCENARIO],
    plant: { id: intersection.id },
    pous: [main],
    tasks: [
      {
        name: 'MainTask',
        cycleMs: 100,
        priority: 1,
        programs: [{ instance: 'MainInstance', pou: main.name }],
      },
    ],
  });
}

/** The reference solution: rests on main road green, serves the side road and pedestrians on demand. */
export function intersectionReference(): Project {
  return intersectionProject('Road intersection', taskText(intersection), [
    ...sequence(),
    ...sideLamps(
      lampNet('Side road green', 'Green after the all-red, for the side green time.', 'SideGreen', [
        contact(0, 0, 'Cycle'),
        contact(0, 1, 'AllRedTime1.Q'),
        contact(0, 2, 'SideGreenTime.Q', 'NC'),
      ]),
    ),
  ]);
}

/**
 * A classic mistake: the side road's green follows the cycle flag alone, so it lights as the main
 * road turns yellow (the yellow and all-red timers are only used for the main road).
 */
export function intersectionWrong(): Project {
  return intersectionProject(
    'Road intersection (wrong: side green with main yellow)',
    taskText(intersection),
    [
      ...sequence(),
      ...sideLamps(
        lampNet(
          'Side road green',
          'Green as soon as the cycle starts (forgets the main road yellow).',
          'SideGreen',
          [contact(0, 0, 'Cycle'), contact(0, 1, 'SideGreenTime.Q', 'NC')],
        ),
      ),
    ],
  );
}

export const INTERSECTION_EXAMPLE: Example = {
  id: 'road-intersection',
  title: 'Road intersection (machine: intersection)',
  description:
    'Exercise: serve a side road and pedestrians from a busy main road with no conflict; the reference solution, with the intersection in the Plant panel.',
  build: intersectionReference,
};
