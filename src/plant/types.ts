// A machine to control (issue 26): pure TypeScript like the engine, no DOM, no React, no Konva,
// no clock of its own and no randomness. docs/PLANTS.md says how to add one.
//
// The program sees a machine only through its I/O points: sensors and operator controls are the
// program's inputs (%IX, %IW), actuators its outputs (%QX, %QW). The machine advances once per
// scan by the scan's PLC time (plant/loop.ts), so a run is exact and reproducible to the scan.
import type { Value } from '../model/iecTypes';

/** What a point is on the machine: the program reads sensors and operator controls, drives actuators. */
export type PointKind = 'sensor' | 'actuator' | 'operator';

/** How an operator control behaves on the drawing: a button is held while pressed, a switch toggles. */
export type OperatorControl = 'button' | 'switch';

export interface PlantPoint {
  /** Name in the machine and the default variable name (a valid IEC identifier). */
  readonly name: string;
  /** Default address: %IX/%IW for sensors and operator controls, %QX/%QW for actuators. */
  readonly address: string;
  readonly type: 'BOOL' | 'INT';
  readonly kind: PointKind;
  /** What the point is, in the words of the machine's electrical drawing (also the variable's comment). */
  readonly comment: string;
  /** Operator points: button (momentary) or switch (maintained). */
  readonly control?: OperatorControl;
}

/** A fault set on purpose (troubleshooting exercises), on from the scan it is set until cleared. */
export interface PlantFault {
  /** Identifier used by scenarios (`fault high_stuck_off` columns) and the panel. */
  readonly id: string;
  readonly title: string;
}

/** A named quantity of the machine's state, readable by scenarios and the watch as `<machine>.<name>`. */
export interface PlantQuantity {
  readonly name: string;
  readonly type: 'BOOL' | 'INT' | 'REAL';
  readonly unit?: string;
  readonly comment: string;
}

/** A consequence the machine suffered (overflow, ran dry, collision): reported where it starts. */
export interface PlantConsequence {
  /** Stable id (`overflow`), counted in the quantity of the same name when the machine has one. */
  readonly id: string;
  readonly severity: 'error' | 'warning';
  /** "tank overflowed": the loop adds where ("at scan 1,204 (12.04 s)"). */
  readonly message: string;
  /**
   * The quantity counting it (`overflows`). A scenario that expects that quantity checks the
   * consequence itself; otherwise the consequence fails the scenario where it happens.
   */
  readonly counter?: string;
}

/**
 * The values the machine sees from outside at one step: each actuator point's value as the
 * program's output image has it, and each operator control as the operator holds it, by point name.
 */
export type PlantDrive = Readonly<Record<string, Value>>;

/** A state's fields writable: what `step` fills (`into`). */
export type Writable<S> = { -readonly [K in keyof S]: S[K] };

/**
 * One machine. `S` is its state: plain, serialisable data (numbers, booleans, strings, and arrays
 * or records that are never changed once made) so a scan's state can be recorded, posted to the
 * page and compared. The loop keeps two state objects and steps from one into the other every scan
 * (no allocation per scan); whoever keeps a state gets a copy (`copyPlantState`).
 */
export interface PlantModel<S = unknown> {
  /** Short lower-case identifier: `# plant: tank`, `--plant tank`, `tank.level`. */
  readonly id: string;
  readonly title: string;
  /** The exercise: goal and rules, plain text (the I/O table is made from `points`). */
  readonly task: string;
  readonly points: readonly PlantPoint[];
  readonly faults: readonly PlantFault[];
  readonly quantities: readonly PlantQuantity[];
  initial(): S;
  /**
   * The state `dtMs` of PLC time after `from`, driven by `drive` the whole time, with `faults`
   * active, written into `into` (every field of it: `into` holds an older state) and returned.
   * Never changes `from` (nor any array or record in it: a new one replaces one that changes).
   * Without `into`, a new object. Pure and deterministic: the same arguments always give the same state.
   */
  step(from: S, drive: PlantDrive, dtMs: number, faults: ReadonlySet<string>, into?: S): S;
  /**
   * The sensors the program reads in this state, written into `out` at their slots: the sensor
   * points in the order of `points` (`sensorSlots`); every sensor every call. Operator points are
   * the loop's. `senseRecord` gives them by name.
   */
  sense(state: S, faults: ReadonlySet<string>, out: Value[]): void;
  /** The consequences that started between `before` and `after` (one step). */
  check(before: S, after: S): readonly PlantConsequence[];
  /** A named quantity (`level`), as a number or boolean. */
  quantity(state: S, name: string): number | boolean;
  /**
   * Optional, for "Why?": why sensor `point` reads what it reads in `state`, in a few words
   * (`ON at 800 L and above; the level is 812.4 L`). Without it "Why?" gives the point's comment
   * and the machine's quantities.
   */
  explain?(state: S, point: string, faults: ReadonlySet<string>): string | undefined;
}
