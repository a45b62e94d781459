// The road intersection (issue 26): a main road (north-south) crossed by a side road (east-west),
// each with a red/yellow/green signal head, a pedestrian crossing over each road with WALK and
// DON'T WALK lamps and a push button, and a vehicle detector loop at each road's stop line.
//
// Vehicles arrive on a fixed, repeating schedule computed from PLC time (no randomness), queue at
// the stop line while their green is not lit, and leave one every 2 s while it is (the first 1 s
// after the green lights); a car takes 2 s to clear the intersection. Pedestrians come from the
// operator: a press of a crossing's button is a pedestrian waiting there, who starts across when
// the crossing's WALK lamp lights and takes 8 s (main road) or 6 s (side road) to cross.
//
// A conflict monitor, as in a real signal cabinet, watches the lamps the program drives.
import { sensorSlots } from './points';
import type { Value } from '../model/iecTypes';
import type { PlantConsequence, PlantDrive, PlantModel, PlantPoint, Writable } from './types';

/** Vehicle arrivals, ms into each repeating minute (sorted). Main: 12 a minute; side: 6, in bunches. */
export const MAIN_ARRIVALS_MS: readonly number[] = [
  1500, 6000, 10_500, 15_000, 21_000, 25_500, 30_000, 34_500, 40_500, 45_000, 51_000, 55_500,
];
export const SIDE_ARRIVALS_MS: readonly number[] = [4000, 6500, 9000, 31_000, 33_500, 47_000];
export const ARRIVAL_PERIOD_MS = 60_000;
/** A queue leaves one car every HEADWAY_MS of lit green, the first START_MS after the green lights. */
export const HEADWAY_MS = 2000;
const START_MS = 1000;
/** How long a car that left the stop line is in the intersection. */
export const CLEAR_MS = 2000;
/** How long a pedestrian takes to walk across the main road and across the side road. */
export const CROSS_MAIN_MS = 8000;
export const CROSS_SIDE_MS = 6000;
/**
 * The clearance intervals the conflict monitor checks, as a signal cabinet's does: a road's yellow
 * lit at least YELLOW_MIN_MS between its green and its red, and both roads red at least
 * ALL_RED_MIN_MS before the other road's green. PLC time is exact, so a timer of 3 s gives 3 s.
 */
export const YELLOW_MIN_MS = 3000;
export const ALL_RED_MIN_MS = 2000;
/** Sums of step times: a yellow timed exactly may read a hair short. */
const CLEARANCE_HAIR_MS = 1e-6;
/** Waits that are consequences: a vehicle at the stop line, a pedestrian at a button. */
export const VEHICLE_WAIT_LIMIT_MS = 120_000;
export const PED_WAIT_LIMIT_MS = 60_000;
const NOTHING: readonly PlantConsequence[] = [];
/** The time of a car that never left (JSON-safe, unlike -Infinity). */
const NEVER = -1_000_000_000;

/** The lamps, as bits of `lamps` (driven) and `lit` (giving light). */
export const LAMP = {
  MainRed: 1,
  MainYellow: 2,
  MainGreen: 4,
  SideRed: 8,
  SideYellow: 16,
  SideGreen: 32,
  WalkMain: 64,
  DontWalkMain: 128,
  WalkSide: 256,
  DontWalkSide: 512,
} as const;
type LampName = keyof typeof LAMP;
const LAMP_NAMES = Object.keys(LAMP) as LampName[];

/**
 * Bits of `conflict`: which pairs of signals that must never show together do: both roads going,
 * WALK over a road whose traffic goes, and one head showing two things (red with green, WALK with
 * DON'T WALK), which a signal cabinet's monitor flags as it does a conflict.
 */
export const CONFLICT = { Roads: 1, WalkMain: 2, WalkSide: 4, MainHead: 8, SideHead: 16, PedMain: 32, PedSide: 64 } as const;
/** Bits of `dark`: which signal heads give no light at all. */
export const HEAD = { Main: 1, Side: 2, PedMain: 4, PedSide: 8 } as const;
/** Bits of `caught` (a crossing's pedestrians) and `box` (a road's green over the other's car). */
export const ROAD = { Main: 1, Side: 2 } as const;

export interface IntersectionState {
  /** PLC time the machine has reached, ms. */
  readonly timeMs: number;
  /** Lamps the program drives (LAMP bits), and those giving light (a burnt-out lamp does not). */
  readonly lamps: number;
  readonly lit: number;
  /** Vehicles arrived at and gone through each road's stop line since the start. */
  readonly arrivedMain: number;
  readonly departedMain: number;
  readonly arrivedSide: number;
  readonly departedSide: number;
  /** Green time banked toward the next car leaving, per road (ms). */
  readonly goMain: number;
  readonly goSide: number;
  /** When the last car of each road left the stop line (it is in the intersection for CLEAR_MS). */
  readonly lastMainMs: number;
  readonly lastSideMs: number;
  /** The longest any vehicle has waited at a stop line so far, ms. */
  readonly maxWaitMs: number;
  /** Vehicles (by arrival index) already counted as waiting too long, per road. */
  readonly longMain: number;
  readonly longSide: number;
  /** Pedestrians waiting at each crossing, since when the first of them waits, and whether counted as too long. */
  readonly pedWaitMain: number;
  readonly pedWaitSide: number;
  readonly pedSinceMain: number;
  readonly pedSinceSide: number;
  readonly pedLongMain: boolean;
  readonly pedLongSide: boolean;
  /** Time left for the pedestrians on each crossing to reach the far side, ms (0: nobody on it). */
  readonly pedOnMain: number;
  readonly pedOnSide: number;
  /** The buttons as they were held at the last step (a press is a new pedestrian). */
  readonly buttonMain: boolean;
  readonly buttonSide: boolean;
  readonly pedServed: number;
  /** Conditions now (bit masks above): consequences are counted where a bit comes on. */
  readonly conflict: number;
  readonly dark: number;
  readonly caught: number;
  readonly box: number;
  readonly conflicts: number;
  readonly darkSignals: number;
  readonly pedsCaught: number;
  readonly nearMisses: number;
  readonly longWaits: number;
  readonly longPedWaits: number;
  /**
   * The clearance monitor, per road: how long its yellow has been lit since its green, how long
   * its red since it came on, whether that red followed its green or yellow (the other road's
   * green then needs the all-red first), and the counts and account of the last short clearance.
   */
  readonly mainYellowMs: number;
  readonly sideYellowMs: number;
  readonly mainRedMs: number;
  readonly sideRedMs: number;
  readonly mainFromGo: boolean;
  readonly sideFromGo: boolean;
  readonly shortYellows: number;
  readonly shortReds: number;
  readonly lastShortYellow: string;
  readonly lastShortRed: string;
}

/** One road's clearance after a step (module scratch, like a road's queue: no allocation per step). */
const clearance = { yellowMs: 0, redMs: 0, fromGo: false, shortYellow: '' };

/**
 * One road's yellow and red over a step with `lamps` driven (`was`: the step before): fills
 * `clearance`; `shortYellow` says how the road went red too soon after its green, or ''.
 */
function clear(road: 'main' | 'side', lamps: number, was: number, yellowMs: number, redMs: number, fromGo: boolean, dtMs: number): void {
  const R = road === 'main' ? LAMP.MainRed : LAMP.SideRed;
  const Y = road === 'main' ? LAMP.MainYellow : LAMP.SideYellow;
  const G = road === 'main' ? LAMP.MainGreen : LAMP.SideGreen;
  const go = has(lamps, G | Y);
  clearance.shortYellow = '';
  if (has(lamps, G)) clearance.yellowMs = 0;
  else if (has(lamps, Y)) clearance.yellowMs = yellowMs + dtMs;
  else clearance.yellowMs = yellowMs;
  if (has(lamps, R) && !go) {
    // Red now: after the road's green or yellow, the yellow must have been long enough.
    const wentRed = !has(was, R) || has(was, G | Y);
    if (wentRed && has(was, G | Y) && yellowMs < YELLOW_MIN_MS - CLEARANCE_HAIR_MS)
      clearance.shortYellow =
        yellowMs === 0
          ? `the ${road} road went from green to red without yellow`
          : `the ${road} road went from green to red after ${(yellowMs / 1000).toFixed(1)} s of yellow`;
    clearance.redMs = wentRed ? dtMs : redMs + dtMs;
    clearance.fromGo = wentRed ? has(was, G | Y) : fromGo;
  } else {
    clearance.redMs = 0;
    clearance.fromGo = false;
  }
}

/** Arrivals at or before `t` on a road with these offsets into the repeating period. */
export function arrivalsUpTo(offsets: readonly number[], t: number): number {
  if (t < 0) return 0;
  const periods = Math.floor(t / ARRIVAL_PERIOD_MS);
  const rest = t - periods * ARRIVAL_PERIOD_MS;
  let n = 0;
  while (n < offsets.length && offsets[n]! <= rest) n++;
  return periods * offsets.length + n;
}

/** When car number `i` (0-based) of a road arrives. */
export function arrivalTime(offsets: readonly number[], i: number): number {
  return Math.floor(i / offsets.length) * ARRIVAL_PERIOD_MS + offsets[i % offsets.length]!;
}

const on = (v: Value | undefined): boolean => v === true;
const has = (bits: number, mask: number): boolean => (bits & mask) !== 0;
const bitCount = (m: number): number => {
  let n = 0;
  for (let x = m; x; x &= x - 1) n++;
  return n;
};

/** How many bits came on from `before` to `now` (conditions that started). */
const started = (now: number, before: number): number => bitCount(now & ~before);

/** One road's queue after a step: filled in place (no allocation per step), read into the new state. */
interface Road {
  arrived: number;
  departed: number;
  go: number;
  last: number;
  long: number;
  longWaits: number;
  maxWait: number;
}
const road = (): Road => ({ arrived: 0, departed: 0, go: 0, last: 0, long: 0, longWaits: 0, maxWait: 0 });
const MAIN_ROAD = road();
const SIDE_ROAD = road();

/** One road's queue over one step: arrivals from the schedule, departures while its green is lit. */
function advanceRoad(
  out: Road,
  offsets: readonly number[],
  departedBefore: number,
  goBefore: number,
  lastBefore: number,
  longBefore: number,
  green: boolean,
  t0: number,
  t1: number,
  maxWaitBefore: number,
): Road {
  const arrived = arrivalsUpTo(offsets, t1);
  let departed = departedBefore;
  let go = goBefore;
  let last = lastBefore;
  if (green) {
    go += t1 - t0;
    while (go >= HEADWAY_MS && departed < arrived) {
      // The car left when its headway was reached inside this step (not before it arrived).
      last = Math.max(t1 - (go - HEADWAY_MS), arrivalTime(offsets, departed));
      departed++;
      go -= HEADWAY_MS;
    }
    // An empty road banks no more than one headway: a car arriving on green goes straight through.
    if (departed === arrived && go > HEADWAY_MS) go = HEADWAY_MS;
  } else go = HEADWAY_MS - START_MS;
  let maxWait = maxWaitBefore;
  if (departed < arrived) maxWait = Math.max(maxWait, t1 - arrivalTime(offsets, departed));
  // Every car that left had its wait measured when it left (it was at the head of the queue).
  if (departed > departedBefore) maxWait = Math.max(maxWait, last - arrivalTime(offsets, departed - 1));
  let long = Math.max(longBefore, departed);
  let longWaits = 0;
  while (long < arrived && t1 - arrivalTime(offsets, long) >= VEHICLE_WAIT_LIMIT_MS) {
    long++;
    longWaits++;
  }
  out.arrived = arrived;
  out.departed = departed;
  out.go = go;
  out.last = last;
  out.long = long;
  out.longWaits = longWaits;
  out.maxWait = maxWait;
  return out;
}

const POINTS: readonly PlantPoint[] = [
  {
    name: 'CrossMain',
    address: '%IX0.0',
    type: 'BOOL',
    kind: 'operator',
    control: 'button',
    comment: 'Pedestrian push button at the crossing over the main road',
  },
  {
    name: 'CrossSide',
    address: '%IX0.1',
    type: 'BOOL',
    kind: 'operator',
    control: 'button',
    comment: 'Pedestrian push button at the crossing over the side road',
  },
  {
    name: 'LoopMain',
    address: '%IX0.2',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Detector loop at the main road stop line, ON while a vehicle waits',
  },
  {
    name: 'LoopSide',
    address: '%IX0.3',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Detector loop at the side road stop line, ON while a vehicle waits',
  },
  { name: 'MainRed', address: '%QX0.0', type: 'BOOL', kind: 'actuator', comment: 'Main road signal, red' },
  {
    name: 'MainYellow',
    address: '%QX0.1',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Main road signal, yellow',
  },
  {
    name: 'MainGreen',
    address: '%QX0.2',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Main road signal, green',
  },
  { name: 'SideRed', address: '%QX0.3', type: 'BOOL', kind: 'actuator', comment: 'Side road signal, red' },
  {
    name: 'SideYellow',
    address: '%QX0.4',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Side road signal, yellow',
  },
  {
    name: 'SideGreen',
    address: '%QX0.5',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Side road signal, green',
  },
  {
    name: 'WalkMain',
    address: '%QX0.6',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Crossing over the main road, WALK lamp',
  },
  {
    name: 'DontWalkMain',
    address: '%QX0.7',
    type: 'BOOL',
    kind: 'actuator',
    comment: "Crossing over the main road, DON'T WALK lamp",
  },
  {
    name: 'WalkSide',
    address: '%QX1.0',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Crossing over the side road, WALK lamp',
  },
  {
    name: 'DontWalkSide',
    address: '%QX1.1',
    type: 'BOOL',
    kind: 'actuator',
    comment: "Crossing over the side road, DON'T WALK lamp",
  },
];
/** Where sense() writes each sensor (the loop's input image order). */
const SENSE = sensorSlots(POINTS, ['LoopMain', 'LoopSide']);

export const intersection: PlantModel<IntersectionState> = {
  id: 'intersection',
  title: 'Road intersection',
  task: [
    'Control the signals where a side road (east-west) crosses a busy main road (north-south).',
    'Each road has a signal head (red, yellow, green) and a pedestrian crossing over it with WALK and',
    "DON'T WALK lamps and a push button (CrossMain: to cross the main road; CrossSide: the side road).",
    'A detector loop at each stop line (LoopMain, LoopSide) is ON while a vehicle waits there.',
    'Rest on main road green. Serve the side road when a vehicle waits on it or a pedestrian asks to',
    'cross, but not before the main road has had at least 20 s of green. Go from green through',
    'yellow (3 s) and red on both roads (2 s) before the other road gets green. The pedestrians',
    'crossing the main road walk with the side road traffic, those crossing the side road with the',
    "main road traffic: light WALK at the start of that green, for a few seconds, then DON'T WALK",
    'long enough for the last to reach the far side (8 s over the main road, 6 s over the side road)',
    'before the traffic they cross gets green. The conflict monitor checks the clearances: a road',
    'going from green to red with less than 3 s of yellow, or a green less than 2 s after the other',
    'road turned red, is an error.',
    'Never show conflicting signals (both roads green or yellow, WALK over a road with green or',
    "yellow, red with green on one signal, WALK with DON'T WALK), never leave a signal head dark,",
    'never let a vehicle wait more than 120 s or a pedestrian more than 60 s. Vehicles leave one',
    'every 2 s while their green is lit.',
  ].join('\n'),
  points: POINTS,
  faults: [
    { id: 'main_green_out', title: 'Main road green lamp burnt out' },
    { id: 'side_loop_stuck_off', title: 'Side road detector loop stuck OFF' },
    { id: 'side_loop_stuck_on', title: 'Side road detector loop stuck ON' },
    { id: 'main_loop_stuck_off', title: 'Main road detector loop stuck OFF' },
  ],
  quantities: [
    { name: 'served', type: 'INT', comment: 'Vehicles through the intersection' },
    { name: 'served_main', type: 'INT', comment: 'Vehicles through on the main road' },
    { name: 'served_side', type: 'INT', comment: 'Vehicles through on the side road' },
    { name: 'waiting_main', type: 'INT', comment: 'Vehicles waiting at the main road stop line' },
    { name: 'waiting_side', type: 'INT', comment: 'Vehicles waiting at the side road stop line' },
    { name: 'max_wait', type: 'REAL', unit: 's', comment: 'Longest wait of a vehicle at a stop line so far' },
    { name: 'peds_waiting', type: 'INT', comment: 'Pedestrians waiting at the crossings' },
    { name: 'ped_served', type: 'INT', comment: 'Pedestrians who started across on WALK' },
    { name: 'conflicts', type: 'INT', comment: 'Times conflicting signals were shown together' },
    { name: 'dark_signals', type: 'INT', comment: 'Times a signal head went dark (no lamp lit)' },
    {
      name: 'near_misses',
      type: 'INT',
      comment: 'Times a road got green while a car of the other was still in the intersection',
    },
    {
      name: 'peds_caught',
      type: 'INT',
      comment: 'Times a road got green while pedestrians were still crossing it',
    },
    { name: 'long_waits', type: 'INT', comment: 'Vehicles that waited more than 120 s' },
    { name: 'long_ped_waits', type: 'INT', comment: 'Times pedestrians waited more than 60 s' },
    {
      name: 'short_yellows',
      type: 'INT',
      comment: 'Times a road went from green to red with less than 3 s of yellow',
    },
    {
      name: 'short_reds',
      type: 'INT',
      comment: 'Times a road got green less than 2 s after the other road turned red',
    },
  ],

  initial: () => ({
    timeMs: 0,
    lamps: 0,
    lit: 0,
    arrivedMain: 0,
    departedMain: 0,
    arrivedSide: 0,
    departedSide: 0,
    goMain: HEADWAY_MS - START_MS,
    goSide: HEADWAY_MS - START_MS,
    lastMainMs: NEVER,
    lastSideMs: NEVER,
    maxWaitMs: 0,
    longMain: 0,
    longSide: 0,
    pedWaitMain: 0,
    pedWaitSide: 0,
    pedSinceMain: 0,
    pedSinceSide: 0,
    pedLongMain: false,
    pedLongSide: false,
    pedOnMain: 0,
    pedOnSide: 0,
    buttonMain: false,
    buttonSide: false,
    pedServed: 0,
    conflict: 0,
    dark: 0,
    caught: 0,
    box: 0,
    conflicts: 0,
    darkSignals: 0,
    pedsCaught: 0,
    nearMisses: 0,
    longWaits: 0,
    longPedWaits: 0,
    mainYellowMs: 0,
    sideYellowMs: 0,
    mainRedMs: 0,
    sideRedMs: 0,
    mainFromGo: false,
    sideFromGo: false,
    shortYellows: 0,
    shortReds: 0,
    lastShortYellow: '',
    lastShortRed: '',
  }),

  step(
    s: IntersectionState,
    drive: PlantDrive,
    dtMs: number,
    faults: ReadonlySet<string>, into: Writable<IntersectionState> = { ...s },
  ): IntersectionState {
    const t0 = s.timeMs;
    const t1 = t0 + dtMs;
    let lamps = 0;
    for (const name of LAMP_NAMES) if (on(drive[name])) lamps |= LAMP[name];
    const lit = faults.has('main_green_out') ? lamps & ~LAMP.MainGreen : lamps;

    // Vehicles: cars go on a lit green only.
    const mainGreen = has(lit, LAMP.MainGreen);
    const sideGreen = has(lit, LAMP.SideGreen);
    const main = advanceRoad(
      MAIN_ROAD,
      MAIN_ARRIVALS_MS,
      s.departedMain,
      s.goMain,
      s.lastMainMs,
      s.longMain,
      mainGreen,
      t0,
      t1,
      s.maxWaitMs,
    );
    const side = advanceRoad(
      SIDE_ROAD,
      SIDE_ARRIVALS_MS,
      s.departedSide,
      s.goSide,
      s.lastSideMs,
      s.longSide,
      sideGreen,
      t0,
      t1,
      main.maxWait,
    );

    // Pedestrians: a press is one more waiting; WALK lit starts all who wait across.
    const buttonMain = on(drive.CrossMain);
    const buttonSide = on(drive.CrossSide);
    let pedWaitMain = s.pedWaitMain + (buttonMain && !s.buttonMain ? 1 : 0);
    let pedWaitSide = s.pedWaitSide + (buttonSide && !s.buttonSide ? 1 : 0);
    const pedSinceMain = pedWaitMain > 0 && s.pedWaitMain === 0 ? t1 : s.pedSinceMain;
    const pedSinceSide = pedWaitSide > 0 && s.pedWaitSide === 0 ? t1 : s.pedSinceSide;
    let pedOnMain = Math.max(0, s.pedOnMain - dtMs);
    let pedOnSide = Math.max(0, s.pedOnSide - dtMs);
    let pedServed = s.pedServed;
    if (pedWaitMain > 0 && has(lit, LAMP.WalkMain)) {
      pedServed += pedWaitMain;
      pedWaitMain = 0;
      pedOnMain = CROSS_MAIN_MS;
    }
    if (pedWaitSide > 0 && has(lit, LAMP.WalkSide)) {
      pedServed += pedWaitSide;
      pedWaitSide = 0;
      pedOnSide = CROSS_SIDE_MS;
    }
    const longPedMain = pedWaitMain > 0 && t1 - pedSinceMain >= PED_WAIT_LIMIT_MS;
    const longPedSide = pedWaitSide > 0 && t1 - pedSinceSide >= PED_WAIT_LIMIT_MS;
    const pedLongMain = pedWaitMain > 0 && (s.pedLongMain || longPedMain);
    const pedLongSide = pedWaitSide > 0 && (s.pedLongSide || longPedSide);
    const longPedWaits =
      s.longPedWaits + (longPedMain && !s.pedLongMain ? 1 : 0) + (longPedSide && !s.pedLongSide ? 1 : 0);

    // The conflict monitor: on the lamps driven (green or yellow means traffic may go).
    const mainGo = has(lamps, LAMP.MainGreen | LAMP.MainYellow);
    const sideGo = has(lamps, LAMP.SideGreen | LAMP.SideYellow);
    const conflict =
      (mainGo && sideGo ? CONFLICT.Roads : 0) |
      (mainGo && has(lamps, LAMP.WalkMain) ? CONFLICT.WalkMain : 0) |
      (sideGo && has(lamps, LAMP.WalkSide) ? CONFLICT.WalkSide : 0) |
      ((lamps & (LAMP.MainRed | LAMP.MainGreen)) === (LAMP.MainRed | LAMP.MainGreen) ? CONFLICT.MainHead : 0) |
      ((lamps & (LAMP.SideRed | LAMP.SideGreen)) === (LAMP.SideRed | LAMP.SideGreen) ? CONFLICT.SideHead : 0) |
      ((lamps & (LAMP.WalkMain | LAMP.DontWalkMain)) === (LAMP.WalkMain | LAMP.DontWalkMain) ? CONFLICT.PedMain : 0) |
      ((lamps & (LAMP.WalkSide | LAMP.DontWalkSide)) === (LAMP.WalkSide | LAMP.DontWalkSide) ? CONFLICT.PedSide : 0);
    // Dark heads: on the light given (a burnt-out lamp leaves its head dark).
    const dark =
      (has(lit, LAMP.MainRed | LAMP.MainYellow | LAMP.MainGreen) ? 0 : HEAD.Main) |
      (has(lit, LAMP.SideRed | LAMP.SideYellow | LAMP.SideGreen) ? 0 : HEAD.Side) |
      (has(lit, LAMP.WalkMain | LAMP.DontWalkMain) ? 0 : HEAD.PedMain) |
      (has(lit, LAMP.WalkSide | LAMP.DontWalkSide) ? 0 : HEAD.PedSide);
    // A green over pedestrians still crossing that road, or over a car of the other road still in the box.
    const caught =
      (mainGreen && pedOnMain > 0 ? ROAD.Main : 0) | (sideGreen && pedOnSide > 0 ? ROAD.Side : 0);
    const box =
      (mainGreen && t1 - side.last < CLEAR_MS ? ROAD.Main : 0) |
      (sideGreen && t1 - main.last < CLEAR_MS ? ROAD.Side : 0);

    // The clearance monitor: each road's yellow before its red, both red before a green.
    let shortYellows = s.shortYellows;
    let shortReds = s.shortReds;
    let lastShortYellow = s.lastShortYellow;
    let lastShortRed = s.lastShortRed;
    /** A road's clearance just worked out (`clear`): a yellow too short is counted. */
    const countShortYellow = (): void => {
      if (!clearance.shortYellow) return;
      shortYellows++;
      lastShortYellow = clearance.shortYellow;
    };
    clear('main', lamps, s.lamps, s.mainYellowMs, s.mainRedMs, s.mainFromGo, dtMs);
    const mainYellowMs = clearance.yellowMs;
    const mainRedMs = clearance.redMs;
    const mainFromGo = clearance.fromGo;
    countShortYellow();
    clear('side', lamps, s.lamps, s.sideYellowMs, s.sideRedMs, s.sideFromGo, dtMs);
    const sideYellowMs = clearance.yellowMs;
    const sideRedMs = clearance.redMs;
    const sideFromGo = clearance.fromGo;
    countShortYellow();
    // A green that lights: the other road, red after its own green or yellow, must have been red long enough.
    // (The other road going until this very step: its red is 0 s old.)
    for (const [road, G, other, otherGo, otherRedMs, otherFromGo] of [
      ['main', LAMP.MainGreen, 'side', LAMP.SideGreen | LAMP.SideYellow, s.sideRedMs, s.sideFromGo],
      ['side', LAMP.SideGreen, 'main', LAMP.MainGreen | LAMP.MainYellow, s.mainRedMs, s.mainFromGo],
    ] as const) {
      const wasGoing = has(s.lamps, otherGo);
      const redMs = wasGoing ? 0 : otherRedMs;
      if (has(lamps, G) && !has(s.lamps, G) && (wasGoing || otherFromGo) && redMs < ALL_RED_MIN_MS - CLEARANCE_HAIR_MS) {
        shortReds++;
        lastShortRed = `the ${road} road got green ${(redMs / 1000).toFixed(1)} s after the ${other} road turned red`;
      }
    }

    into.timeMs = t1;
    into.lamps = lamps;
    into.lit = lit;
    into.arrivedMain = main.arrived;
    into.departedMain = main.departed;
    into.arrivedSide = side.arrived;
    into.departedSide = side.departed;
    into.goMain = main.go;
    into.goSide = side.go;
    into.lastMainMs = main.last;
    into.lastSideMs = side.last;
    into.maxWaitMs = side.maxWait;
    into.longMain = main.long;
    into.longSide = side.long;
    into.pedWaitMain = pedWaitMain;
    into.pedWaitSide = pedWaitSide;
    into.pedSinceMain = pedSinceMain;
    into.pedSinceSide = pedSinceSide;
    into.pedLongMain = pedLongMain;
    into.pedLongSide = pedLongSide;
    into.pedOnMain = pedOnMain;
    into.pedOnSide = pedOnSide;
    into.buttonMain = buttonMain;
    into.buttonSide = buttonSide;
    into.pedServed = pedServed;
    into.conflict = conflict;
    into.dark = dark;
    into.caught = caught;
    into.box = box;
    into.conflicts = s.conflicts + started(conflict, s.conflict);
    into.darkSignals = s.darkSignals + started(dark, s.dark);
    into.pedsCaught = s.pedsCaught + started(caught, s.caught);
    into.nearMisses = s.nearMisses + started(box, s.box);
    into.longWaits = s.longWaits + main.longWaits + side.longWaits;
    into.longPedWaits = longPedWaits;
    into.mainYellowMs = mainYellowMs;
    into.sideYellowMs = sideYellowMs;
    into.mainRedMs = mainRedMs;
    into.sideRedMs = sideRedMs;
    into.mainFromGo = mainFromGo;
    into.sideFromGo = sideFromGo;
    into.shortYellows = shortYellows;
    into.shortReds = shortReds;
    into.lastShortYellow = lastShortYellow;
    into.lastShortRed = lastShortRed;
    return into;
  },

  sense(s: IntersectionState, faults: ReadonlySet<string>, out: Value[]): void {
    const loopSide = faults.has('side_loop_stuck_on')
      ? true
      : faults.has('side_loop_stuck_off')
        ? false
        : s.arrivedSide > s.departedSide;
    out[SENSE.LoopMain] = faults.has('main_loop_stuck_off') ? false : s.arrivedMain > s.departedMain;
    out[SENSE.LoopSide] = loopSide;
  },

  check(before: IntersectionState, after: IntersectionState): readonly PlantConsequence[] {
    // The common case, every scan: nothing started (no allocation).
    if (
      after.conflicts === before.conflicts &&
      after.darkSignals === before.darkSignals &&
      after.nearMisses === before.nearMisses &&
      after.pedsCaught === before.pedsCaught &&
      after.longWaits === before.longWaits &&
      after.longPedWaits === before.longPedWaits &&
      after.shortYellows === before.shortYellows &&
      after.shortReds === before.shortReds
    )
      return NOTHING;
    const out: PlantConsequence[] = [];
    const newly = (now: number, was: number, bit: number) => (now & bit) !== 0 && (was & bit) === 0;
    const shown = (lamps: number, road: 'Main' | 'Side') =>
      [lamps & LAMP[`${road}Green`] ? 'green' : '', lamps & LAMP[`${road}Yellow`] ? 'yellow' : '']
        .filter(Boolean)
        .join(' and ');
    const conflict = (message: string) =>
      out.push({
        id: 'conflict',
        severity: 'error',
        message: `conflicting signals: ${message}`,
        counter: 'conflicts',
      });
    if (newly(after.conflict, before.conflict, CONFLICT.Roads))
      conflict(`main road ${shown(after.lamps, 'Main')} with side road ${shown(after.lamps, 'Side')}`);
    if (newly(after.conflict, before.conflict, CONFLICT.WalkMain))
      conflict(`WALK over the main road with main road ${shown(after.lamps, 'Main')}`);
    if (newly(after.conflict, before.conflict, CONFLICT.WalkSide))
      conflict(`WALK over the side road with side road ${shown(after.lamps, 'Side')}`);
    if (newly(after.conflict, before.conflict, CONFLICT.MainHead)) conflict('the main road signal shows red and green together');
    if (newly(after.conflict, before.conflict, CONFLICT.SideHead)) conflict('the side road signal shows red and green together');
    if (newly(after.conflict, before.conflict, CONFLICT.PedMain)) conflict("WALK and DON'T WALK together over the main road");
    if (newly(after.conflict, before.conflict, CONFLICT.PedSide)) conflict("WALK and DON'T WALK together over the side road");
    const heads: [number, string][] = [
      [HEAD.Main, 'the main road signal'],
      [HEAD.Side, 'the side road signal'],
      [HEAD.PedMain, 'the pedestrian signal over the main road'],
      [HEAD.PedSide, 'the pedestrian signal over the side road'],
    ];
    for (const [bit, head] of heads)
      if (newly(after.dark, before.dark, bit))
        out.push({ id: 'dark', severity: 'error', message: `${head} went dark`, counter: 'dark_signals' });
    for (const [bit, road, other] of [
      [ROAD.Main, 'main', 'side'],
      [ROAD.Side, 'side', 'main'],
    ] as const) {
      if (newly(after.box, before.box, bit))
        out.push({
          id: 'near_miss',
          severity: 'error',
          message: `the ${road} road got green while a car from the ${other} road was still in the intersection`,
          counter: 'near_misses',
        });
      if (newly(after.caught, before.caught, bit))
        out.push({
          id: 'ped_caught',
          severity: 'error',
          message: `the ${road} road got green while pedestrians were still crossing it`,
          counter: 'peds_caught',
        });
    }
    if (after.longWaits > before.longWaits) {
      const road = after.longSide > before.longSide ? 'side' : 'main';
      out.push({
        id: 'long_wait',
        severity: 'error',
        message: `a vehicle waited more than ${VEHICLE_WAIT_LIMIT_MS / 1000} s on the ${road} road`,
        counter: 'long_waits',
      });
    }
    if (after.longPedWaits > before.longPedWaits) {
      const road = after.pedLongMain && !before.pedLongMain ? 'main' : 'side';
      out.push({
        id: 'long_ped_wait',
        severity: 'error',
        message: `a pedestrian waited more than ${PED_WAIT_LIMIT_MS / 1000} s to cross the ${road} road`,
        counter: 'long_ped_waits',
      });
    }
    if (after.shortYellows > before.shortYellows)
      out.push({
        id: 'short_yellow',
        severity: 'error',
        message: `${after.lastShortYellow} (at least ${YELLOW_MIN_MS / 1000} s of yellow asked)`,
        counter: 'short_yellows',
      });
    if (after.shortReds > before.shortReds)
      out.push({
        id: 'short_all_red',
        severity: 'error',
        message: `${after.lastShortRed} (both roads red at least ${ALL_RED_MIN_MS / 1000} s asked)`,
        counter: 'short_reds',
      });
    return out;
  },

  explain(s: IntersectionState, point: string, faults: ReadonlySet<string>): string | undefined {
    const loop = (road: 'main' | 'side', waiting: number, id: string) => {
      const queue = `${waiting} vehicle${waiting === 1 ? '' : 's'} wait${waiting === 1 ? 's' : ''} at the ${road} road stop line`;
      if (faults.has(`${id}_stuck_on`))
        return `the ${road} road detector loop is stuck ON (fault ${id}_stuck_on): it reads ON whatever waits; ${queue}`;
      if (faults.has(`${id}_stuck_off`))
        return `the ${road} road detector loop is stuck OFF (fault ${id}_stuck_off): it reads OFF whatever waits; ${queue}`;
      return `the ${road} road detector loop is ON while a vehicle waits at the stop line; ${queue}, so it is ${waiting > 0 ? 'ON' : 'OFF'}`;
    };
    switch (point) {
      case 'LoopMain':
        return loop('main', s.arrivedMain - s.departedMain, 'main_loop');
      case 'LoopSide':
        return loop('side', s.arrivedSide - s.departedSide, 'side_loop');
    }
    return undefined;
  },

  quantity(s: IntersectionState, name: string): number | boolean {
    switch (name) {
      case 'served':
        return s.departedMain + s.departedSide;
      case 'served_main':
        return s.departedMain;
      case 'served_side':
        return s.departedSide;
      case 'waiting_main':
        return s.arrivedMain - s.departedMain;
      case 'waiting_side':
        return s.arrivedSide - s.departedSide;
      case 'max_wait':
        return s.maxWaitMs / 1000;
      case 'peds_waiting':
        return s.pedWaitMain + s.pedWaitSide;
      case 'ped_served':
        return s.pedServed;
      case 'conflicts':
        return s.conflicts;
      case 'dark_signals':
        return s.darkSignals;
      case 'near_misses':
        return s.nearMisses;
      case 'peds_caught':
        return s.pedsCaught;
      case 'long_waits':
        return s.longWaits;
      case 'long_ped_waits':
        return s.longPedWaits;
      case 'short_yellows':
        return s.shortYellows;
      case 'short_reds':
        return s.shortReds;
    }
    throw new Error(`intersection has no quantity "${name}"`);
  },
};
