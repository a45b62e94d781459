// The tank's exercise (issue 26): hold the tank between its level switches for 5 minutes; the
// reference solution in ladder, a classic wrong one, and the scenario run in CI.
import { coil, contact, line, network, rung } from '../model/examples';
import type { Example } from '../model/examples';
import { newPou, newProject, variable } from '../model/factory';
import type { Network, Project, Scenario } from '../model/project';
import { plantVariables, taskText } from './exerciseKit';
import { tank } from './tank';

/**
 * Holding the tank between the switches for 5 minutes of PLC time, with no overflow, no dry run:
 * filling from the low switch up to the high switch while the process draws, the drain shut below
 * the low switch, the inlet open whenever the pump runs, everything off on Stop and on again on Start.
 */
export const TANK_SCENARIO: Scenario = {
  name: 'Tank held between the switches for 5 minutes',
  csv: `# plant: tank
# cycle: 100ms
# Start is pressed for 0.2 s. The tank fills from the low switch (200 L) to the high switch (800 L)
# in about 45 s while the process draws, then the process draws it down in about 60 s: the level
# is checked against that cycle (within 50 L) every minute.
# At 2 s the water is below the low switch: the pump fills through the open inlet, the drain is shut.
# Stop is pressed at 230 s while the tank fills: everything goes off and the level stays; Start at 240 s.
# An overflow or a dry run fails the scenario at the scan it happens.
scan,tank.Start,tank.Stop,expect RunLamp,expect Pump,expect InletValve,expect DrainValve,expect tank.level ~ 50,expect tank.deadheads
1,1,0,,,,,,
3,0,,1,*,*,*,*,0
20,,,1,1,1,0,138,0
600,,,1,0,0,1,646,0
1200,,,1,1,1,1,421,0
1800,,,1,0,0,1,458,0
2300,,1,,,,,,
2302,,0,,,,,,
2310,,,0,0,0,0,552,0
2399,,,0,0,0,0,552,0
2400,1,,,,,,,
2402,0,,1,*,*,*,*,0
2700,,,1,0,0,1,256,0
3000,,,1,1,1,1,557,0
`,
};

const fillAndDrain = (stopFilling: Network): Network[] => [
  network(
    'System running',
    'Start OR Running (seal-in), AND NOT Stop: the system runs until Stop is pressed.',
    [
      ...rung([contact(0, 0, 'Start'), contact(0, 1, 'Stop', 'NC')], coil(0, 'Running')),
      contact(1, 0, 'Running'),
    ],
    { vlinks: [{ row: 0, boundary: 1 }] },
  ),
  network(
    'Run lamp',
    'The pilot lamp shows the system is running.',
    rung([contact(0, 0, 'Running')], coil(0, 'RunLamp')),
    { rows: 1 },
  ),
  network(
    'Start filling',
    'Running with the water below the low switch: fill.',
    rung([contact(0, 0, 'Running'), contact(0, 1, 'LowLevel', 'NC')], coil(0, 'Filling', 'SET')),
    { rows: 1 },
  ),
  stopFilling,
  network(
    'Pump',
    'The pump runs while filling (the inlet valve opens with it).',
    rung([contact(0, 0, 'Filling')], coil(0, 'Pump')),
    { rows: 1 },
  ),
  network(
    'Inlet valve',
    'The inlet valve is open while filling.',
    rung([contact(0, 0, 'Filling')], coil(0, 'InletValve')),
    { rows: 1 },
  ),
  network(
    'Drain to the process',
    'The process draws water while running, only from a tank at or above the low switch.',
    rung([contact(0, 0, 'Running'), contact(0, 1, 'LowLevel')], coil(0, 'DrainValve')),
    { rows: 1 },
  ),
];

function tankProject(name: string, description: string, networks: Network[]): Project {
  const main = newPou('Main', {
    variables: [
      ...plantVariables(tank),
      variable('Running', 'BOOL', { comment: 'The system runs (Start pressed, Stop not since)' }),
      variable('Filling', 'BOOL', { comment: 'Filling from the low switch up to the high switch' }),
    ],
    networks,
    comment: description,
  });
  return newProject(name, {
    description,
    scenarios: [TANK_SCENARIO],
    plant: { id: tank.id },
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

/** The reference solution: fills from the low switch to the high switch, stops filling when stopped. */
export function tankReference(): Project {
  return tankProject(
    'Tank level control',
    taskText(tank),
    fillAndDrain(
      network(
        'Stop filling',
        'The high switch, or the system stopped, ends filling.',
        [...rung([contact(0, 0, 'HighLevel')], coil(0, 'Filling', 'RESET')), contact(1, 0, 'Running', 'NC')],
        { vlinks: [{ row: 0, boundary: 1 }] },
      ),
    ),
  );
}

/** A classic mistake for the exercise: the high switch never ends filling, so the tank overflows. */
export function tankWrong(): Project {
  return tankProject(
    'Tank level control (wrong: ignores the high switch)',
    taskText(tank),
    fillAndDrain(
      network(
        'Stop filling',
        'Only stopping the system ends filling (the high switch is forgotten).',
        [contact(0, 0, 'Running', 'NC'), ...line(0, 1, 8), coil(0, 'Filling', 'RESET')],
        { rows: 1 },
      ),
    ),
  );
}

export const TANK_EXAMPLE: Example = {
  id: 'tank-level',
  title: 'Tank level control (machine: tank)',
  description:
    'Exercise: hold the tank between its level switches; the reference solution, with the tank in the Plant panel.',
  build: tankReference,
};
