// The bottle-filling station of issue 24 as a Rungsmith project, for bench:editor and the online
// change figures: a user FB `Conveyor` (LD body) called twice, 15 globals with addresses and
// comments, a CTU, a TON, a maintenance jump, two tasks, 13 networks in the main program.
// `bottleFillerProject(copies)` pastes the 13 networks `copies - 1` more times into Main the way
// the editor's paste does (preparePaste, mode `new`): every copy gets its own instances
// (`InfeedConv2`, `FillTimer2`, ...) and labels (`MAINT2`, `DONE2`); the globals are shared.
import type { BoxElement, LdElement, VLink } from '../src/model/elements';
import {
  box as exampleBox,
  coil,
  contact,
  jump,
  line,
  network as exampleNetwork,
  rung,
} from '../src/model/examples';
import { newPou, newProject, variable } from '../src/model/factory';
import type { Network, Pou, Project, Variable } from '../src/model/project';
import { copyNetworks, preparePaste } from '../src/store/networkUnits';

const COLS = 10;
/** A box on row 0 (the examples' box). */
const box = (
  col: number,
  blockType: string,
  instance: string,
  inputs: Record<string, string>,
  outputs: Record<string, string> = {},
): BoxElement => exampleBox(0, col, blockType, instance, inputs, outputs);

/** A network of the examples' shape, one row unless said otherwise. */
const network = (
  title: string,
  comment: string,
  elements: LdElement[],
  extra: { rows?: number; vlinks?: VLink[]; label?: string } = {},
): Network => exampleNetwork(title, comment, elements, { rows: 1, ...extra });

const g = (name: string, type: string, location: string, comment: string, initial?: string): Variable =>
  variable(name, type, { location, comment, ...(initial ? { initial } : {}) });

/** The 15 globals: 8 inputs, 5 outputs, a marker and the batch size. */
export function bottleFillerGlobals(): Variable[] {
  return [
    g('Start', 'BOOL', '%IX0.0', 'Start push button'),
    g('Stop', 'BOOL', '%IX0.1', 'Stop push button (TRUE while pressed)'),
    g('EStop', 'BOOL', '%IX0.2', 'Emergency stop chain open'),
    g('MaintKey', 'BOOL', '%IX0.3', 'Maintenance key switch'),
    g('BottleAtFill', 'BOOL', '%IX0.4', 'Photo eye: bottle under the fill nozzle'),
    g('BottleAtExit', 'BOOL', '%IX0.5', 'Photo eye: bottle at the outfeed'),
    g('LevelHigh', 'BOOL', '%IX0.6', 'Level probe: bottle full'),
    g('ConveyorJam', 'BOOL', '%IX0.7', 'Jam detector on the conveyors'),
    g('InfeedMotor', 'BOOL', '%QX0.0', 'Infeed conveyor motor contactor'),
    g('OutfeedMotor', 'BOOL', '%QX0.1', 'Outfeed conveyor motor contactor'),
    g('FillValve', 'BOOL', '%QX0.2', 'Fill valve solenoid'),
    g('RunLamp', 'BOOL', '%QX0.3', 'Line running lamp'),
    g('BatchLamp', 'BOOL', '%QX0.4', 'Batch complete lamp'),
    g('Running', 'BOOL', '%MX0.0', 'Line running (sealed in)'),
    g('BatchSize', 'INT', '%MW10', 'Bottles per batch', '24'),
  ];
}

/** FB Conveyor: Motor := Enable AND NOT Fault; Fault := Jam. */
export function conveyorFb(): Pou {
  const v = (name: string, varClass: Variable['varClass'], comment: string) =>
    variable(name, 'BOOL', { varClass, comment });
  return newPou('Conveyor', {
    kind: 'FUNCTION_BLOCK',
    comment: 'A conveyor motor that stops on a jam.',
    variables: [
      v('Enable', 'input', 'Run request'),
      v('Jam', 'input', 'Jam detected'),
      v('Motor', 'output', 'Motor contactor'),
      v('Fault', 'output', 'Stopped by a jam'),
    ],
    networks: [
      network('Fault', 'A jam faults the conveyor.', rung([contact(0, 0, 'Jam')], coil(0, 'Fault'))),
      network(
        'Motor',
        'The motor runs while enabled and not faulted.',
        rung([contact(0, 0, 'Enable'), contact(0, 1, 'Fault', 'NC')], coil(0, 'Motor')),
      ),
    ],
  });
}

/** Main's locals: the two conveyors, the fill timer, the bottle counter and the markers. */
function mainLocals(): Variable[] {
  return [
    variable('InfeedConv', 'Conveyor', { comment: 'Infeed conveyor' }),
    variable('OutfeedConv', 'Conveyor', { comment: 'Outfeed conveyor' }),
    variable('FillTimer', 'TON', { comment: 'Fill time' }),
    variable('BottleCounter', 'CTU', { comment: 'Bottles filled in this batch' }),
    variable('Filling', 'BOOL', { comment: 'A bottle is being filled' }),
    variable('FillDone', 'BOOL', { comment: 'Fill time elapsed' }),
    variable('Count', 'INT', { comment: 'Bottles filled' }),
    variable('MaintActive', 'BOOL', { comment: 'In maintenance' }),
    variable('JogRequest', 'BOOL', { comment: 'Maintenance jog requested' }),
    variable('ExitPulse', 'BOOL', { comment: 'A bottle left the station' }),
  ];
}

/** The 13 networks of the main program. */
export function bottleFillerNetworks(): Network[] {
  return [
    network(
      'Line running',
      'Start seals the line in; Stop or the emergency stop drops it.',
      [
        contact(0, 0, 'Start'),
        contact(1, 0, 'Running'),
        contact(0, 1, 'Stop', 'NC'),
        contact(0, 2, 'EStop', 'NC'),
        ...line(0, 3, COLS - 2),
        coil(0, 'Running'),
      ],
      { rows: 2, vlinks: [{ row: 0, boundary: 1 }] },
    ),
    network(
      'Maintenance',
      'The maintenance key skips production.',
      rung([contact(0, 0, 'MaintKey')], jump(0, 'MAINT')),
    ),
    network(
      'Infeed conveyor',
      'Brings bottles in until one is under the nozzle.',
      [
        contact(0, 0, 'Running'),
        contact(0, 1, 'BottleAtFill', 'NC'),
        box(2, 'Conveyor', 'InfeedConv', { Jam: 'ConveyorJam' }),
        ...line(0, 4, COLS - 2),
        coil(0, 'InfeedMotor'),
      ],
      { rows: 2 },
    ),
    network(
      'Filling',
      'A bottle under the nozzle is filled until the fill time is over.',
      rung(
        [contact(0, 0, 'Running'), contact(0, 1, 'BottleAtFill'), contact(0, 2, 'FillDone', 'NC')],
        coil(0, 'Filling'),
      ),
    ),
    network(
      'Fill time',
      'The fill time.',
      [
        contact(0, 0, 'Filling'),
        box(1, 'TON', 'FillTimer', { PT: 'T#2s' }),
        ...line(0, 3, COLS - 2),
        coil(0, 'FillDone'),
      ],
      { rows: 2 },
    ),
    network(
      'Fill valve',
      'The valve is open while filling and the bottle is not full.',
      rung([contact(0, 0, 'Filling'), contact(0, 1, 'LevelHigh', 'NC')], coil(0, 'FillValve')),
    ),
    network(
      'Bottle count',
      'Counts filled bottles; the batch lamp lights at the batch size.',
      [
        contact(0, 0, 'FillDone', 'P'),
        box(1, 'CTU', 'BottleCounter', { R: 'Stop', PV: 'BatchSize' }, { CV: 'Count' }),
        ...line(0, 3, COLS - 2),
        coil(0, 'BatchLamp'),
      ],
      { rows: 3 },
    ),
    network(
      'Outfeed conveyor',
      'Takes the filled bottle away.',
      [
        contact(0, 0, 'Running'),
        contact(0, 1, 'FillDone'),
        box(2, 'Conveyor', 'OutfeedConv', { Jam: 'ConveyorJam' }),
        ...line(0, 4, COLS - 2),
        coil(0, 'OutfeedMotor'),
      ],
      { rows: 2 },
    ),
    network('Run lamp', 'Lit while the line runs.', rung([contact(0, 0, 'Running')], coil(0, 'RunLamp'))),
    network(
      'Skip maintenance',
      'Without the maintenance key, the maintenance networks are skipped.',
      rung([contact(0, 0, 'MaintKey', 'NC')], jump(0, 'DONE')),
    ),
    network(
      'Maintenance mode',
      'The station is in maintenance.',
      rung([contact(0, 0, 'MaintKey')], coil(0, 'MaintActive')),
      { label: 'MAINT' },
    ),
    network(
      'Maintenance jog',
      'Start jogs the conveyors in maintenance.',
      rung([contact(0, 0, 'MaintActive'), contact(0, 1, 'Start')], coil(0, 'JogRequest')),
    ),
    network(
      'Bottle out',
      'A pulse per bottle leaving the station.',
      rung([contact(0, 0, 'BottleAtExit', 'P')], coil(0, 'ExitPulse')),
      { label: 'DONE' },
    ),
  ];
}

/** The second task's program: a 1 Hz blinker for the lamps. */
function signalsProgram(): Pou {
  return newPou('Signals', {
    comment: 'Slow signals.',
    variables: [
      variable('Blink', 'BOOL', { comment: 'One-scan pulse every 500 ms' }),
      variable('BlinkTimer', 'TON', { comment: 'Blink period' }),
    ],
    networks: [
      network(
        'Blinker',
        'A pulse every half second.',
        [
          contact(0, 0, 'Blink', 'NC'),
          box(1, 'TON', 'BlinkTimer', { PT: 'T#500ms' }),
          ...line(0, 3, COLS - 2),
          coil(0, 'Blink'),
        ],
        { rows: 2 },
      ),
    ],
  });
}

/** One bottle-filling station: 13 networks in Main, FB Conveyor, program Signals, two tasks. */
export function bottleFiller(): Project {
  const main = newPou('Main', {
    comment: 'Bottle-filling station.',
    variables: mainLocals(),
    networks: bottleFillerNetworks(),
  });
  return newProject('Bottle filler', {
    description: 'A bottle-filling station: infeed, fill, count, outfeed, maintenance.',
    pous: [main, conveyorFb(), signalsProgram()],
    globals: bottleFillerGlobals(),
    tasks: [
      { name: 'MainTask', cycleMs: 10, priority: 1, programs: [{ instance: 'MainInstance', pou: 'Main' }] },
      {
        name: 'SlowTask',
        cycleMs: 100,
        priority: 2,
        programs: [{ instance: 'SignalsInstance', pou: 'Signals' }],
      },
    ],
  });
}

/**
 * The station with its 13 networks in Main `copies` times (50: 650 networks), each further copy
 * pasted at the end as the editor's paste does (new instances, renamed labels).
 */
export function bottleFillerProject(copies = 50): Project {
  let project = bottleFiller();
  const first = project.pous[0]!;
  const clip = copyNetworks(
    first,
    first.networks.map((n) => n.id),
  )!;
  for (let k = 1; k < copies; k++) {
    const main = project.pous[0]!;
    const p = preparePaste(project, main, clip, 'new');
    const next: Pou = {
      ...main,
      variables: [...main.variables, ...p.variables],
      networks: [...main.networks, ...p.networks],
    };
    project = { ...project, pous: [next, ...project.pous.slice(1)] };
  }
  return project;
}
