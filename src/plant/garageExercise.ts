// The garage door's exercise (issue 26): open and close the door on the key switch three times,
// reversing when a car drives into the doorway while it closes; the reference solution in ladder,
// a classic wrong one (it ignores the photo-eye), and the scenario run in CI.
import { box, coil, contact, line, network, rung } from '../model/examples';
import type { Example } from '../model/examples';
import { newPou, newProject, variable } from '../model/factory';
import type { Network, Project, Scenario } from '../model/project';
import { plantVariables, taskText } from './exerciseKit';
import { garage } from './garage';

/**
 * Three full cycles on the key switch, 100 ms scans. The second close is interrupted: a car drives
 * into the doorway with the door still high (about 80 % open); the door must reverse and open
 * fully; the car leaves and the door closes. KeyClose turned while the door opens is ignored; Stop
 * stops the door where it is. A door coming down on the car, a short circuit or an overrun fails
 * the scenario at the scan it happens.
 */
export const GARAGE_SCENARIO: Scenario = {
  name: 'Garage door: three cycles on the key, reversing for a car',
  csv: `# plant: garage
# cycle: 100ms
# KeyOpen / KeyClose are turned for 0.2 s; the door takes 12 s (120 scans) from end to end.
# Scan 470: a car drives into the doorway while the door closes (about 80 % open).
# The door coming down on it fails the scenario where it happens ("the door came down on the car…").
# Scan 760: KeyClose while the door opens: it opens on (MotorUp, never MotorDown with it).
# Scan 1070: Stop while the door opens (about 41 %): it stays there, between its limits, the motor off;
# KeyClose closes it.
scan,garage.KeyOpen,garage.KeyClose,garage.Doorway,garage.Stop,expect MotorUp,expect MotorDown,expect Obstacle,expect OpenLimit,expect ClosedLimit,expect garage.position ~ 1,expect garage.cycles,expect garage.unwarned,expect garage.moving
1,1,0,0,0,,,0,0,1,0,0,0,
3,0,,,,,,,,,,,,
150,,1,,,,,0,1,0,99.5,0,0,
152,,0,,,,,,,,,,,
290,,,,,,,0,0,1,0.5,1,0,
300,1,,,,,,,,,,,,
302,0,,,,,,,,,,,,
440,,1,,,,,,1,,99.5,1,,
442,,0,,,,,,,,,,,
470,,,1,,,,,,,,,,
472,,,,,,,1,0,0,*,1,0,
540,,,,,,,1,1,0,99.5,1,0,
560,,,0,,,,,,,,,,
570,,1,,,,,0,1,,,,,
572,,0,,,,,,,,,,,
710,,,,,,,0,0,1,0.5,2,0,
720,1,,,,,,,,,,,,
722,0,,,,,,,,,,,,
760,,1,,,,,,,,,,,
762,,0,,,,,,,,,,,
770,,,,,1,0,0,0,0,*,2,0,
860,,1,,,,,,1,,,,,
862,,0,,,,,,,,,,,
1000,,,,,,,0,0,1,0.5,3,0,
1010,1,,,,,,,,,,,,
1012,0,,,,,,,,,,,,
1070,,,,1,,,,,,,,,
1072,,,,0,,,,,,,,,
1080,,,,,0,0,0,0,0,*,3,0,0
1100,,,,,0,0,0,0,0,*,3,0,0
1110,,1,,,,,,,,,,,
1112,,0,,,,,,,,,,,
1200,,,,,0,0,0,0,1,0.5,3,0,
`,
};

const GARAGE_VARIABLES = [
  variable('Opening', 'BOOL', { comment: 'The door is to open (KeyOpen, or reversing for an obstacle)' }),
  variable('Closing', 'BOOL', { comment: 'The door is to close (KeyClose)' }),
  variable('PreWarn', 'TON', { comment: 'The warning lamp lit 1 s before the motor starts' }),
];

/** Opening and Closing: the two networks the wrong solution gets wrong. */
type Direction = readonly [open: Network, close: Network];

const doorNetworks = ([open, close]: Direction): Network[] => [
  open,
  close,
  network(
    'Warning lamp',
    'The lamp is lit while the door is to move, opening or closing.',
    [...rung([contact(0, 0, 'Opening')], coil(0, 'WarningLamp')), contact(1, 0, 'Closing')],
    { vlinks: [{ row: 0, boundary: 1 }] },
  ),
  network('Pre-warning', 'The motor starts only once the lamp has been lit for 1 s.', [
    contact(0, 0, 'WarningLamp'),
    ...line(0, 1, 1),
    box(0, 2, 'TON', 'PreWarn', { PT: 'T#1s' }),
    ...line(0, 4, 9),
  ]),
  network(
    'Motor up',
    'Opening, warned: the up contactor, interlocked with the down one (never both on).',
    rung(
      [contact(0, 0, 'Opening'), contact(0, 1, 'PreWarn.Q'), contact(0, 2, 'MotorDown', 'NC')],
      coil(0, 'MotorUp'),
    ),
    { rows: 1 },
  ),
  network(
    'Motor down',
    'Closing, warned: the down contactor, interlocked with the up one.',
    rung(
      [contact(0, 0, 'Closing'), contact(0, 1, 'PreWarn.Q'), contact(0, 2, 'MotorUp', 'NC')],
      coil(0, 'MotorDown'),
    ),
    { rows: 1 },
  ),
];

function garageProject(name: string, networks: Network[]): Project {
  const description = taskText(garage);
  const main = newPou('Main', {
    variables: [...plantVariables(garage), ...GARAGE_VARIABLES],
    networks,
    comment: description,
  });
  return newProject(name, {
    description,
    scenarios: [GARAGE_SCENARIO],
    plant: { id: garage.id },
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

/** The reference solution: seal-in to the limits, Stop, the photo-eye blocks closing and reverses it. */
export function garageReference(): Project {
  return garageProject(
    'Garage door',
    doorNetworks([
      network(
        'Opening',
        'KeyOpen, or the photo-eye broken while closing (reverse), opens the door; sealed in until the open limit or Stop.',
        [
          contact(0, 0, 'KeyOpen'),
          ...line(0, 1, 1),
          contact(0, 2, 'OpenLimit', 'NC'),
          contact(0, 3, 'Stop', 'NC'),
          ...line(0, 4, 8),
          coil(0, 'Opening'),
          contact(1, 0, 'Opening'),
          ...line(1, 1, 1),
          contact(2, 0, 'Closing'),
          contact(2, 1, 'Obstacle'),
        ],
        {
          rows: 3,
          vlinks: [
            { row: 0, boundary: 2 },
            { row: 1, boundary: 2 },
          ],
        },
      ),
      network(
        'Closing',
        'KeyClose closes the door, sealed in until the closed limit or Stop; never while the photo-eye is broken or the door opens.',
        [
          ...rung(
            [
              contact(0, 0, 'KeyClose'),
              contact(0, 1, 'ClosedLimit', 'NC'),
              contact(0, 2, 'Stop', 'NC'),
              contact(0, 3, 'Obstacle', 'NC'),
              contact(0, 4, 'Opening', 'NC'),
            ],
            coil(0, 'Closing'),
          ),
          contact(1, 0, 'Closing'),
        ],
        { vlinks: [{ row: 0, boundary: 1 }] },
      ),
    ]),
  );
}

/** A classic mistake: the photo-eye is forgotten, so the door comes down on a car in the doorway. */
export function garageWrong(): Project {
  return garageProject(
    'Garage door (wrong: ignores the photo-eye)',
    doorNetworks([
      network(
        'Opening',
        'KeyOpen opens the door, sealed in until the open limit or Stop.',
        [
          ...rung(
            [contact(0, 0, 'KeyOpen'), contact(0, 1, 'OpenLimit', 'NC'), contact(0, 2, 'Stop', 'NC')],
            coil(0, 'Opening'),
          ),
          contact(1, 0, 'Opening'),
        ],
        { vlinks: [{ row: 0, boundary: 1 }] },
      ),
      network(
        'Closing',
        'KeyClose closes the door, sealed in until the closed limit or Stop (the photo-eye is forgotten).',
        [
          ...rung(
            [
              contact(0, 0, 'KeyClose'),
              contact(0, 1, 'ClosedLimit', 'NC'),
              contact(0, 2, 'Stop', 'NC'),
              contact(0, 3, 'Opening', 'NC'),
            ],
            coil(0, 'Closing'),
          ),
          contact(1, 0, 'Closing'),
        ],
        { vlinks: [{ row: 0, boundary: 1 }] },
      ),
    ]),
  );
}

export const GARAGE_EXAMPLE: Example = {
  id: 'garage-door',
  title: 'Garage door (machine: garage)',
  description:
    'Exercise: open and close a garage door on a key switch, reversing for a car in the doorway; the reference solution, with the door in the Plant panel.',
  build: garageReference,
};
