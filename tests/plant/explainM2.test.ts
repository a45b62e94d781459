// "Why?" on a sensor of the box sorter, the garage door and the lift explains it through the
// machine (issue 26): which box breaks which photo-eye, where the door stands against its limit
// switches and whether a car is in the beam, where the car is against the floor sensor's window,
// and a stuck fault by name. Without it "Why?" gave only the point's comment and the counters
// (the box sorter's say nothing of where the boxes are).
import { describe, expect, test } from 'vitest';
import { boxes, type BoxesState } from '../../src/plant/boxes';
import { garage, type GarageState } from '../../src/plant/garage';
import { lift, type LiftState } from '../../src/plant/lift';
import { senseRecord } from '../../src/plant/points';
import type { PlantDrive, PlantModel } from '../../src/plant/types';

const NONE = new Set<string>();

/** Steps `model` from its initial state by `dtMs` with the drive `drive` gives, calling `each` after every step. */
function drive<S>(model: PlantModel<S>, steps: number, dtMs: number, drive: (s: S, sensed: Record<string, unknown>) => PlantDrive, each: (s: S) => void): S {
  let s = model.initial();
  for (let i = 0; i < steps; i++) {
    s = model.step(s, drive(s, senseRecord(model, s, NONE)), dtMs, NONE, { ...s });
    each(s);
  }
  return s;
}

/** Every sensor's explanation ends in what it reads, as sense() has it. */
function agrees<S>(model: PlantModel<S>, s: S): void {
  const sensed = senseRecord(model, s, NONE);
  for (const p of model.points) {
    if (p.kind !== 'sensor' || p.type !== 'BOOL') continue;
    const text = model.explain!(s, p.name, NONE);
    expect(text, p.name).toMatch(new RegExp(`so it is ${sensed[p.name] ? 'ON' : 'OFF'}$`));
  }
}

describe('"Why?" on the box sorter\'s sensors names the boxes and where they are', () => {
  test('which box breaks a photo-eye, a small box under the high size sensor, the pusher against its limits', () => {
    let seen = 0;
    drive<BoxesState>(boxes, 1500, 20, (_, i) => ({ Conveyor: true, Pusher: i.PusherEye === true }), (s) => {
      agrees(boxes, s);
      seen++;
    });
    expect(seen).toBe(1500);
    // Box 1 (small) under the size sensor: there, but too low to break the beam.
    const at = drive<BoxesState>(boxes, 120, 20, () => ({ Conveyor: true }), () => {});
    const box1 = at.belt + at.boxes[0]!.base;
    expect(box1).toBeGreaterThanOrEqual(800);
    expect(box1 - 300).toBeLessThanOrEqual(800);
    expect(boxes.explain!(at, 'SizeEye', NONE)).toBe(
      `the size sensor, a high photo-eye, at 0.80 m is ON while a large box breaks its beam; box 1 (small) is in front of it, its front edge at ${(box1 / 1000).toFixed(2)} m, too low to break the high beam, so it is OFF`,
    );
    expect(boxes.explain!(at, 'PusherEye', NONE)).toBe(
      `the photo-eye at the pusher at 2.08 m is ON while a box breaks its beam; no box is in front of it (the next box's front edge is at ${(box1 / 1000).toFixed(2)} m), so it is OFF`,
    );
    expect(boxes.explain!(at, 'PusherIn', NONE)).toBe('the in limit switch is ON at 2 % out and under; the pusher is 0.0 % out, so it is ON');
    expect(boxes.explain!(at, 'SizeEye', new Set(['size_stuck_on']))).toBe(
      'the size sensor is stuck ON (fault size_stuck_on): it reads ON whatever is on the belt',
    );
  });
});

describe('"Why?" on the garage door\'s sensors', () => {
  test('the limit switches against the door\'s opening, the photo-eye against the car, a stuck switch by name', () => {
    const opening = drive<GarageState>(garage, 60, 100, () => ({ MotorUp: true, WarningLamp: true }), (s) => agrees(garage, s));
    expect(garage.explain!(opening, 'OpenLimit', NONE)).toBe(
      `the open limit switch is ON at 99 % open and above; the door is ${opening.position.toFixed(1)} % open, so it is OFF`,
    );
    expect(garage.explain!(opening, 'ClosedLimit', new Set(['closed_stuck_on']))).toBe(
      `the closed limit switch is stuck ON (fault closed_stuck_on): it reads ON wherever the door is; the door is ${opening.position.toFixed(1)} % open`,
    );
    // A car waiting outside a door too low for it; then in, with the door open.
    const waiting = garage.step(garage.initial(), { Doorway: true }, 100, NONE);
    expect(garage.explain!(waiting, 'Obstacle', NONE)).toBe(
      'the photo-eye is ON while something breaks its beam; a car waits outside: it drives in only under a door open above 60 %, and the door is 0.0 % open, so it is OFF',
    );
    const open = drive<GarageState>(garage, 200, 100, () => ({ MotorUp: true, WarningLamp: true, Doorway: true }), (s) => agrees(garage, s));
    expect(garage.explain!(open, 'Obstacle', NONE)).toBe(
      'the photo-eye is ON while something breaks its beam; a car is in the doorway, in the beam, so it is ON',
    );
    expect(garage.explain!(open, 'Obstacle', new Set(['eye_stuck_off']))).toBe(
      'the photo-eye is stuck OFF (fault eye_stuck_off): it reads OFF whatever is in the doorway; a car is in the doorway, in the beam',
    );
  });
});

describe('"Why?" on the lift\'s sensors', () => {
  test('a floor sensor against the car\'s level, the door switches against its opening, a stuck sensor by name', () => {
    // Up from floor 1 until the floor 2 sensor comes ON, then stop.
    const s = drive<LiftState>(lift, 400, 20, (_, i) => ({ MotorUp: i.AtFloor2 !== true }), (x) => agrees(lift, x));
    expect(s.speed).toBe(0);
    const off = s.position - 3000;
    expect(Math.abs(off)).toBeLessThanOrEqual(20);
    expect(lift.explain!(s, 'AtFloor2', NONE)).toBe(
      `the floor 2 sensor is ON within 20 mm of floor 2 (3,000 mm); the car is at ${s.position.toLocaleString('en-US', { minimumFractionDigits: 1, maximumFractionDigits: 1 })} mm, ${Math.abs(off).toFixed(1)} mm ${off >= 0 ? 'above' : 'below'} it, so it is ON`,
    );
    expect(lift.explain!(s, 'AtFloor1', NONE)).toMatch(/^the floor 1 sensor is ON within 20 mm of floor 1 \(0 mm\); the car is at 3,0\d\d\.\d mm, 3,0\d\d\.\d mm above it, so it is OFF$/);
    expect(lift.explain!(s, 'AtFloor2', new Set(['floor2_stuck_off']))).toMatch(
      /^the floor 2 sensor is stuck OFF \(fault floor2_stuck_off\): it reads OFF wherever the car is; the car is at 3,0\d\d\.\d mm$/,
    );
    expect(lift.explain!(s, 'DoorClosed', NONE)).toBe('the closed limit switch is ON only with the door fully closed; the door is 0.0 % open, so it is ON');
    const opening = lift.step(s, { DoorOpen: true }, 500, NONE);
    expect(lift.explain!(opening, 'DoorOpened', NONE)).toBe('the fully open limit switch is ON only with the door fully open; the door is 25.0 % open, so it is OFF');
    expect(lift.explain!(s, 'Position', NONE)).toMatch(/^the shaft encoder gives the car level in whole millimetres above floor 1; the car is at 3,0\d\d\.\d mm$/);
  });
});
