// The lift (issue 26): a car in a three-floor shaft, hoisted by a motor with an up and a down
// contactor, floor level sensors, a call button and lamp at each landing, and a car door that
// takes time to open and close. Positions are in millimetres above floor 1, speeds in mm/s of
// PLC time. The motor ramps up slowly and brakes fast but not at once: a program that drops the
// contactor late stops off the floor, or runs past the top floor into the buffer.
//
// The passengers are the operator's: a call button press is a passenger waiting at that landing
// until the door stands fully open there (`served`), however the program handles its lamps.
import { sensorSlots } from './points';
import type { Value } from '../model/iecTypes';
import type { PlantConsequence, PlantDrive, PlantModel, PlantPoint, Writable } from './types';

/** Floor levels, mm above floor 1 (floors 1, 2, 3). */
export const FLOOR_MM = [0, 3000, 6000] as const;
export const TOP_MM = FLOOR_MM[2];
/** A floor sensor is ON while the car is within this of the floor's level; a stop farther off is a misstop. */
export const FLOOR_WINDOW_MM = 20;
/** Rated speed, acceleration (0.5 s to full speed) and braking (0.1 s from full speed, 25 mm). */
export const SPEED_MM_S = 500;
export const ACCEL_MM_S2 = 1000;
export const BRAKE_MM_S2 = 5000;
/** Past the top floor or below the bottom one by more than this: an overrun (the final limit). */
export const OVERRUN_MM = 100;
/** The buffers in the pit and under the headroom: hitting one is a crash. */
export const BUFFER_MM = 300;
export const DOOR_MS = 2000;
const SLOW_DOOR_MS = 6000;
/** An obstructed door cannot close past this opening. */
const OBSTRUCTED_OPENING = 0.3;
/** No call pending at a landing. */
const NO_CALL = -1;

export interface LiftState {
  /** Car floor level, mm above floor 1 (the buffers at -300 and 6,300). */
  readonly position: number;
  /** Car speed, mm/s, positive up. */
  readonly speed: number;
  /** Car door opening, 0 (closed) to 1 (fully open). */
  readonly door: number;
  /** The contactors and the door command as the program drives them. */
  readonly motorUp: boolean;
  readonly motorDown: boolean;
  readonly doorCmd: boolean;
  readonly lamp1: boolean;
  readonly lamp2: boolean;
  readonly lamp3: boolean;
  /** When the passenger waiting at each landing pressed the call button (PLC ms), or -1: none waiting. */
  readonly call1: number;
  readonly call2: number;
  readonly call3: number;
  /** Call buttons held in the last step (bit 0: floor 1), to see presses. */
  readonly held: number;
  /** PLC time the car has reached, ms. */
  readonly timeMs: number;
  /** Calls answered (the door stood fully open at the called floor) and the longest wait of those, ms. */
  readonly served: number;
  readonly maxWaitMs: number;
  /** Past the final limit, against a buffer, moving with the door not closed, both contactors on, now. */
  readonly overrunning: boolean;
  readonly crashed: boolean;
  readonly doorMoving: boolean;
  readonly bothOn: boolean;
  readonly overruns: number;
  readonly crashes: number;
  readonly doorMoves: number;
  readonly bothMotors: number;
  /** Stops more than 20 mm off the nearest floor. */
  readonly misstops: number;
  /** Where the car last came to rest: the nearest floor (1..3) and how far above (+) or below (-) it, mm. */
  readonly stopFloor: number;
  readonly stopOffset: number;
}

const on = (v: Value | undefined): boolean => v === true;
const towards = (from: number, target: number, dtMs: number, travelMs: number): number => {
  const delta = dtMs / travelMs;
  return target > from ? Math.min(target, from + delta) : Math.max(target, from - delta);
};

/** The floor (1..3) the car is level with, within the sensors' window, or 0 between floors. */
export function levelFloor(position: number): number {
  for (let i = 0; i < FLOOR_MM.length; i++)
    if (Math.abs(position - FLOOR_MM[i]!) <= FLOOR_WINDOW_MM) return i + 1;
  return 0;
}

/** The floor (1..3) nearest the car. */
export function nearestFloor(position: number): number {
  return Math.min(FLOOR_MM.length, Math.max(1, Math.round(position / (FLOOR_MM[1] - FLOOR_MM[0])) + 1));
}

const mm = (n: number): string => Math.round(Math.abs(n)).toLocaleString('en-US');

/** The car after `move` (module scratch: step() stays allocation-free beyond its new state). */
const car = { x: 0, v: 0 };

/**
 * Car motion over `dt` seconds: brake towards rest when the target is rest or the other way,
 * then accelerate towards the target; exact for the piecewise constant accelerations.
 */
function move(position: number, speed: number, target: number, dt: number): void {
  let x = position;
  let v = speed;
  let t = dt;
  if (v !== 0 && (target === 0 || target > 0 !== v > 0)) {
    const tStop = Math.abs(v) / BRAKE_MM_S2;
    if (tStop > t) {
      const v1 = v - Math.sign(v) * BRAKE_MM_S2 * t;
      car.x = x + ((v + v1) / 2) * t;
      car.v = v1;
      return;
    }
    x += (v / 2) * tStop;
    v = 0;
    t -= tStop;
  }
  if (t > 0 && v !== target) {
    const tUp = Math.abs(target - v) / ACCEL_MM_S2;
    if (tUp > t) {
      const v1 = v + Math.sign(target - v) * ACCEL_MM_S2 * t;
      car.x = x + ((v + v1) / 2) * t;
      car.v = v1;
      return;
    }
    x += ((v + target) / 2) * tUp;
    v = target;
    t -= tUp;
  }
  car.x = x + v * t;
  car.v = v;
}

const CALLS = ['Call1', 'Call2', 'Call3'] as const;
const STUCK_ON = ['floor1_stuck_on', 'floor2_stuck_on', 'floor3_stuck_on'] as const;
const STUCK_OFF = ['floor1_stuck_off', 'floor2_stuck_off', 'floor3_stuck_off'] as const;

/** The passengers' progress in a step (module scratch, like `car`). */
const tally = { served: 0, maxWaitMs: 0 };

/**
 * The passenger at landing `i` (0..2): a press registers a call (`since`, PLC ms); the door
 * standing fully open at that floor (`open`, the floor or 0) answers it. The call after the step.
 */
function passenger(
  call: number,
  i: number,
  pressed: boolean,
  wasHeld: boolean,
  since: number,
  now: number,
  open: number,
): number {
  const c = pressed && !wasHeld && call === NO_CALL ? since : call;
  if (c === NO_CALL || open !== i + 1) return c;
  tally.served++;
  tally.maxWaitMs = Math.max(tally.maxWaitMs, now - c);
  return NO_CALL;
}

const NOTHING: readonly PlantConsequence[] = [];
const POINTS: readonly PlantPoint[] = [
  {
    name: 'Call1',
    address: '%IX0.0',
    type: 'BOOL',
    kind: 'operator',
    control: 'button',
    comment: 'Call button, floor 1 landing (NO)',
  },
  {
    name: 'Call2',
    address: '%IX0.1',
    type: 'BOOL',
    kind: 'operator',
    control: 'button',
    comment: 'Call button, floor 2 landing (NO)',
  },
  {
    name: 'Call3',
    address: '%IX0.2',
    type: 'BOOL',
    kind: 'operator',
    control: 'button',
    comment: 'Call button, floor 3 landing (NO)',
  },
  {
    name: 'AtFloor1',
    address: '%IX0.3',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Floor 1 level sensor, ON within 20 mm of the floor',
  },
  {
    name: 'AtFloor2',
    address: '%IX0.4',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Floor 2 level sensor, ON within 20 mm of the floor',
  },
  {
    name: 'AtFloor3',
    address: '%IX0.5',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Floor 3 level sensor, ON within 20 mm of the floor',
  },
  {
    name: 'DoorClosed',
    address: '%IX0.6',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Car door closed limit switch',
  },
  {
    name: 'DoorOpened',
    address: '%IX0.7',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Car door fully open limit switch',
  },
  {
    name: 'Position',
    address: '%IW0',
    type: 'INT',
    kind: 'sensor',
    comment: 'Shaft encoder, car level in mm above floor 1',
  },
  {
    name: 'MotorUp',
    address: '%QX0.0',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Hoist motor contactor, up',
  },
  {
    name: 'MotorDown',
    address: '%QX0.1',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Hoist motor contactor, down',
  },
  {
    name: 'DoorOpen',
    address: '%QX0.2',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Door operator: open while ON, close while OFF',
  },
  {
    name: 'CallLamp1',
    address: '%QX0.3',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Call registered lamp, floor 1',
  },
  {
    name: 'CallLamp2',
    address: '%QX0.4',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Call registered lamp, floor 2',
  },
  {
    name: 'CallLamp3',
    address: '%QX0.5',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Call registered lamp, floor 3',
  },
];
/** Where sense() writes each sensor (the loop's input image order). */
const SENSE = sensorSlots(POINTS, ['AtFloor1', 'AtFloor2', 'AtFloor3', 'DoorClosed', 'DoorOpened', 'Position']);

export const lift: PlantModel<LiftState> = {
  id: 'lift',
  title: 'Three-floor lift',
  task: [
    'Answer the calls of a three-floor lift. A call button pressed at a landing (Call1..Call3) is',
    'registered and lights its lamp (CallLamp1..3) until the car has come to that floor and its door',
    'stands fully open there. The car goes where it is called and stops at a floor it passes when that',
    'floor is called too; it never runs past the top floor (AtFloor3) or below the bottom one (AtFloor1).',
    'MotorUp and MotorDown drive the hoist (never both at once): 500 mm/s after a 0.5 s ramp. With the',
    'motor off the car brakes to a stop in 0.1 s (25 mm from full speed), so stop it as soon as the',
    'floor sensor of the floor you stop at comes ON (it is ON within 20 mm of the floor): scan at 20 ms',
    'or faster, or the car stops off the floor. Open the door (DoorOpen) only once the car stands still,',
    'keep it open 2 s once fully open (DoorOpened), then close it; the door takes 2 s each way. The car',
    'must never move unless the door is closed (DoorClosed ON and DoorOpen off).',
    'Floors are 3,000 mm apart; Position (%IW0) is the car level in mm above floor 1.',
  ].join('\n'),
  points: POINTS,
  faults: [
    { id: 'floor2_stuck_off', title: 'Floor 2 sensor stuck OFF' },
    { id: 'floor2_stuck_on', title: 'Floor 2 sensor stuck ON' },
    { id: 'floor3_stuck_off', title: 'Floor 3 (top) sensor stuck OFF' },
    { id: 'motor_dead', title: 'Hoist motor does not start' },
    { id: 'door_slow', title: 'Door slow (6 s to open or close)' },
    { id: 'door_obstructed', title: 'Door obstructed (cannot close)' },
  ],
  quantities: [
    { name: 'position', type: 'REAL', unit: 'mm', comment: 'Car level above floor 1' },
    { name: 'speed', type: 'REAL', unit: 'mm/s', comment: 'Car speed, positive up' },
    {
      name: 'floor',
      type: 'INT',
      comment: 'The floor the car is level with (within 20 mm), 0 between floors',
    },
    { name: 'door', type: 'REAL', unit: '%', comment: 'Car door opening' },
    { name: 'served', type: 'INT', comment: 'Calls answered: the door stood fully open at the called floor' },
    { name: 'waiting', type: 'INT', comment: 'Calls pressed and not answered yet' },
    {
      name: 'max_wait',
      type: 'REAL',
      unit: 's',
      comment: 'Longest wait for the car, answered or still waiting',
    },
    {
      name: 'overruns',
      type: 'INT',
      comment: 'Times the car ran 100 mm past the top floor or below the bottom floor',
    },
    { name: 'crashes', type: 'INT', comment: 'Times the car hit a buffer' },
    { name: 'door_moves', type: 'INT', comment: 'Times the car moved with the door not closed' },
    { name: 'both_motors', type: 'INT', comment: 'Times both motor contactors were on' },
    { name: 'misstops', type: 'INT', comment: 'Stops more than 20 mm off the nearest floor' },
  ],

  initial: () => ({
    position: 0,
    speed: 0,
    door: 0,
    motorUp: false,
    motorDown: false,
    doorCmd: false,
    lamp1: false,
    lamp2: false,
    lamp3: false,
    call1: NO_CALL,
    call2: NO_CALL,
    call3: NO_CALL,
    held: 0,
    timeMs: 0,
    served: 0,
    maxWaitMs: 0,
    overrunning: false,
    crashed: false,
    doorMoving: false,
    bothOn: false,
    overruns: 0,
    crashes: 0,
    doorMoves: 0,
    bothMotors: 0,
    misstops: 0,
    stopFloor: 1,
    stopOffset: 0,
  }),

  step(s: LiftState, drive: PlantDrive, dtMs: number, faults: ReadonlySet<string>, into: Writable<LiftState> = { ...s }): LiftState {
    const up = on(drive.MotorUp);
    const down = on(drive.MotorDown);
    const bothOn = up && down;
    // Both contactors on: the motor trips (no torque) and the car brakes.
    const target = bothOn || faults.has('motor_dead') ? 0 : up ? SPEED_MM_S : down ? -SPEED_MM_S : 0;
    move(s.position, s.speed, target, dtMs / 1000);
    let position = car.x;
    let speed = car.v;
    const crashed = position >= TOP_MM + BUFFER_MM || position <= -BUFFER_MM;
    if (crashed) {
      position = position > 0 ? TOP_MM + BUFFER_MM : -BUFFER_MM;
      speed = 0;
    }
    const doorCmd = on(drive.DoorOpen);
    const closedAt = faults.has('door_obstructed') && s.door > 0 ? Math.min(s.door, OBSTRUCTED_OPENING) : 0;
    const door = towards(
      s.door,
      doorCmd ? 1 : closedAt,
      dtMs,
      faults.has('door_slow') ? SLOW_DOOR_MS : DOOR_MS,
    );
    const moving = speed !== 0 || position !== s.position;
    const doorMoving = moving && (door > 0 || s.door > 0);
    const overrunning = position > TOP_MM + OVERRUN_MM || position < -OVERRUN_MM;
    // Came to rest (not against a buffer): where, against the nearest floor.
    let { stopFloor, stopOffset, misstops } = s;
    if (s.speed !== 0 && speed === 0 && !crashed) {
      stopFloor = nearestFloor(position);
      stopOffset = position - FLOOR_MM[stopFloor - 1]!;
      if (Math.abs(stopOffset) > FLOOR_WINDOW_MM) misstops++;
    }
    // The passengers: a press registers a call; the door standing fully open at the floor answers it.
    const timeMs = s.timeMs + dtMs;
    const open = door >= 1 && speed === 0 ? levelFloor(position) : 0;
    tally.served = s.served;
    tally.maxWaitMs = s.maxWaitMs;
    let held = 0;
    for (let i = 0; i < 3; i++) if (on(drive[CALLS[i]!])) held |= 1 << i;
    const call1 = passenger(s.call1, 0, (held & 1) !== 0, (s.held & 1) !== 0, s.timeMs, timeMs, open);
    const call2 = passenger(s.call2, 1, (held & 2) !== 0, (s.held & 2) !== 0, s.timeMs, timeMs, open);
    const call3 = passenger(s.call3, 2, (held & 4) !== 0, (s.held & 4) !== 0, s.timeMs, timeMs, open);
    into.position = position;
    into.speed = speed;
    into.door = door;
    into.motorUp = up;
    into.motorDown = down;
    into.doorCmd = doorCmd;
    into.lamp1 = on(drive.CallLamp1);
    into.lamp2 = on(drive.CallLamp2);
    into.lamp3 = on(drive.CallLamp3);
    into.call1 = call1;
    into.call2 = call2;
    into.call3 = call3;
    into.held = held;
    into.timeMs = timeMs;
    into.served = tally.served;
    into.maxWaitMs = tally.maxWaitMs;
    into.overrunning = overrunning;
    into.crashed = crashed;
    into.doorMoving = doorMoving;
    into.bothOn = bothOn;
    into.overruns = s.overruns + (overrunning && !s.overrunning ? 1 : 0);
    into.crashes = s.crashes + (crashed && !s.crashed ? 1 : 0);
    into.doorMoves = s.doorMoves + (doorMoving && !s.doorMoving ? 1 : 0);
    into.bothMotors = s.bothMotors + (bothOn && !s.bothOn ? 1 : 0);
    into.misstops = misstops;
    into.stopFloor = stopFloor;
    into.stopOffset = stopOffset;
    return into;
  },

  sense(s: LiftState, faults: ReadonlySet<string>, out: Value[]): void {
    // No fault set (the usual case): no fault looked up.
    const any = faults.size > 0;
    const at = (i: number): boolean =>
      any && faults.has(STUCK_ON[i]!)
        ? true
        : any && faults.has(STUCK_OFF[i]!)
          ? false
          : Math.abs(s.position - FLOOR_MM[i]!) <= FLOOR_WINDOW_MM;
    out[SENSE.AtFloor1] = at(0);
    out[SENSE.AtFloor2] = at(1);
    out[SENSE.AtFloor3] = at(2);
    out[SENSE.DoorClosed] = s.door <= 0;
    out[SENSE.DoorOpened] = s.door >= 1;
    out[SENSE.Position] = Math.round(s.position);
  },

  explain(s: LiftState, point: string, faults: ReadonlySet<string>): string | undefined {
    const mm = (v: number) => `${v.toLocaleString('en-US', { minimumFractionDigits: 1, maximumFractionDigits: 1 })} mm`;
    const car = `the car is at ${mm(s.position)}`;
    const door = `the door is ${(s.door * 100).toFixed(1)} % open`;
    const floor = /^AtFloor([123])$/.exec(point);
    if (floor) {
      const i = Number(floor[1]) - 1;
      const level = FLOOR_MM[i]!;
      const title = `the floor ${i + 1} sensor`;
      if (faults.has(STUCK_ON[i]!)) return `${title} is stuck ON (fault ${STUCK_ON[i]}): it reads ON wherever the car is; ${car}`;
      if (faults.has(STUCK_OFF[i]!)) return `${title} is stuck OFF (fault ${STUCK_OFF[i]}): it reads OFF wherever the car is; ${car}`;
      const off = Math.abs(s.position - level);
      return `${title} is ON within ${FLOOR_WINDOW_MM} mm of floor ${i + 1} (${level.toLocaleString('en-US')} mm); ${car}, ${mm(off)} ${s.position >= level ? 'above' : 'below'} it, so it is ${off <= FLOOR_WINDOW_MM ? 'ON' : 'OFF'}`;
    }
    switch (point) {
      case 'DoorClosed':
        return `the closed limit switch is ON only with the door fully closed; ${door}, so it is ${s.door <= 0 ? 'ON' : 'OFF'}`;
      case 'DoorOpened':
        return `the fully open limit switch is ON only with the door fully open; ${door}, so it is ${s.door >= 1 ? 'ON' : 'OFF'}`;
      case 'Position':
        return `the shaft encoder gives the car level in whole millimetres above floor 1; ${car}`;
    }
    return undefined;
  },

  check(before: LiftState, after: LiftState): readonly PlantConsequence[] {
    // Nothing started (every scan but a handful): no list made.
    let out: PlantConsequence[] | undefined;
    const top = after.position > TOP_MM / 2;
    if (after.bothMotors > before.bothMotors)
      (out ??= []).push({
        id: 'both_motors',
        severity: 'error',
        message: 'MotorUp and MotorDown were on together (the motor tripped)',
        counter: 'both_motors',
      });
    if (after.doorMoves > before.doorMoves)
      (out ??= []).push({
        id: 'door_move',
        severity: 'error',
        message: `the car moved with the door ${Math.round(Math.max(after.door, before.door) * 100)} % open`,
        counter: 'door_moves',
      });
    if (after.overruns > before.overruns)
      (out ??= []).push({
        id: 'overrun',
        severity: 'error',
        message: top
          ? `the car ran ${OVERRUN_MM} mm past the top floor (floor 3)`
          : `the car ran ${OVERRUN_MM} mm below the bottom floor (floor 1)`,
        counter: 'overruns',
      });
    if (after.crashes > before.crashes)
      (out ??= []).push({
        id: 'crash',
        severity: 'error',
        message: top
          ? 'the car crashed into the buffer above floor 3'
          : 'the car crashed into the buffer in the pit',
        counter: 'crashes',
      });
    if (after.misstops > before.misstops)
      (out ??= []).push({
        id: 'misstop',
        severity: 'warning',
        message: `the car stopped ${mm(after.stopOffset)} mm ${after.stopOffset > 0 ? 'above' : 'below'} floor ${after.stopFloor}`,
        counter: 'misstops',
      });
    return out ?? NOTHING;
  },

  quantity(s: LiftState, name: string): number | boolean {
    switch (name) {
      case 'position':
        return s.position;
      case 'speed':
        return s.speed;
      case 'floor':
        return levelFloor(s.position);
      case 'door':
        return s.door * 100;
      case 'served':
        return s.served;
      case 'waiting':
        return (s.call1 !== NO_CALL ? 1 : 0) + (s.call2 !== NO_CALL ? 1 : 0) + (s.call3 !== NO_CALL ? 1 : 0);
      case 'max_wait': {
        let w = s.maxWaitMs;
        if (s.call1 !== NO_CALL) w = Math.max(w, s.timeMs - s.call1);
        if (s.call2 !== NO_CALL) w = Math.max(w, s.timeMs - s.call2);
        if (s.call3 !== NO_CALL) w = Math.max(w, s.timeMs - s.call3);
        return w / 1000;
      }
      case 'overruns':
        return s.overruns;
      case 'crashes':
        return s.crashes;
      case 'door_moves':
        return s.doorMoves;
      case 'both_motors':
        return s.bothMotors;
      case 'misstops':
        return s.misstops;
    }
    throw new Error(`lift has no quantity "${name}"`);
  },
};
