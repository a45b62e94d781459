// The tank (issue 26): a 1,000 L tank filled by a pump through an inlet valve and drawn off by
// the process through a drain valve, with low and high level switches and an analog level.
// Flows are in litres per second of PLC time; valves and the pump take time to move.
import { START_STOP_BUTTONS, sensorSlots } from './points';
import type { Value } from '../model/iecTypes';
import type { PlantConsequence, PlantDrive, PlantModel, PlantPoint, Writable } from './types';

export const TANK_CAPACITY_L = 1000;
/** Where the float switches sit: ON at and above these levels. */
export const LOW_SWITCH_L = 200;
export const HIGH_SWITCH_L = 800;
/** Pump at full speed through a fully open inlet valve. */
export const INFLOW_L_S = 25;
/** The process's draw through a fully open drain valve. */
export const OUTFLOW_L_S = 10;
const VALVE_TRAVEL_MS = 1000;
const SLOW_VALVE_TRAVEL_MS = 15_000;
const PUMP_RAMP_MS = 500;
/** A pump running this long against a closed inlet valve is a consequence (it overheats). */
const DEADHEAD_MS = 3000;
const INITIAL_L = 100;

export interface TankState {
  /** Water in the tank, litres. */
  readonly level: number;
  /** Pump speed, valve openings: 0 to 1. */
  readonly pump: number;
  readonly inlet: number;
  readonly drain: number;
  readonly lamp: boolean;
  /** Water pouring over the rim right now; water asked for by an open drain on an empty tank. */
  readonly overflowing: boolean;
  readonly dry: boolean;
  /** How long the pump has run against the closed inlet valve (reset when it stops or the valve opens). */
  readonly deadheadMs: number;
  readonly overflows: number;
  readonly dryRuns: number;
  readonly deadheads: number;
  /** Litres poured over the rim since the start. */
  readonly spilled: number;
  /** Flows in the last step, litres per second. */
  readonly inflow: number;
  readonly outflow: number;
}

const towards = (from: number, target: number, dtMs: number, travelMs: number): number => {
  // At rest (the usual case): the same as below, without a division.
  if (from === target) return target;
  const delta = dtMs / travelMs;
  return target > from ? Math.min(target, from + delta) : Math.max(target, from - delta);
};
const on = (v: Value | undefined): boolean => v === true;
const NOTHING: readonly PlantConsequence[] = [];

const POINTS: readonly PlantPoint[] = [
  ...START_STOP_BUTTONS,
  {
    name: 'LowLevel',
    address: '%IX0.2',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Low level float switch, ON at 200 L and above',
  },
  {
    name: 'HighLevel',
    address: '%IX0.3',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'High level float switch, ON at 800 L and above',
  },
  {
    name: 'Level',
    address: '%IW0',
    type: 'INT',
    kind: 'sensor',
    comment: 'Level transmitter, litres (0 to 1000)',
  },
  { name: 'Pump', address: '%QX0.0', type: 'BOOL', kind: 'actuator', comment: 'Feed pump contactor' },
  {
    name: 'InletValve',
    address: '%QX0.1',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Inlet valve solenoid (open when ON)',
  },
  {
    name: 'DrainValve',
    address: '%QX0.2',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Drain valve to the process (open when ON)',
  },
  { name: 'RunLamp', address: '%QX0.3', type: 'BOOL', kind: 'actuator', comment: 'Running pilot lamp' },
];
/** Where sense() writes each sensor (the loop's input image order). */
const SENSE = sensorSlots(POINTS, ['LowLevel', 'HighLevel', 'Level']);

export const tank: PlantModel<TankState> = {
  id: 'tank',
  title: 'Tank level control',
  task: [
    'Keep the tank between its level switches while the process draws water from it.',
    'Start (a push button) starts the system, Stop stops it; RunLamp is lit while it runs.',
    'While running, the process draws water through DrainValve whenever the water is at or above',
    'the low switch (LowLevel ON), and never from a tank below it (the process would run dry).',
    'When the water falls below the low switch, run Pump with InletValve open until the high',
    'switch (HighLevel) comes ON, then stop filling. Never run Pump with InletValve closed.',
    'Stopped: Pump off, both valves closed. The tank must never overflow.',
    'Level (%IW0) is the water in litres, 0 to 1000; the switches sit at 200 L and 800 L.',
    'The pump delivers 25 L/s through the open inlet (it takes 0.5 s to run up, a valve 1 s to open),',
    'the process draws 10 L/s: the tank fills by some 15 L/s while the process draws, and empties',
    'by 10 L/s. It starts with 100 L in it.',
  ].join('\n'),
  points: POINTS,
  faults: [
    { id: 'low_stuck_off', title: 'Low level switch stuck OFF' },
    { id: 'low_stuck_on', title: 'Low level switch stuck ON' },
    { id: 'high_stuck_off', title: 'High level switch stuck OFF' },
    { id: 'high_stuck_on', title: 'High level switch stuck ON' },
    { id: 'pump_dead', title: 'Pump motor does not start' },
    { id: 'inlet_slow', title: 'Inlet valve slow (15 s to open or close)' },
    { id: 'drain_stuck', title: 'Drain valve stuck closed' },
  ],
  quantities: [
    { name: 'level', type: 'REAL', unit: 'L', comment: 'Water in the tank' },
    { name: 'percent', type: 'REAL', unit: '%', comment: 'Water in the tank, percent of capacity' },
    { name: 'pump', type: 'REAL', unit: '%', comment: 'Pump speed' },
    { name: 'inlet', type: 'REAL', unit: '%', comment: 'Inlet valve opening' },
    { name: 'drain', type: 'REAL', unit: '%', comment: 'Drain valve opening' },
    { name: 'inflow', type: 'REAL', unit: 'L/s', comment: 'Flow into the tank' },
    { name: 'outflow', type: 'REAL', unit: 'L/s', comment: 'Flow drawn by the process' },
    { name: 'overflowing', type: 'BOOL', comment: 'Water is pouring over the rim' },
    { name: 'dry', type: 'BOOL', comment: 'The drain is open on an empty tank' },
    { name: 'overflows', type: 'INT', comment: 'Times the tank overflowed' },
    { name: 'dry_runs', type: 'INT', comment: 'Times the tank ran dry' },
    { name: 'deadheads', type: 'INT', comment: 'Times the pump ran against the closed inlet valve' },
    { name: 'spilled', type: 'REAL', unit: 'L', comment: 'Water poured over the rim' },
  ],

  initial: () => ({
    level: INITIAL_L,
    pump: 0,
    inlet: 0,
    drain: 0,
    lamp: false,
    overflowing: false,
    dry: false,
    deadheadMs: 0,
    overflows: 0,
    dryRuns: 0,
    deadheads: 0,
    spilled: 0,
    inflow: 0,
    outflow: 0,
  }),

  step(s: TankState, drive: PlantDrive, dtMs: number, faults: ReadonlySet<string>, into: Writable<TankState> = { ...s }): TankState {
    const faulty = faults.size > 0;
    const pump = towards(s.pump, on(drive.Pump) && !(faulty && faults.has('pump_dead')) ? 1 : 0, dtMs, PUMP_RAMP_MS);
    const inlet = towards(
      s.inlet,
      on(drive.InletValve) ? 1 : 0,
      dtMs,
      faulty && faults.has('inlet_slow') ? SLOW_VALVE_TRAVEL_MS : VALVE_TRAVEL_MS,
    );
    const drain = towards(
      s.drain,
      on(drive.DrainValve) && !(faulty && faults.has('drain_stuck')) ? 1 : 0,
      dtMs,
      VALVE_TRAVEL_MS,
    );
    const dt = dtMs / 1000;
    const inflow = INFLOW_L_S * pump * inlet;
    const wanted = OUTFLOW_L_S * drain;
    let level = s.level + inflow * dt;
    // The drain closed (no draw): 0, as the minimum below gives it (the level is never negative), without a division.
    const outflow = wanted === 0 ? 0 : Math.min(wanted, level / (dt || 1));
    level -= outflow * dt;
    let spilled = s.spilled;
    const overflowing = level > TANK_CAPACITY_L;
    if (overflowing) {
      spilled += level - TANK_CAPACITY_L;
      level = TANK_CAPACITY_L;
    }
    const dry = wanted > 0 && level <= 0;
    if (level < 0) level = 0;
    const deadheading = pump > 0.5 && inlet < 0.05;
    const deadheadMs = deadheading ? s.deadheadMs + dtMs : 0;
    into.level = level;
    into.pump = pump;
    into.inlet = inlet;
    into.drain = drain;
    into.lamp = on(drive.RunLamp);
    into.overflowing = overflowing;
    into.dry = dry;
    into.deadheadMs = deadheadMs;
    into.overflows = s.overflows + (overflowing && !s.overflowing ? 1 : 0);
    into.dryRuns = s.dryRuns + (dry && !s.dry ? 1 : 0);
    into.deadheads = s.deadheads + (deadheadMs >= DEADHEAD_MS && s.deadheadMs < DEADHEAD_MS ? 1 : 0);
    into.spilled = spilled;
    into.inflow = inflow;
    into.outflow = dt > 0 ? outflow : 0;
    return into;
  },

  sense(s: TankState, faults: ReadonlySet<string>, out: Value[]): void {
    const low = s.level >= LOW_SWITCH_L;
    const high = s.level >= HIGH_SWITCH_L;
    // No fault set (the usual case): the switches as the water has them.
    if (faults.size === 0) {
      out[SENSE.LowLevel] = low;
      out[SENSE.HighLevel] = high;
      out[SENSE.Level] = Math.round(s.level);
      return;
    }
    out[SENSE.LowLevel] = faults.has('low_stuck_on') ? true : faults.has('low_stuck_off') ? false : low;
    out[SENSE.HighLevel] = faults.has('high_stuck_on') ? true : faults.has('high_stuck_off') ? false : high;
    out[SENSE.Level] = Math.round(s.level);
  },

  check(before: TankState, after: TankState): readonly PlantConsequence[] {
    // Nothing happened (every scan but a handful): no list made.
    if (after.overflows === before.overflows && after.dryRuns === before.dryRuns && after.deadheads === before.deadheads)
      return NOTHING;
    const out: PlantConsequence[] = [];
    if (after.overflows > before.overflows)
      out.push({ id: 'overflow', severity: 'error', message: 'the tank overflowed', counter: 'overflows' });
    if (after.dryRuns > before.dryRuns)
      out.push({
        id: 'dry',
        severity: 'error',
        message: 'the tank ran dry (the drain was open on an empty tank)',
        counter: 'dry_runs',
      });
    if (after.deadheads > before.deadheads)
      out.push({
        id: 'deadhead',
        severity: 'warning',
        message: `the pump ran ${DEADHEAD_MS / 1000} s against the closed inlet valve`,
        counter: 'deadheads',
      });
    return out;
  },

  explain(s: TankState, point: string, faults: ReadonlySet<string>): string | undefined {
    const level = `the level is ${s.level.toFixed(1)} L`;
    const sw = (id: string, title: string, at: number) => {
      if (faults.has(`${id}_stuck_on`)) return `${title} is stuck ON (fault ${id}_stuck_on): it reads ON whatever the level; ${level}`;
      if (faults.has(`${id}_stuck_off`)) return `${title} is stuck OFF (fault ${id}_stuck_off): it reads OFF whatever the level; ${level}`;
      return `${title} is ON at ${at} L and above; ${level}, so it is ${s.level >= at ? 'ON' : 'OFF'}`;
    };
    switch (point) {
      case 'LowLevel':
        return sw('low', 'the low level switch', LOW_SWITCH_L);
      case 'HighLevel':
        return sw('high', 'the high level switch', HIGH_SWITCH_L);
      case 'Level':
        return `the transmitter gives the level in whole litres; ${level}`;
    }
    return undefined;
  },

  quantity(s: TankState, name: string): number | boolean {
    switch (name) {
      case 'level':
        return s.level;
      case 'percent':
        return (s.level / TANK_CAPACITY_L) * 100;
      case 'pump':
        return s.pump * 100;
      case 'inlet':
        return s.inlet * 100;
      case 'drain':
        return s.drain * 100;
      case 'inflow':
        return s.inflow;
      case 'outflow':
        return s.outflow;
      case 'overflowing':
        return s.overflowing;
      case 'dry':
        return s.dry;
      case 'overflows':
        return s.overflows;
      case 'dry_runs':
        return s.dryRuns;
      case 'deadheads':
        return s.deadheads;
      case 'spilled':
        return s.spilled;
    }
    throw new Error(`tank has no quantity "${name}"`);
  },
};
