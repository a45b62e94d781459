// The garage door (issue 26): a sectional door lifted and lowered by a reversing motor (two
// contactors, up and down), with a limit switch at each end of its travel, a photo-eye across
// the doorway, a key switch and a warning lamp. The operator drives a car into the doorway (it can
// pass only under a door open above its roof); a door that comes down on it hits it.
// Position is the door's opening in percent of the doorway's height (0 closed, 100 fully open).
import { sensorSlots } from './points';
import type { Value } from '../model/iecTypes';
import type { PlantConsequence, PlantDrive, PlantModel, PlantPoint, Writable } from './types';

/** Full travel at nominal speed, and with the `motor_slow` fault. */
export const TRAVEL_MS = 12_000;
const SLOW_TRAVEL_MS = 30_000;
/** The motor reaches full speed in this time from standstill; it brakes to a stop in BRAKE_MS. */
const RAMP_MS = 500;
const BRAKE_MS = 100;
/** Where the limit switches are made: OpenLimit ON at and above, ClosedLimit ON at and below. */
export const OPEN_LIMIT_AT = 99;
export const CLOSED_LIMIT_AT = 1;
/** The car's roof, in percent of the doorway's height: it passes only under a door open above it. */
export const CAR_TOP = 60;
/** The motor driving the door against its end stop this long damages it (overrun). */
export const OVERRUN_MS = 1000;
/** The warning lamp must be lit this long before the door starts to move (and while it moves). */
export const PREWARN_MS = 1000;

export interface GarageState {
  /** The door's opening, percent of the doorway's height: 0 closed, 100 fully open. */
  readonly position: number;
  /** Motor speed, -1 (down at nominal speed) to 1 (up); 0 stalled against an end stop or on the car. */
  readonly speed: number;
  /** The contactors and the lamp as the program drives them. */
  readonly up: boolean;
  readonly down: boolean;
  readonly lamp: boolean;
  /** How long the warning lamp has been lit without a break. */
  readonly lampMs: number;
  /** The door moved in the last step. */
  readonly moving: boolean;
  /** The operator wants a car in the doorway; the car is in it (under the door, in the photo-eye's beam). */
  readonly carWaiting: boolean;
  readonly carIn: boolean;
  /** The door's edge rests on the car. */
  readonly onCar: boolean;
  /** Both contactors on: a phase-to-phase short (the motor does not turn). */
  readonly short: boolean;
  /** How long the motor has driven the door against an end stop (reset when it stops or leaves the end). */
  readonly pushMs: number;
  /** The door moves (or started) without the warning the task asks for. */
  readonly unwarnedNow: boolean;
  /** The door has been fully open since it was last closed (a cycle ends when it closes). */
  readonly wasOpen: boolean;
  readonly cycles: number;
  readonly hits: number;
  readonly overruns: number;
  readonly shorts: number;
  readonly unwarned: number;
}

const on = (v: Value | undefined): boolean => v === true;

const NOTHING: readonly PlantConsequence[] = [];
const POINTS: readonly PlantPoint[] = [
  {
    name: 'KeyOpen',
    address: '%IX0.0',
    type: 'BOOL',
    kind: 'operator',
    control: 'button',
    comment: 'Key switch turned to OPEN (spring return)',
  },
  {
    name: 'KeyClose',
    address: '%IX0.1',
    type: 'BOOL',
    kind: 'operator',
    control: 'button',
    comment: 'Key switch turned to CLOSE (spring return)',
  },
  {
    name: 'Stop',
    address: '%IX0.2',
    type: 'BOOL',
    kind: 'operator',
    control: 'button',
    comment: 'Stop push button (NO)',
  },
  {
    name: 'OpenLimit',
    address: '%IX0.3',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Open limit switch, ON at 99 % open and above',
  },
  {
    name: 'ClosedLimit',
    address: '%IX0.4',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Closed limit switch, ON at 1 % open and below',
  },
  {
    name: 'Obstacle',
    address: '%IX0.5',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Photo-eye across the doorway, ON while the beam is broken',
  },
  {
    name: 'Doorway',
    address: '%IX0.6',
    type: 'BOOL',
    kind: 'operator',
    control: 'switch',
    comment: 'A car in the doorway (simulation: the operator drives one in; read Obstacle)',
  },
  {
    name: 'MotorUp',
    address: '%QX0.0',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Motor contactor, door up',
  },
  {
    name: 'MotorDown',
    address: '%QX0.1',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Motor contactor, door down',
  },
  {
    name: 'WarningLamp',
    address: '%QX0.2',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Warning lamp over the doorway',
  },
];
/** Where sense() writes each sensor (the loop's input image order). */
const SENSE = sensorSlots(POINTS, ['OpenLimit', 'ClosedLimit', 'Obstacle']);

export const garage: PlantModel<GarageState> = {
  id: 'garage',
  title: 'Garage door',
  task: [
    'Open and close the garage door on the key switch, stopping at the limit switches, and never',
    'let it come down on a car in the doorway.',
    'KeyOpen (key turned to OPEN, springs back) opens the door: MotorUp until OpenLimit comes ON.',
    'KeyClose (key turned to CLOSE) closes it: MotorDown until ClosedLimit comes ON. Stop stops the',
    'door wherever it is. A door that is opening ignores KeyClose until it is open or stopped.',
    'The photo-eye Obstacle is ON while something is in the doorway: the door does not close while it',
    'is ON, and a closing door reverses and opens fully when it comes ON.',
    'WarningLamp lights 1 s before the door starts to move (the motor starts 1 s after the key) and',
    'stays lit while it moves. Never switch MotorUp and MotorDown on together (short circuit), never',
    'keep the motor on against an end of travel (overrun: over 1 s damages it).',
    "The door takes 12 s from closed to open. Doorway is the simulation's own control: the operator",
    'drives a car into the doorway (it passes only under a door open above 60 %); the program reads',
    'the photo-eye, not Doorway.',
  ].join('\n'),
  points: POINTS,
  faults: [
    { id: 'open_stuck_off', title: 'Open limit switch stuck OFF' },
    { id: 'open_stuck_on', title: 'Open limit switch stuck ON' },
    { id: 'closed_stuck_off', title: 'Closed limit switch stuck OFF' },
    { id: 'closed_stuck_on', title: 'Closed limit switch stuck ON' },
    { id: 'eye_stuck_off', title: 'Photo-eye stuck OFF (does not see the car)' },
    { id: 'motor_dead', title: 'Motor does not start' },
    { id: 'motor_slow', title: 'Motor slow (30 s full travel)' },
  ],
  quantities: [
    { name: 'position', type: 'REAL', unit: '%', comment: 'Door opening: 0 closed, 100 fully open' },
    {
      name: 'speed',
      type: 'REAL',
      unit: '%',
      comment: 'Door speed, percent of full speed, up positive, down negative (0 stalled against a stop)',
    },
    { name: 'moving', type: 'BOOL', comment: 'The door is moving' },
    { name: 'car_in', type: 'BOOL', comment: 'A car is in the doorway' },
    { name: 'on_car', type: 'BOOL', comment: 'The door rests on the car' },
    { name: 'cycles', type: 'INT', comment: 'Full cycles: fully open, then closed' },
    { name: 'hits', type: 'INT', comment: 'Times the door came down on the car' },
    {
      name: 'overruns',
      type: 'INT',
      comment: 'Times the motor drove the door against an end stop for over 1 s',
    },
    { name: 'shorts', type: 'INT', comment: 'Times both motor contactors were on together' },
    { name: 'unwarned', type: 'INT', comment: 'Times the door moved without the warning the task asks for' },
  ],

  initial: () => ({
    position: 0,
    speed: 0,
    up: false,
    down: false,
    lamp: false,
    lampMs: 0,
    moving: false,
    carWaiting: false,
    carIn: false,
    onCar: false,
    short: false,
    pushMs: 0,
    unwarnedNow: false,
    wasOpen: false,
    cycles: 0,
    hits: 0,
    overruns: 0,
    shorts: 0,
    unwarned: 0,
  }),

  step(s: GarageState, drive: PlantDrive, dtMs: number, faults: ReadonlySet<string>, into: Writable<GarageState> = { ...s }): GarageState {
    const up = on(drive.MotorUp);
    const down = on(drive.MotorDown);
    const lamp = on(drive.WarningLamp);
    const short = up && down;
    const powered = !short && !faults.has('motor_dead');
    const top = faults.has('motor_slow') ? TRAVEL_MS / SLOW_TRAVEL_MS : 1;
    const target = powered ? (up ? top : down ? -top : 0) : 0;
    // Braking to a stop (or through it, to reverse) is quick; starting takes the ramp.
    let speed = s.speed;
    if (speed !== 0 && (target === 0 || Math.sign(target) !== Math.sign(speed))) {
      const dv = dtMs / BRAKE_MS;
      speed = speed > 0 ? Math.max(0, speed - dv) : Math.min(0, speed + dv);
    } else if (target !== speed) {
      const dv = dtMs / RAMP_MS;
      speed = target > speed ? Math.min(target, speed + dv) : Math.max(target, speed - dv);
    }
    // The car drives in only under a door open above its roof; it leaves when the operator says.
    const carWaiting = on(drive.Doorway);
    const carIn = carWaiting && (s.carIn || s.position > CAR_TOP);
    let position = s.position + (speed * 100 * dtMs) / TRAVEL_MS;
    const floor = carIn ? CAR_TOP : 0;
    if (position > 100) position = 100;
    if (position < floor) position = floor;
    const onCar = carIn && position <= CAR_TOP && (speed < 0 || s.onCar);
    const pushing = (speed > 0 && position >= 100) || (speed < 0 && position <= 0);
    // Against an end stop, or resting on the car, the door does not move: the motor stalls
    // (its contactor may still be on: that is the overrun), so the door's speed is 0.
    if ((speed > 0 && position >= 100) || (speed < 0 && position <= floor)) speed = 0;
    const moving = position !== s.position;
    const lampMs = lamp ? s.lampMs + dtMs : 0;
    // Driven by the motor, that is: a door braking to a stop after the contactor dropped (with the
    // lamp, as the limit switch ends the run) is not moved without warning, however fast the scan.
    const unwarnedNow = moving && target !== 0 && (!lamp || (!s.moving && lampMs < PREWARN_MS));
    const pushMs = pushing ? s.pushMs + dtMs : 0;
    const open = position >= OPEN_LIMIT_AT;
    const closed = position <= CLOSED_LIMIT_AT;
    const cycleDone = closed && s.wasOpen;
    into.position = position;
    into.speed = speed;
    into.up = up;
    into.down = down;
    into.lamp = lamp;
    into.lampMs = lampMs;
    into.moving = moving;
    into.carWaiting = carWaiting;
    into.carIn = carIn;
    into.onCar = onCar;
    into.short = short;
    into.pushMs = pushMs;
    into.unwarnedNow = unwarnedNow;
    into.wasOpen = open || (s.wasOpen && !closed);
    into.cycles = s.cycles + (cycleDone ? 1 : 0);
    into.hits = s.hits + (onCar && !s.onCar ? 1 : 0);
    into.overruns = s.overruns + (pushMs > OVERRUN_MS && s.pushMs <= OVERRUN_MS ? 1 : 0);
    into.shorts = s.shorts + (short && !s.short ? 1 : 0);
    into.unwarned = s.unwarned + (unwarnedNow && !s.unwarnedNow ? 1 : 0);
    return into;
  },

  sense(s: GarageState, faults: ReadonlySet<string>, out: Value[]): void {
    const open = s.position >= OPEN_LIMIT_AT;
    const closed = s.position <= CLOSED_LIMIT_AT;
    // No fault set (the usual case): the switches as the door has them, no fault looked up.
    if (faults.size === 0) {
      out[SENSE.OpenLimit] = open;
      out[SENSE.ClosedLimit] = closed;
      out[SENSE.Obstacle] = s.carIn;
      return;
    }
    const sw = (id: string, real: boolean) =>
      faults.has(`${id}_stuck_on`) ? true : faults.has(`${id}_stuck_off`) ? false : real;
    out[SENSE.OpenLimit] = sw('open', open);
    out[SENSE.ClosedLimit] = sw('closed', closed);
    out[SENSE.Obstacle] = sw('eye', s.carIn);
  },

  explain(s: GarageState, point: string, faults: ReadonlySet<string>): string | undefined {
    const door = `the door is ${s.position.toFixed(1)} % open`;
    const stuck = (id: string, title: string, whatever: string): string | undefined =>
      faults.has(`${id}_stuck_on`)
        ? `${title} is stuck ON (fault ${id}_stuck_on): it reads ON ${whatever}`
        : faults.has(`${id}_stuck_off`)
          ? `${title} is stuck OFF (fault ${id}_stuck_off): it reads OFF ${whatever}`
          : undefined;
    switch (point) {
      case 'OpenLimit':
        return (
          (stuck('open', 'the open limit switch', `wherever the door is; ${door}`) ??
          `the open limit switch is ON at ${OPEN_LIMIT_AT} % open and above; ${door}, so it is ${s.position >= OPEN_LIMIT_AT ? 'ON' : 'OFF'}`)
        );
      case 'ClosedLimit':
        return (
          (stuck('closed', 'the closed limit switch', `wherever the door is; ${door}`) ??
          `the closed limit switch is ON at ${CLOSED_LIMIT_AT} % open and below; ${door}, so it is ${s.position <= CLOSED_LIMIT_AT ? 'ON' : 'OFF'}`)
        );
      case 'Obstacle': {
        const car = s.carIn
          ? `a car is in the doorway, in the beam${s.onCar ? ', with the door resting on it' : ''}`
          : s.carWaiting
            ? `a car waits outside: it drives in only under a door open above ${CAR_TOP} %, and ${door}`
            : 'no car is in the doorway';
        return stuck('eye', 'the photo-eye', `whatever is in the doorway; ${car}`) ?? `the photo-eye is ON while something breaks its beam; ${car}, so it is ${s.carIn ? 'ON' : 'OFF'}`;
      }
    }
    return undefined;
  },

  check(before: GarageState, after: GarageState): readonly PlantConsequence[] {
    // Nothing started (every scan but a handful): no list made.
    let out: PlantConsequence[] | undefined;
    if (after.hits > before.hits)
      (out ??= []).push({
        id: 'hit',
        severity: 'error',
        message: 'the door came down on the car in the doorway',
        counter: 'hits',
      });
    if (after.shorts > before.shorts)
      (out ??= []).push({
        id: 'short',
        severity: 'error',
        message: 'MotorUp and MotorDown were on together (short circuit)',
        counter: 'shorts',
      });
    if (after.overruns > before.overruns)
      (out ??= []).push({
        id: 'overrun',
        severity: 'error',
        message: `the motor drove the door against its ${after.position >= 100 ? 'open' : 'closed'} end stop for over ${OVERRUN_MS / 1000} s (overrun)`,
        counter: 'overruns',
      });
    if (after.unwarned > before.unwarned)
      (out ??= []).push({
        id: 'unwarned',
        severity: 'warning',
        message: after.lamp
          ? `the door started to move less than ${PREWARN_MS / 1000} s after the warning lamp lit`
          : 'the door moved without the warning lamp lit',
        counter: 'unwarned',
      });
    return out ?? NOTHING;
  },

  quantity(s: GarageState, name: string): number | boolean {
    switch (name) {
      case 'position':
        return s.position;
      case 'speed':
        return s.speed * 100;
      case 'moving':
        return s.moving;
      case 'car_in':
        return s.carIn;
      case 'on_car':
        return s.onCar;
      case 'cycles':
        return s.cycles;
      case 'hits':
        return s.hits;
      case 'overruns':
        return s.overruns;
      case 'shorts':
        return s.shorts;
      case 'unwarned':
        return s.unwarned;
    }
    throw new Error(`garage has no quantity "${name}"`);
  },
};
