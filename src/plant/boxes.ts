// The box sorter (issue 26): a belt conveyor carries boxes past an entry photo-eye and a size
// sensor (a high photo-eye only a large box breaks) to a diverter station, where a pusher pushes
// large boxes off into a side chute; small boxes ride on to the bin at the belt's end.
//
// Kinematics in one dimension along the belt (millimetres, PLC time), no physics engine: the belt
// ramps up and down, every box on it moves at the belt's speed unless something holds it (the
// pusher's plate, a box ahead). Boxes come from a feeder that puts one on the belt every
// `BOX_SPACING_MM` of belt travel, their sizes from a fixed repeating pattern: the same program
// and the same operator actions always see the same boxes. Across the belt the pusher's plate
// and a box's sideways offset run from 0 (belt's edge by the pusher) to 1 (off into the chute).
import { START_STOP_BUTTONS, sensorSlots } from './points';
import type { Value } from '../model/iecTypes';
import type { PlantConsequence, PlantDrive, PlantModel, PlantPoint, Writable } from './types';

/** Positions along the belt, mm from the infeed (a box's position is its front, downstream, edge). */
export const BELT_LENGTH_MM = 2800;
export const BOX_LENGTH_MM = 300;
export const ENTRY_EYE_MM = 400;
export const SIZE_EYE_MM = 800;
/** The pusher's centre line; its plate covers PUSHER_MM ± PLATE_HALF_MM along the belt. */
export const PUSHER_MM = 2000;
export const PLATE_HALF_MM = 150;
/**
 * The photo-eye at the pusher: a box breaks it from when its centre is 70 mm before the pusher,
 * placed so that a push ordered on it meets the box within the station window even when the
 * program scans at 200 ms (the box runs on 80 mm a scan: one scan to read the eye, one step for
 * the plate to reach the box, up to 160 mm), and at a 1 ms scan still meets it square.
 */
export const PUSHER_EYE_MM = PUSHER_MM + 80;
/** A box whose centre is within this of the pusher's centre line is pushed square; farther, it is struck (jam). */
export const STATION_WINDOW_MM = 100;
/** Belt at full speed. */
export const BELT_SPEED_MM_S = 400;
/** The feeder puts a box on the belt every this much belt travel (so at most one box is between the size eye and the pusher). */
export const BOX_SPACING_MM = 1800;
/** Sizes of the boxes fed, in order, repeating: L large, S small. */
export const SIZE_PATTERN = 'SLLSSLSLLS';
const BELT_RAMP_MS = 500;
const PUSHER_TRAVEL_MS = 600;
const SLOW_PUSHER_TRAVEL_MS = 3000;
/** A box pushed at least this far across falls off the belt's edge when the plate leaves it. */
const TIP_OVER_SIDE = 0.35;
/** A box pushed this far across slides off into the chute (the plate is then at its out limit). */
const INTO_CHUTE_SIDE = 0.97;
/** The limit switches: out at 98 % of the stroke, in at 2 %. */
const OUT_LIMIT = 0.98;
const IN_LIMIT = 0.02;
/** The plate's front across the belt for an extension e: it reaches the belt's edge at e = 1/11. */
const plateFront = (e: number): number => e * 1.1 - 0.1;
/** The plate at `f` touches (or stands across) a box pushed `side` across. */
const touches = (f: number, side: number): boolean => f >= side - 1e-9;

export interface Box {
  /** 1, 2, 3… in the order the feeder put them on the belt. */
  readonly n: number;
  readonly large: boolean;
  /**
   * Where its front edge is, less the belt's travel (`BoxesState.belt`): the front is at
   * `belt + base` mm from the infeed. A box riding the belt keeps its base (and its object: a
   * step allocates nothing for it); a box held still gets a new one.
   */
  readonly base: number;
  /** Sideways offset, 0 (on its lane) to 1 (across the belt: off into the chute from 0.97). */
  readonly side: number;
  /** Held against the pusher's plate or a box ahead: it does not move with the belt. */
  readonly blocked: boolean;
  /** Struck by the pusher off the station, or blocked by the extended plate (a jam). */
  readonly jammed: boolean;
  /** Being pushed square by the plate. */
  readonly pushed: boolean;
}

export interface BoxesState {
  /** Belt speed, 0 to 1 of full speed. */
  readonly speed: number;
  /** Pusher extension, 0 (in) to 1 (out). */
  readonly pusher: number;
  readonly lamp: boolean;
  /** Belt travel since the start, mm. */
  readonly belt: number;
  /** Belt travel since the feeder last put a box on it, mm. */
  readonly feed: number;
  /** Boxes fed so far (the next box is number fed + 1). */
  readonly fed: number;
  /** Boxes on the belt, downstream first. */
  readonly boxes: readonly Box[];
  readonly smallBin: number;
  readonly largeChute: number;
  readonly sorted: number;
  readonly missorted: number;
  readonly jams: number;
  readonly fallen: number;
  /** What the last consequence of each kind was ("box 3 (small) was pushed into the large-box chute"). */
  readonly lastMissort: string;
  readonly lastJam: string;
  readonly lastFall: string;
  /** The last box that left the belt and where: 'bin', 'chute', 'floor' (the drawing shows it). */
  readonly lastOut: string;
}

const NOTHING: readonly PlantConsequence[] = [];
const on = (v: Value | undefined): boolean => v === true;
const towards = (from: number, target: number, dtMs: number, travelMs: number): number => {
  const delta = dtMs / travelMs;
  return target > from ? Math.min(target, from + delta) : Math.max(target, from - delta);
};
const sizeOf = (b: Box): string => (b.large ? 'large' : 'small');
/** Where a box's front edge is, mm from the infeed. */
export const frontOf = (s: BoxesState, b: Box): number => s.belt + b.base;
/** A box with its front at `x` breaks a photo-eye at `at` (across the belt, so anywhere sideways while on the belt). */
const covers = (x: number, at: number): boolean => x >= at && x - BOX_LENGTH_MM <= at;
/** The plate's upstream face along the belt. */
const PLATE_FACE_MM = PUSHER_MM - PLATE_HALF_MM;
/** Positions are sums of travel and base: a box held at the face may read a hair off it. */
const HAIR_MM = 1e-6;
/** A box whose front is at `x` is (partly) in front of the plate. */
const underPlate = (x: number): boolean =>
  x > PLATE_FACE_MM + HAIR_MM && x - BOX_LENGTH_MM < PUSHER_MM + PLATE_HALF_MM;

const POINTS: readonly PlantPoint[] = [
  ...START_STOP_BUTTONS,
  {
    name: 'EntryEye',
    address: '%IX0.2',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Entry photo-eye, 0.4 m from the infeed (ON while a box breaks it)',
  },
  {
    name: 'SizeEye',
    address: '%IX0.3',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Size sensor, high photo-eye at 0.8 m (ON while a large box breaks it)',
  },
  {
    name: 'PusherEye',
    address: '%IX0.4',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Photo-eye at the pusher, 2.08 m (ON while a box is in front of the pusher)',
  },
  {
    name: 'PusherOut',
    address: '%IX0.5',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Pusher extended limit switch',
  },
  {
    name: 'PusherIn',
    address: '%IX0.6',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Pusher retracted limit switch',
  },
  { name: 'Conveyor', address: '%QX0.0', type: 'BOOL', kind: 'actuator', comment: 'Belt motor contactor' },
  {
    name: 'Pusher',
    address: '%QX0.1',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Pusher cylinder solenoid valve (extends while ON)',
  },
  { name: 'RunLamp', address: '%QX0.2', type: 'BOOL', kind: 'actuator', comment: 'Running pilot lamp' },
];
/** Where sense() writes each sensor (the loop's input image order). */
const SENSE = sensorSlots(POINTS, ['EntryEye', 'SizeEye', 'PusherEye', 'PusherOut', 'PusherIn']);

export const boxes: PlantModel<BoxesState> = {
  id: 'boxes',
  title: 'Box sorter (conveyor, size sensor, pusher)',
  task: [
    'Sort the boxes by size: push every large box into the side chute, let every small box ride',
    'on to the bin at the end of the belt.',
    'Start (a push button) starts the conveyor, Stop stops it; RunLamp is lit while it runs.',
    'The belt runs at 0.4 m/s (0.5 s to run up); boxes are 0.3 m long. A feeder puts a box on the',
    'belt every 1.8 m of belt travel (4.5 s at full speed). The size sensor SizeEye is a high',
    'photo-eye only a large box breaks; it sits 1.2 m before the pusher.',
    'PusherEye comes ON when a box has reached the pusher (its centre 70 mm before the pusher).',
    'Pusher extends the pusher while ON (0.6 s to the out limit PusherOut) and retracts it when',
    'OFF (PusherIn is the in limit). Push a large box only when it is in front of the pusher and',
    'hold the pusher out until PusherOut: a box pushed halfway falls off the belt, the pusher',
    'striking a box off the station or left out in the way of the next box jams the conveyor.',
    'Scan at 200 ms or faster: a box runs on 80 mm in 200 ms, and the plate must meet it within',
    '100 mm of its centre.',
    'Goal: 10 boxes sorted into the right place, none missorted, no jam, no box fallen.',
  ].join('\n'),
  points: POINTS,
  faults: [
    { id: 'entry_stuck_on', title: 'Entry photo-eye stuck ON' },
    { id: 'size_stuck_off', title: 'Size sensor stuck OFF (sees no large box)' },
    { id: 'size_stuck_on', title: 'Size sensor stuck ON' },
    { id: 'station_stuck_off', title: 'Photo-eye at the pusher (station) stuck OFF' },
    { id: 'motor_dead', title: 'Belt motor does not start' },
    { id: 'pusher_slow', title: 'Pusher slow (3 s to extend or retract)' },
  ],
  quantities: [
    {
      name: 'sorted',
      type: 'INT',
      comment: 'Boxes that reached the right place (large in the chute, small in the bin)',
    },
    { name: 'missorted', type: 'INT', comment: 'Boxes that reached the wrong place' },
    { name: 'jams', type: 'INT', comment: 'Times a box jammed against the pusher' },
    { name: 'fallen', type: 'INT', comment: 'Boxes that fell off the belt' },
    { name: 'on_belt', type: 'INT', comment: 'Boxes on the belt now' },
    { name: 'fed', type: 'INT', comment: 'Boxes the feeder has put on the belt' },
    { name: 'small_bin', type: 'INT', comment: 'Boxes in the bin at the end of the belt' },
    { name: 'large_chute', type: 'INT', comment: 'Boxes pushed into the side chute' },
    { name: 'speed', type: 'REAL', unit: '%', comment: 'Belt speed' },
    { name: 'pusher', type: 'REAL', unit: '%', comment: 'Pusher extension' },
    { name: 'jammed', type: 'BOOL', comment: 'A box is jammed against the pusher now' },
  ],

  initial: () => ({
    speed: 0,
    pusher: 0,
    lamp: false,
    belt: 0,
    feed: BOX_SPACING_MM,
    fed: 0,
    boxes: [],
    smallBin: 0,
    largeChute: 0,
    sorted: 0,
    missorted: 0,
    jams: 0,
    fallen: 0,
    lastMissort: '',
    lastJam: '',
    lastFall: '',
    lastOut: '',
  }),

  step(s: BoxesState, drive: PlantDrive, dtMs: number, faults: ReadonlySet<string>, into: Writable<BoxesState> = { ...s }): BoxesState {
    const speed = towards(
      s.speed,
      on(drive.Conveyor) && !faults.has('motor_dead') ? 1 : 0,
      dtMs,
      BELT_RAMP_MS,
    );
    const travel = ((s.speed + speed) / 2) * BELT_SPEED_MM_S * (dtMs / 1000);
    const f0 = plateFront(s.pusher);
    let sorted = s.sorted;
    let missorted = s.missorted;
    let jams = s.jams;
    let fallen = s.fallen;
    let smallBin = s.smallBin;
    let largeChute = s.largeChute;
    let lastMissort = s.lastMissort;
    let lastJam = s.lastJam;
    let lastFall = s.lastFall;
    let lastOut = s.lastOut;
    // The pusher travels (a plate striking a box stops it there, below).
    let pusher = towards(
      s.pusher,
      on(drive.Pusher) ? 1 : 0,
      dtMs,
      faults.has('pusher_slow') ? SLOW_PUSHER_TRAVEL_MS : PUSHER_TRAVEL_MS,
    );
    let f = plateFront(pusher);
    const extending = pusher > s.pusher;
    const belt = s.belt + travel;
    const list = s.boxes;
    /** The new list of boxes, made on the first box that changes (riding boxes are kept as they are). */
    let kept: Box[] | undefined;

    // Downstream first. Along the belt: each box moves with the belt unless the plate holds it
    // (being pushed, struck), the plate stands in its way, or the box ahead stops it.
    let limit = Infinity;
    for (let i = 0; i < list.length; i++) {
      const b = list[i]!;
      const was = s.belt + b.base;
      let x = was;
      let side = b.side;
      let pushed = b.pushed;
      let blocked = false;
      let jammed = b.jammed;
      /** It moved with the belt all the step: its base stays (exactly) what it was. */
      let rode = false;
      const held = (pushed || jammed) && touches(f0, side) && underPlate(x);
      if (held) blocked = true;
      else {
        rode = true;
        x = belt + b.base;
        if (f0 > side && was <= PLATE_FACE_MM + HAIR_MM && x > PLATE_FACE_MM) {
          // The extended plate stands across this box's lane: it runs into it.
          x = PLATE_FACE_MM;
          blocked = true;
          rode = false;
          if (!jammed) {
            jammed = true;
            jams++;
            lastJam = `box ${b.n} (${sizeOf(b)}) jammed against the extended pusher`;
          }
        }
        if (x > limit) {
          x = Math.max(was, limit);
          blocked = true;
          rode = false;
        }
      }
      if (!blocked) jammed = false;
      // Off the end of the belt into the bin once its centre passes the end.
      if (x - BOX_LENGTH_MM / 2 >= BELT_LENGTH_MM) {
        kept ??= list.slice(0, i);
        smallBin++;
        lastOut = 'bin';
        if (b.large) {
          missorted++;
          lastMissort = `box ${b.n} (large) ran into the small-box bin`;
        } else sorted++;
        continue;
      }
      limit = x - BOX_LENGTH_MM;

      // Across the belt: the plate pushes the box square in front of it, strikes a box that is
      // not (a jam: the plate stops there), lets go when it goes back.
      if (extending && underPlate(x) && f > side + 1e-9) {
        blocked = true;
        if (!pushed && (jammed || Math.abs(x - BOX_LENGTH_MM / 2 - PUSHER_MM) > STATION_WINDOW_MM)) {
          // Struck off the station: the plate stops against the box.
          if (!jammed) {
            jams++;
            lastJam = `the pusher struck box ${b.n} (${sizeOf(b)}) off the station`;
          }
          jammed = true;
          pusher = Math.max(s.pusher, (side + 0.1) / 1.1);
          f = side;
        } else {
          pushed = true;
          side = Math.min(1, f);
        }
      } else if ((pushed || jammed) && !touches(f, side)) {
        // The plate left it.
        if (pushed && side >= TIP_OVER_SIDE) {
          kept ??= list.slice(0, i);
          fallen++;
          lastOut = 'floor';
          lastFall = `box ${b.n} (${sizeOf(b)}) fell off the belt (pushed ${Math.round(side * 100)} % across, then let go)`;
          continue;
        }
        pushed = false;
        jammed = false;
      }
      if (side >= INTO_CHUTE_SIDE) {
        kept ??= list.slice(0, i);
        largeChute++;
        lastOut = 'chute';
        if (b.large) sorted++;
        else {
          missorted++;
          lastMissort = `box ${b.n} (small) was pushed into the large-box chute`;
        }
        continue;
      }
      const base = rode ? b.base : x - belt;
      if (
        base === b.base &&
        side === b.side &&
        blocked === b.blocked &&
        jammed === b.jammed &&
        pushed === b.pushed
      )
        kept?.push(b);
      else (kept ??= list.slice(0, i)).push({ n: b.n, large: b.large, base, side, blocked, jammed, pushed });
    }

    // 3. The feeder: a box on the belt every BOX_SPACING_MM of travel, when the infeed is clear.
    let feed = s.feed + travel;
    let fed = s.fed;
    const now = kept ?? list;
    const last = now[now.length - 1];
    if (feed >= BOX_SPACING_MM && travel > 0) {
      const x = feed - BOX_SPACING_MM;
      if (!last || belt + last.base - BOX_LENGTH_MM >= x) {
        fed++;
        (kept ??= list.slice()).push({
          n: fed,
          large: SIZE_PATTERN[(fed - 1) % SIZE_PATTERN.length] === 'L',
          base: x - belt,
          side: 0,
          blocked: false,
          jammed: false,
          pushed: false,
        });
        feed = x;
      } else feed = BOX_SPACING_MM;
    }

    into.speed = speed;
    into.pusher = pusher;
    into.lamp = on(drive.RunLamp);
    into.belt = belt;
    into.feed = feed;
    into.fed = fed;
    into.boxes = kept ?? list;
    into.smallBin = smallBin;
    into.largeChute = largeChute;
    into.sorted = sorted;
    into.missorted = missorted;
    into.jams = jams;
    into.fallen = fallen;
    into.lastMissort = lastMissort;
    into.lastJam = lastJam;
    into.lastFall = lastFall;
    into.lastOut = lastOut;
    return into;
  },

  sense(s: BoxesState, faults: ReadonlySet<string>, out: Value[]): void {
    let entry = false;
    let size = false;
    let atPusher = false;
    for (const b of s.boxes) {
      const x = s.belt + b.base;
      if (covers(x, ENTRY_EYE_MM)) entry = true;
      if (b.large && covers(x, SIZE_EYE_MM)) size = true;
      if (covers(x, PUSHER_EYE_MM)) atPusher = true;
    }
    out[SENSE.EntryEye] = faults.has('entry_stuck_on') ? true : entry;
    out[SENSE.SizeEye] = faults.has('size_stuck_on') ? true : faults.has('size_stuck_off') ? false : size;
    out[SENSE.PusherEye] = faults.has('station_stuck_off') ? false : atPusher;
    out[SENSE.PusherOut] = s.pusher >= OUT_LIMIT;
    out[SENSE.PusherIn] = s.pusher <= IN_LIMIT;
  },

  explain(s: BoxesState, point: string, faults: ReadonlySet<string>): string | undefined {
    const m = (mm: number) => `${(mm / 1000).toFixed(2)} m`;
    const pusher = `the pusher is ${(s.pusher * 100).toFixed(1)} % out`;
    /** What is at a photo-eye `at` mm along the belt, and whether it breaks the beam (`large`: only a large box does). */
    const eye = (title: string, at: number, largeOnly: boolean): string => {
      const there = s.boxes.filter((b) => covers(frontOf(s, b), at));
      const breaking = there.filter((b) => b.large || !largeOnly);
      const words = there.map(
        (b) =>
          `box ${b.n} (${sizeOf(b)}) is in front of it, its front edge at ${m(frontOf(s, b))}${largeOnly && !b.large ? ', too low to break the high beam' : ''}`,
      );
      const upstream = s.boxes.filter((b) => frontOf(s, b) < at).map((b) => frontOf(s, b));
      const next = upstream.length ? Math.max(...upstream) : undefined;
      const what = words.length
        ? words.join('; ')
        : `no box is in front of it${next === undefined ? '' : ` (the next box's front edge is at ${m(next)})`}`;
      return `${title} at ${m(at)} is ON while ${largeOnly ? 'a large box' : 'a box'} breaks its beam; ${what}, so it is ${breaking.length ? 'ON' : 'OFF'}`;
    };
    switch (point) {
      case 'EntryEye':
        return faults.has('entry_stuck_on')
          ? 'the entry photo-eye is stuck ON (fault entry_stuck_on): it reads ON whatever is on the belt'
          : eye('the entry photo-eye', ENTRY_EYE_MM, false);
      case 'SizeEye':
        return faults.has('size_stuck_on')
          ? 'the size sensor is stuck ON (fault size_stuck_on): it reads ON whatever is on the belt'
          : faults.has('size_stuck_off')
            ? 'the size sensor is stuck OFF (fault size_stuck_off): it reads OFF whatever is on the belt'
            : eye('the size sensor, a high photo-eye,', SIZE_EYE_MM, true);
      case 'PusherEye':
        return faults.has('station_stuck_off')
          ? 'the photo-eye at the pusher is stuck OFF (fault station_stuck_off): it reads OFF whatever is on the belt'
          : eye('the photo-eye at the pusher', PUSHER_EYE_MM, false);
      case 'PusherOut':
        return `the out limit switch is ON at ${OUT_LIMIT * 100} % out and over; ${pusher}, so it is ${s.pusher >= OUT_LIMIT ? 'ON' : 'OFF'}`;
      case 'PusherIn':
        return `the in limit switch is ON at ${IN_LIMIT * 100} % out and under; ${pusher}, so it is ${s.pusher <= IN_LIMIT ? 'ON' : 'OFF'}`;
    }
    return undefined;
  },

  check(before: BoxesState, after: BoxesState): readonly PlantConsequence[] {
    if (after.missorted === before.missorted && after.jams === before.jams && after.fallen === before.fallen)
      return NOTHING;
    const out: PlantConsequence[] = [];
    if (after.missorted > before.missorted)
      out.push({ id: 'missorted', severity: 'error', message: after.lastMissort, counter: 'missorted' });
    if (after.jams > before.jams)
      out.push({ id: 'jam', severity: 'error', message: after.lastJam, counter: 'jams' });
    if (after.fallen > before.fallen)
      out.push({ id: 'fallen', severity: 'error', message: after.lastFall, counter: 'fallen' });
    return out;
  },

  quantity(s: BoxesState, name: string): number | boolean {
    switch (name) {
      case 'sorted':
        return s.sorted;
      case 'missorted':
        return s.missorted;
      case 'jams':
        return s.jams;
      case 'fallen':
        return s.fallen;
      case 'on_belt':
        return s.boxes.length;
      case 'fed':
        return s.fed;
      case 'small_bin':
        return s.smallBin;
      case 'large_chute':
        return s.largeChute;
      case 'speed':
        return s.speed * 100;
      case 'pusher':
        return s.pusher * 100;
      case 'jammed':
        return s.boxes.some((b) => b.jammed);
    }
    throw new Error(`boxes has no quantity "${name}"`);
  },
};
