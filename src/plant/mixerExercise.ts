// The batch mixer's exercise (issue 26): three good batches, each dosed (A to the mid switch, B to
// the high switch), stirred and heated to 60 °C, held 30 s, discharged; the reference solution in
// ladder (a step sequence of SET/RESET flags, a comparison box and two on-delay timers), a classic
// wrong one, and the scenario run in CI.
import { box, coil, contact, line, network, rung } from '../model/examples';
import type { Example } from '../model/examples';
import type { LdElement } from '../model/elements';
import { newPou, newProject, variable } from '../model/factory';
import type { Network, Project, Scenario } from '../model/project';
import { plantVariables, taskText } from './exerciseKit';
import { mixer } from './mixer';

/**
 * Three good batches in 6 minutes of PLC time: no overflow, no scorch, no spoiled batch; the
 * steps in order (A alone, then B alone, then stirred and heated, then discharged with the lamp),
 * and Stop pausing the third batch while it heats (everything off), Start going on with it.
 */
export const MIXER_SCENARIO: Scenario = {
  name: 'Three good batches',
  csv: `# plant: mixer
# cycle: 100ms
# Start is pressed for 0.2 s. A batch takes under 2 minutes: dosing A (10 s), B (10 s), heating to
# 60 °C (some 40 s), the 30 s hold, discharge. At 5 s only valve A is open, at 15 s only valve B;
# at 40 s the batch is stirred; at 100 s it is discharged with DoneLamp lit, heater and agitator off.
# Counted every batch a few seconds after its discharge; a longer hold or emptying time is fine.
# Stop is pressed at 260 s while the third batch heats (everything goes off), Start at 270 s.
# An overflow, a scorch, a heater run dry or a spoiled batch fails the scenario at the scan it happens.
scan,mixer.Start,mixer.Stop,expect ValveA,expect ValveB,expect Agitator,expect Heater,expect OutletValve,expect DoneLamp,expect mixer.batches,expect mixer.ratio ~ 10
1,1,0,,,,,,,0,
3,0,,,,,,,,0,
50,,,1,0,0,0,0,0,0,
150,,,0,1,0,0,0,0,0,
400,,,0,0,1,*,0,0,0,
1000,,,0,0,0,0,1,1,0,50
1200,,,,,,,,,1,
2300,,,,,,,,,2,
2600,,1,,,,,,,,
2602,,0,,,,,,,,
2610,,,0,0,0,0,0,0,2,
2700,1,,,,,,,,,
2702,0,,,,,,,,,
3600,,,,,,,,,3,
`,
};

/** Contacts in series from the left rail, then coils in parallel (one a row) in the last column. */
const coils = (contacts: LdElement[], ends: LdElement[]): LdElement[] => [
  ...rung(contacts, ends[0]!),
  ...ends.slice(1).flatMap((end, i) => [...line(i + 1, contacts.length, 8), end]),
];
const parallel = (title: string, comment: string, contacts: LdElement[], ends: LdElement[]): Network =>
  network(title, comment, coils(contacts, ends), {
    rows: ends.length,
    vlinks: ends.slice(1).map((_, i) => ({ row: i, boundary: contacts.length })),
  });
const simple = (title: string, comment: string, contacts: LdElement[], end: LdElement): Network =>
  network(title, comment, rung(contacts, end), { rows: 1 });
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

function mixerNetworks(heater: Network): Network[] {
  return [
    network(
      'Production running',
      'Start OR Running (seal-in), AND NOT Stop: production runs until Stop is pressed. Stop pauses the batch where it is.',
      [
        ...rung([contact(0, 0, 'Start'), contact(0, 1, 'Stop', 'NC')], coil(0, 'Running')),
        contact(1, 0, 'Running'),
      ],
      { vlinks: [{ row: 0, boundary: 1 }] },
    ),
    simple(
      'Start a batch',
      'Running, the vessel empty (low switch OFF) and no step active: dose ingredient A.',
      [
        contact(0, 0, 'Running'),
        contact(0, 1, 'LowLevel', 'NC'),
        contact(0, 2, 'DoseA', 'NC'),
        contact(0, 3, 'DoseB', 'NC'),
        contact(0, 4, 'Mixing', 'NC'),
        contact(0, 5, 'Emptying', 'NC'),
      ],
      coil(0, 'DoseA', 'SET'),
    ),
    parallel(
      'Ingredient A dosed',
      'The mid level switch ends the dose of A: dose B.',
      [contact(0, 0, 'DoseA'), contact(0, 1, 'MidLevel')],
      [coil(0, 'DoseB', 'SET'), coil(1, 'DoseA', 'RESET')],
    ),
    parallel(
      'Ingredient B dosed',
      'The high level switch ends the dose of B: stir and heat.',
      [contact(0, 0, 'DoseB'), contact(0, 1, 'HighLevel')],
      [coil(0, 'Mixing', 'SET'), coil(1, 'DoseB', 'RESET')],
    ),
    network(
      'At temperature',
      'While mixing: AtTemp when the batch is at 60.0 °C or above (Temperature is in tenths of a degree).',
      [
        contact(0, 0, 'Mixing'),
        box(0, 1, 'GE', undefined, { IN1: 'Temperature', IN2: '600' }),
        ...line(1, 3, 8),
        coil(1, 'AtTemp'),
      ],
      { rows: 3 },
    ),
    simple(
      'Hold from the set point',
      'The hold starts the first time the batch reaches 60 °C (the heater then keeps it there).',
      [contact(0, 0, 'Mixing'), contact(0, 1, 'AtTemp')],
      coil(0, 'Holding', 'SET'),
    ),
    timer(
      'Hold 30 s',
      'The batch is held at 60 °C, stirred, for 30 s (the time restarts after a Stop).',
      [contact(0, 0, 'Holding'), contact(0, 1, 'Running')],
      'HoldTime',
      'T#30s',
    ),
    parallel(
      'Batch done',
      'Held long enough: stop mixing and discharge.',
      [contact(0, 0, 'HoldTime.Q')],
      [coil(0, 'Emptying', 'SET'), coil(1, 'Mixing', 'RESET'), coil(2, 'Holding', 'RESET')],
    ),
    timer(
      'Vessel empty',
      'The outlet stays open 4 s after the low switch goes OFF: the last litres run out.',
      [contact(0, 0, 'Emptying'), contact(0, 1, 'Running'), contact(0, 2, 'LowLevel', 'NC')],
      'EmptyTime',
      'T#4s',
    ),
    simple(
      'Discharged',
      'The vessel is empty: the batch is over (the next one starts).',
      [contact(0, 0, 'EmptyTime.Q')],
      coil(0, 'Emptying', 'RESET'),
    ),
    simple(
      'Valve A',
      'Ingredient A flows while its dose runs.',
      [contact(0, 0, 'DoseA'), contact(0, 1, 'Running')],
      coil(0, 'ValveA'),
    ),
    simple(
      'Valve B',
      'Ingredient B flows while its dose runs.',
      [contact(0, 0, 'DoseB'), contact(0, 1, 'Running')],
      coil(0, 'ValveB'),
    ),
    simple(
      'Agitator',
      'The agitator runs while the batch is mixed, heated and held.',
      [contact(0, 0, 'Mixing'), contact(0, 1, 'Running')],
      coil(0, 'Agitator'),
    ),
    heater,
    simple(
      'Outlet valve',
      'The outlet is open while the batch is discharged.',
      [contact(0, 0, 'Emptying'), contact(0, 1, 'Running')],
      coil(0, 'OutletValve'),
    ),
    simple(
      'Done lamp',
      'The lamp shows a finished batch being discharged.',
      [contact(0, 0, 'Emptying')],
      coil(0, 'DoneLamp'),
    ),
  ];
}

function mixerProject(name: string, networks: Network[]): Project {
  const description = taskText(mixer);
  const main = newPou('Main', {
    variables: [
      ...plantVariables(mixer),
      variable('Running', 'BOOL', { comment: 'Production runs (Start pressed, Stop not since)' }),
      variable('DoseA', 'BOOL', { comment: 'Step: dosing ingredient A up to the mid switch' }),
      variable('DoseB', 'BOOL', { comment: 'Step: dosing ingredient B up to the high switch' }),
      variable('Mixing', 'BOOL', { comment: 'Step: stirring, heating and holding the batch' }),
      variable('Emptying', 'BOOL', { comment: 'Step: discharging the finished batch' }),
      variable('AtTemp', 'BOOL', { comment: 'The batch is at 60.0 °C or above (while mixing)' }),
      variable('Holding', 'BOOL', { comment: 'The batch reached 60 °C: the hold runs' }),
      variable('HoldTime', 'TON', { comment: 'Times the 30 s hold' }),
      variable('EmptyTime', 'TON', { comment: 'Keeps the outlet open 4 s after the low switch goes OFF' }),
    ],
    networks,
    comment: description,
  });
  return newProject(name, {
    description,
    scenarios: [MIXER_SCENARIO],
    plant: { id: mixer.id },
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

/** The reference solution: a thermostat (heater off at 60 °C), only with the agitator running and the element covered. */
export function mixerReference(): Project {
  return mixerProject(
    'Batch mixer',
    mixerNetworks(
      simple(
        'Heater',
        'Heat while mixing, below 60 °C, with the agitator at speed and the element covered; not after the hold.',
        [
          contact(0, 0, 'Mixing'),
          contact(0, 1, 'Running'),
          contact(0, 2, 'AgitatorOn'),
          contact(0, 3, 'LowLevel'),
          contact(0, 4, 'AtTemp', 'NC'),
          contact(0, 5, 'HoldTime.Q', 'NC'),
        ],
        coil(0, 'Heater'),
      ),
    ),
  );
}

/** A classic mistake: the heater has no high limit (it heats through the hold), so the batch overheats. */
export function mixerWrong(): Project {
  return mixerProject(
    'Batch mixer (wrong: the heater has no high limit)',
    mixerNetworks(
      simple(
        'Heater',
        'Heat while mixing with the agitator at speed and the element covered, until the hold is over (no thermostat).',
        [
          contact(0, 0, 'Mixing'),
          contact(0, 1, 'Running'),
          contact(0, 2, 'AgitatorOn'),
          contact(0, 3, 'LowLevel'),
          contact(0, 4, 'HoldTime.Q', 'NC'),
        ],
        coil(0, 'Heater'),
      ),
    ),
  );
}

export const MIXER_EXAMPLE: Example = {
  id: 'batch-mixer',
  title: 'Batch mixer (machine: mixer)',
  description:
    'Exercise: dose, stir, heat, hold and discharge three good batches; the reference solution, with the mixer in the Plant panel.',
  build: mixerReference,
};
