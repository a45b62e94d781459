// The batch mixer (issue 26): a 1,000 L vessel dosed with two ingredients through valves A and B,
// stirred by an agitator, heated by an immersion heater at its bottom and emptied through an
// outlet valve. Level switches (low: the heater is covered, mid: ingredient A's dose, high: the
// batch is full), an analog level and an analog temperature in tenths of a degree.
//
// The heat goes from the heater into a small zone of liquid around its element (the "element"
// temperature) and from there into the batch: quickly with the agitator running, hardly at all
// without it, so heating without the agitator scorches the product on the element. The batch
// loses heat to the 20 °C room. A batch is judged when the outlet opens: the ratio of A to B, how
// long it was held hot with the agitator after the last ingredient went in, whether it overheated
// or scorched. A good batch counts once the vessel is empty.
import { START_STOP_BUTTONS, sensorSlots } from './points';
import type { Value } from '../model/iecTypes';
import type { PlantConsequence, PlantDrive, PlantModel, PlantPoint, Writable } from './types';

export const MIXER_CAPACITY_L = 1000;
/** Where the level switches sit: ON at and above these levels. */
export const LOW_SWITCH_L = 100;
export const MID_SWITCH_L = 400;
export const HIGH_SWITCH_L = 800;
/** The heater's element is under liquid from this level up. */
export const ELEMENT_COVERED_L = 60;
/** Fully open valves: litres per second. */
export const FLOW_A_L_S = 40;
export const FLOW_B_L_S = 40;
export const OUTLET_L_S = 50;
export const AMBIENT_C = 20;
/** The recipe: hold at the set point (held counts from HOLD_MIN_C) for HOLD_S with the agitator running. */
export const SETPOINT_C = 60;
export const HOLD_MIN_C = 57;
export const HOLD_S = 30;
/** A batch above this is spoiled; the product on the element scorches above SCORCH_C. */
export const OVERHEAT_C = 80;
export const SCORCH_C = 150;
/** An element heating in the air burns out at this temperature (some 20 s dry): it never heats again until the machine is reset. */
export const BURNOUT_C = 350;
/** The share of A in a good batch, percent, and its least volume. */
export const RATIO_MIN = 40;
export const RATIO_MAX = 60;
export const MIN_BATCH_L = 700;

const VALVE_TRAVEL_MS = 1000;
const SLOW_VALVE_TRAVEL_MS = 15_000;
const AGITATOR_RAMP_MS = 2000;
/** The heater's power, as degrees times litres per second (1,000: 1.25 °C/s into 800 L). */
const HEATER_POWER = 1000;
/** The liquid around the element, litres, and how fast it mixes with the batch (per second). */
const ZONE_L = 40;
const MIX_STILL = 0.05;
const MIX_STIRRED = 3;
/** Heat lost to the room, per second, per degree above it. */
const LOSS = 0.005;
/** The longest integration step (ms): a step of a longer cycle is cut into these. */
const MAX_STEP_MS = 50;

/** Why the last spoiled batch was spoiled. */
export type SpoilReason = '' | 'overheat' | 'scorch' | 'ratio' | 'unheld' | 'short';

export interface MixerState {
  /** Liquid in the vessel, litres, and how much of it is ingredient A and B. */
  readonly level: number;
  readonly volA: number;
  readonly volB: number;
  /** The batch's temperature and the element zone's, °C. */
  readonly temp: number;
  readonly element: number;
  /** What the temperature transmitter shows, °C (frozen by the `temp_frozen` fault). */
  readonly shownTemp: number;
  /** Valve openings and agitator speed: 0 to 1. */
  readonly valveA: number;
  readonly valveB: number;
  readonly outlet: number;
  readonly agitator: number;
  /** The program orders the outlet open (a discharge starts when it does). */
  readonly outletOrdered: boolean;
  /** The agitator's blades, degrees (drawn turning). */
  readonly angle: number;
  /** The heater's element carries current (and is not burnt). */
  readonly heating: boolean;
  /** The element burnt out, heated uncovered past BURNOUT_C: it heats no more (a new one comes with a reset). */
  readonly burntOut: boolean;
  readonly lamp: boolean;
  /** The batch now in the vessel: time held hot and stirred since the last ingredient, hottest it was. */
  readonly heldMs: number;
  readonly maxTemp: number;
  /** Judged when the outlet opened; spoiled (and counted) at most once. */
  readonly judged: boolean;
  readonly spoiledBatch: boolean;
  readonly spoilReason: SpoilReason;
  /** The share of A of the last batch judged (percent). */
  readonly lastRatio: number;
  readonly overflowing: boolean;
  readonly dryHeating: boolean;
  readonly scorching: boolean;
  readonly batches: number;
  readonly spoiled: number;
  readonly overflows: number;
  readonly scorches: number;
  readonly dryHeats: number;
  /** Times the next batch was dosed onto what was left of the last one (its discharge closed early), and how much was left the last time, litres. */
  readonly heels: number;
  readonly heelL: number;
  /** Flows in the last step, litres per second. */
  readonly inflow: number;
  readonly outflow: number;
}

const towards = (from: number, target: number, dtMs: number, travelMs: number): number => {
  const delta = dtMs / travelMs;
  return target > from ? Math.min(target, from + delta) : Math.max(target, from - delta);
};
const on = (v: Value | undefined): boolean => v === true;

/** The share of A in what the vessel holds, percent (0 when empty). */
export function ratioOf(s: Pick<MixerState, 'volA' | 'volB'>): number {
  const total = s.volA + s.volB;
  return total > 0 ? (s.volA / total) * 100 : 0;
}

/** What is wrong with a batch being discharged, or '' for a good one. */
function verdict(s: { volA: number; volB: number; heldMs: number }): SpoilReason {
  const ratio = ratioOf(s);
  if (s.volA + s.volB < MIN_BATCH_L) return 'short';
  if (ratio < RATIO_MIN || ratio > RATIO_MAX) return 'ratio';
  if (s.heldMs < HOLD_S * 1000) return 'unheld';
  return '';
}

/** Why a batch was spoiled, with what it was (the held time, the ratio), as a consequence's message. */
function spoilText(s: MixerState): string {
  switch (s.spoilReason) {
    case 'overheat':
      return `a batch overheated above ${OVERHEAT_C} °C and is spoiled`;
    case 'ratio':
      return `a batch was discharged with A ${s.lastRatio.toFixed(0)} % of it (it must be ${RATIO_MIN} to ${RATIO_MAX} %) and is spoiled`;
    case 'unheld':
      return `a batch was discharged held only ${(Math.floor(s.heldMs / 100) / 10).toFixed(1)} s at ${HOLD_MIN_C} °C or above with the agitator running (it must be held ${HOLD_S} s at ${SETPOINT_C} °C) and is spoiled`;
    default:
      return `a batch was discharged short (less than ${MIN_BATCH_L} L) and is spoiled`;
  }
}

const NOTHING: readonly PlantConsequence[] = [];
const POINTS: readonly PlantPoint[] = [
  ...START_STOP_BUTTONS,
  {
    name: 'LowLevel',
    address: '%IX0.2',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Low level switch, ON at 100 L and above (heater covered)',
  },
  {
    name: 'MidLevel',
    address: '%IX0.3',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Mid level switch, ON at 400 L and above (dose of A)',
  },
  {
    name: 'HighLevel',
    address: '%IX0.4',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'High level switch, ON at 800 L and above (batch full)',
  },
  {
    name: 'AgitatorOn',
    address: '%IX0.5',
    type: 'BOOL',
    kind: 'sensor',
    comment: 'Agitator speed monitor, ON from 90 % of full speed (the motor runs up in 2 s)',
  },
  {
    name: 'Level',
    address: '%IW0',
    type: 'INT',
    kind: 'sensor',
    comment: 'Level transmitter, litres (0 to 1000)',
  },
  {
    name: 'Temperature',
    address: '%IW1',
    type: 'INT',
    kind: 'sensor',
    comment: 'Temperature transmitter, 0.1 °C (600 = 60.0 °C)',
  },
  {
    name: 'ValveA',
    address: '%QX0.0',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Ingredient A valve solenoid (open when ON)',
  },
  {
    name: 'ValveB',
    address: '%QX0.1',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Ingredient B valve solenoid (open when ON)',
  },
  {
    name: 'Agitator',
    address: '%QX0.2',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Agitator motor contactor',
  },
  {
    name: 'Heater',
    address: '%QX0.3',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Immersion heater contactor',
  },
  {
    name: 'OutletValve',
    address: '%QX0.4',
    type: 'BOOL',
    kind: 'actuator',
    comment: 'Outlet valve solenoid (open when ON)',
  },
  { name: 'DoneLamp', address: '%QX0.5', type: 'BOOL', kind: 'actuator', comment: 'Batch done pilot lamp' },
];
/** Where sense() writes each sensor (the loop's input image order). */
const SENSE = sensorSlots(POINTS, ['LowLevel', 'MidLevel', 'HighLevel', 'AgitatorOn', 'Level', 'Temperature']);

export const mixer: PlantModel<MixerState> = {
  id: 'mixer',
  title: 'Batch mixer',
  task: [
    'Make batches: dose ingredient A, then B, stir and heat, hold, discharge; three good batches.',
    'Start (a push button) starts production, Stop pauses it (valves closed, heater and agitator off;',
    'Start goes on with the same batch). Each batch, from an empty vessel:',
    '1. open ValveA until MidLevel comes ON (400 L), then close it;',
    '2. open ValveB until HighLevel comes ON (800 L), then close it;',
    '3. run the Agitator; with the agitator running (AgitatorOn) and the heater covered (LowLevel),',
    `   heat (Heater) to ${SETPOINT_C} °C (Temperature is in tenths of a degree: ${SETPOINT_C * 10});`,
    `4. hold the batch at ${SETPOINT_C} °C (${HOLD_MIN_C} °C or above counts) with the agitator running for ${HOLD_S} s;`,
    '5. heater and agitator off, open OutletValve until the vessel is empty (a few seconds after',
    '   LowLevel goes OFF), then close it; DoneLamp is lit while a finished batch is discharged.',
    'Then start the next batch. The vessel must never overflow. Never heat an uncovered element',
    '(it burns out) or without the agitator (the product scorches on the element). A batch above',
    `${OVERHEAT_C} °C, discharged before it was held, or with A outside ${RATIO_MIN} to ${RATIO_MAX} % is spoiled.`,
    'Level (%IW0) is in litres, 0 to 1000. Valves A and B let in 40 L/s each, the outlet 50 L/s. The',
    'process runs faster than a real one: the heater warms a full, stirred batch by about 1 °C a',
    'second (20 to 60 °C in some 40 s); with the heater off the batch loses heat to the 20 °C room,',
    'about 0.15 °C a second at 60 °C, so keep it there with a thermostat. Heated without the',
    'agitator the product scorches within some 6 s; an uncovered element burns out within some 20 s.',
  ].join('\n'),
  points: POINTS,
  faults: [
    { id: 'low_stuck_on', title: 'Low level switch stuck ON' },
    { id: 'mid_stuck_off', title: 'Mid level switch stuck OFF' },
    { id: 'high_stuck_off', title: 'High level switch stuck OFF' },
    { id: 'valve_a_slow', title: 'Valve A slow (15 s to open or close)' },
    { id: 'agitator_dead', title: 'Agitator motor does not start' },
    { id: 'heater_dead', title: 'Heater does not heat (element open circuit)' },
    { id: 'temp_frozen', title: 'Temperature transmitter frozen' },
  ],
  quantities: [
    { name: 'temperature', type: 'REAL', unit: '°C', comment: 'Temperature of the batch' },
    { name: 'element', type: 'REAL', unit: '°C', comment: 'Temperature at the heater element' },
    { name: 'level', type: 'REAL', unit: 'L', comment: 'Liquid in the vessel' },
    {
      name: 'ratio',
      type: 'REAL',
      unit: '%',
      comment: 'Share of ingredient A in the vessel (the last batch judged, when empty)',
    },
    {
      name: 'held',
      type: 'REAL',
      unit: 's',
      comment: 'Time the batch was held at 57 °C or above with the agitator at speed, since the last ingredient',
    },
    { name: 'max_temp', type: 'REAL', unit: '°C', comment: 'Hottest the batch in the vessel was' },
    { name: 'valve_a', type: 'REAL', unit: '%', comment: 'Valve A opening' },
    { name: 'valve_b', type: 'REAL', unit: '%', comment: 'Valve B opening' },
    { name: 'outlet', type: 'REAL', unit: '%', comment: 'Outlet valve opening' },
    { name: 'agitator', type: 'REAL', unit: '%', comment: 'Agitator speed' },
    { name: 'heating', type: 'BOOL', comment: 'The heater heats' },
    { name: 'overflowing', type: 'BOOL', comment: 'Liquid is pouring over the rim' },
    { name: 'batches', type: 'INT', comment: 'Good batches discharged' },
    { name: 'spoiled', type: 'INT', comment: 'Batches spoiled' },
    { name: 'overflows', type: 'INT', comment: 'Times the vessel overflowed' },
    { name: 'scorches', type: 'INT', comment: 'Times the product scorched on the heater' },
    { name: 'dry_heats', type: 'INT', comment: 'Times the heater ran dry (element not covered)' },
    {
      name: 'heels',
      type: 'INT',
      comment: 'Times the next batch was dosed onto what was left of the last one (outlet closed before the vessel was empty)',
    },
    { name: 'burnt_out', type: 'BOOL', comment: 'The heater element burnt out (heated uncovered): it heats no more until a reset' },
  ],

  initial: () => ({
    level: 0,
    volA: 0,
    volB: 0,
    temp: AMBIENT_C,
    element: AMBIENT_C,
    shownTemp: AMBIENT_C,
    valveA: 0,
    valveB: 0,
    outlet: 0,
    agitator: 0,
    outletOrdered: false,
    angle: 0,
    heating: false,
    lamp: false,
    heldMs: 0,
    maxTemp: AMBIENT_C,
    judged: false,
    spoiledBatch: false,
    spoilReason: '',
    lastRatio: 0,
    overflowing: false,
    dryHeating: false,
    scorching: false,
    batches: 0,
    spoiled: 0,
    overflows: 0,
    scorches: 0,
    dryHeats: 0,
    heels: 0,
    heelL: 0,
    burntOut: false,
    inflow: 0,
    outflow: 0,
  }),

  step(s: MixerState, drive: PlantDrive, dtMs: number, faults: ReadonlySet<string>, into: Writable<MixerState> = { ...s }): MixerState {
    const wantA = on(drive.ValveA) ? 1 : 0;
    const wantB = on(drive.ValveB) ? 1 : 0;
    const wantOut = on(drive.OutletValve) ? 1 : 0;
    const wantAgitator = on(drive.Agitator) && !faults.has('agitator_dead') ? 1 : 0;
    const ordered = on(drive.Heater) && !faults.has('heater_dead');
    let burntOut = s.burntOut;
    let heating = ordered && !burntOut;
    const travelA = faults.has('valve_a_slow') ? SLOW_VALVE_TRAVEL_MS : VALVE_TRAVEL_MS;
    let { level, volA, volB, temp, element, valveA, valveB, outlet, agitator, heldMs, maxTemp, angle } = s;
    let { judged, spoiledBatch, spoilReason, lastRatio, batches, spoiled, overflows, scorches, dryHeats, heels, heelL } = s;
    let overflowing = false;
    let dryHeating = false;
    let scorching = false;
    let inflowL = 0;
    let outflowL = 0;
    // The outlet ordered open on a vessel with a batch in it: the batch is discharged, judged now.
    if (wantOut === 1 && !s.outletOrdered && level > 0 && !judged) {
      judged = true;
      lastRatio = ratioOf(s);
      const reason = verdict(s);
      if (reason && !spoiledBatch) {
        spoiledBatch = true;
        spoilReason = reason;
        spoiled++;
      }
    }
    const n = Math.max(1, Math.ceil(dtMs / MAX_STEP_MS));
    const hMs = dtMs / n;
    const h = hMs / 1000;
    for (let i = 0; i < n; i++) {
      valveA = towards(valveA, wantA, hMs, travelA);
      valveB = towards(valveB, wantB, hMs, VALVE_TRAVEL_MS);
      outlet = towards(outlet, wantOut, hMs, VALVE_TRAVEL_MS);
      agitator = towards(agitator, wantAgitator, hMs, AGITATOR_RAMP_MS);
      angle = (angle + agitator * 360 * h) % 360;
      // Ingredients come in at room temperature and mix into the batch.
      const inA = FLOW_A_L_S * valveA * h;
      const inB = FLOW_B_L_S * valveB * h;
      if (inA + inB > 0) {
        // An ingredient into a batch already judged (its discharge stopped short): a new batch,
        // on what was left of the last one (which is then never counted a good batch).
        if (judged) {
          if (level > 0) {
            heels++;
            heelL = level;
          }
          judged = false;
          spoiledBatch = false;
          maxTemp = temp;
        }
        // Into the emptied vessel: a batch of its own, whose hottest so far is what it is now.
        const fresh = level <= 0;
        temp = (temp * level + AMBIENT_C * (inA + inB)) / (level + inA + inB);
        if (fresh) maxTemp = temp;
        level += inA + inB;
        volA += inA;
        volB += inB;
        inflowL += inA + inB;
        heldMs = 0;
      }
      // Over the rim: what spills takes A and B with it as they are mixed.
      if (level > MIXER_CAPACITY_L) {
        const keep = MIXER_CAPACITY_L / level;
        volA *= keep;
        volB *= keep;
        level = MIXER_CAPACITY_L;
        overflowing = true;
      }
      // The outlet.
      const out = Math.min(OUTLET_L_S * outlet * h, level);
      if (out > 0) {
        const keep = level > 0 ? (level - out) / level : 0;
        volA *= keep;
        volB *= keep;
        level -= out;
        outflowL += out;
        if (level < 1e-9) level = volA = volB = 0;
      }
      // Heat: heater -> element zone -> batch -> room.
      const power = heating ? HEATER_POWER : 0;
      if (level >= ELEMENT_COVERED_L) {
        const zone = Math.min(ZONE_L, level);
        const mix = MIX_STILL + MIX_STIRRED * agitator;
        const flow = mix * (element - temp);
        element += h * (power / zone - flow);
        temp += h * (flow * (zone / level) - LOSS * (temp - AMBIENT_C));
        if (element > SCORCH_C) scorching = true;
      } else {
        // An element in the air heats by itself, and burns out; with no batch the vessel cools to the room.
        if (heating) dryHeating = true;
        element += h * (power / ZONE_L - MIX_STILL * (element - AMBIENT_C));
        if (heating && element > BURNOUT_C) {
          burntOut = true;
          heating = false;
        }
        temp += h * -LOSS * 4 * (temp - AMBIENT_C);
      }
      if (level >= ELEMENT_COVERED_L && agitator >= 0.9 && temp >= HOLD_MIN_C) heldMs += hMs;
      if (level > 0 && temp > maxTemp) maxTemp = temp;
      // A batch is spoiled (and counted) once, by the first thing that spoils it.
      const harm: SpoilReason = level <= 0 ? '' : scorching ? 'scorch' : temp > OVERHEAT_C ? 'overheat' : '';
      if (harm && !spoiledBatch) {
        spoiledBatch = true;
        spoilReason = harm;
        spoiled++;
      }
      // Emptied: a good batch is done; the next one starts from nothing.
      if (level === 0 && judged) {
        if (judged && !spoiledBatch) batches++;
        judged = false;
        spoiledBatch = false;
        heldMs = 0;
        maxTemp = temp;
      }
    }
    if (overflowing && !s.overflowing) overflows++;
    if (scorching && !s.scorching) scorches++;
    if (dryHeating && !s.dryHeating) dryHeats++;
    const dt = dtMs / 1000;
    into.level = level;
    into.volA = volA;
    into.volB = volB;
    into.temp = temp;
    into.element = element;
    into.shownTemp = faults.has('temp_frozen') ? s.shownTemp : temp;
    into.valveA = valveA;
    into.valveB = valveB;
    into.outlet = outlet;
    into.agitator = agitator;
    into.outletOrdered = wantOut === 1;
    into.angle = angle;
    into.heating = heating;
    into.burntOut = burntOut;
    into.lamp = on(drive.DoneLamp);
    into.heldMs = heldMs;
    into.maxTemp = maxTemp;
    into.judged = judged;
    into.spoiledBatch = spoiledBatch;
    into.spoilReason = spoilReason;
    into.lastRatio = lastRatio;
    into.overflowing = overflowing;
    into.dryHeating = dryHeating;
    into.scorching = scorching;
    into.batches = batches;
    into.spoiled = spoiled;
    into.overflows = overflows;
    into.scorches = scorches;
    into.dryHeats = dryHeats;
    into.heels = heels;
    into.heelL = heelL;
    into.inflow = dt > 0 ? inflowL / dt : 0;
    into.outflow = dt > 0 ? outflowL / dt : 0;
    return into;
  },

  sense(s: MixerState, faults: ReadonlySet<string>, out: Value[]): void {
    // Runs every scan: the fault names are constants, looked up only when a fault is set.
    const any = faults.size > 0;
    out[SENSE.LowLevel] = (any && faults.has('low_stuck_on')) || s.level >= LOW_SWITCH_L;
    out[SENSE.MidLevel] = !(any && faults.has('mid_stuck_off')) && s.level >= MID_SWITCH_L;
    out[SENSE.HighLevel] = !(any && faults.has('high_stuck_off')) && s.level >= HIGH_SWITCH_L;
    out[SENSE.AgitatorOn] = s.agitator >= 0.9;
    out[SENSE.Level] = Math.round(s.level);
    out[SENSE.Temperature] = Math.round(s.shownTemp * 10);
  },

  check(before: MixerState, after: MixerState): readonly PlantConsequence[] {
    // Nothing started (every scan but a handful): no list made.
    let out: PlantConsequence[] | undefined;
    if (after.overflows > before.overflows)
      (out ??= []).push({ id: 'overflow', severity: 'error', message: 'the mixer overflowed', counter: 'overflows' });
    if (after.dryHeats > before.dryHeats)
      (out ??= []).push({
        id: 'dry_heat',
        severity: 'error',
        message: 'the heater ran dry (its element was not covered)',
        counter: 'dry_heats',
      });
    if (after.burntOut && !before.burntOut)
      (out ??= []).push({
        id: 'burnout',
        severity: 'error',
        message: `the heater element burnt out (it heated uncovered past ${BURNOUT_C} °C): it heats no more until the machine is reset`,
        counter: 'burnt_out',
      });
    if (after.scorches > before.scorches)
      (out ??= []).push({
        id: 'scorch',
        severity: 'error',
        // Unstirred, the element scorches the still product around it; stirred, only a batch
        // heated on far past its set point gets the element that hot (a frozen transmitter).
        message:
          after.agitator >= 0.9
            ? `the product scorched on the heater (the batch was heated on to ${after.temp.toFixed(0)} °C) and the batch is spoiled`
            : 'the product scorched on the heater (heating without the agitator) and the batch is spoiled',
        counter: 'scorches',
      });
    if (after.spoiled > before.spoiled && after.spoilReason !== 'scorch')
      (out ??= []).push({
        id: `spoiled_${after.spoilReason}`,
        severity: 'error',
        message: spoilText(after),
        counter: 'spoiled',
      });
    if (after.heels > before.heels)
      (out ??= []).push({
        id: 'heel',
        severity: 'error',
        message: `the vessel was not emptied (the outlet closed with ${after.heelL.toFixed(1)} L left): the next batch was dosed onto it, and the last batch is not counted`,
        counter: 'heels',
      });
    return out ?? NOTHING;
  },

  explain(s: MixerState, point: string, faults: ReadonlySet<string>): string | undefined {
    const level = `the level is ${s.level.toFixed(1)} L`;
    const sw = (title: string, at: number, stuck?: 'ON' | 'OFF', fault?: string) =>
      stuck && fault && faults.has(fault)
        ? `${title} is stuck ${stuck} (fault ${fault}): it reads ${stuck} whatever the level; ${level}`
        : `${title} is ON at ${at} L and above; ${level}, so it is ${s.level >= at ? 'ON' : 'OFF'}`;
    switch (point) {
      case 'LowLevel':
        return sw('the low level switch', LOW_SWITCH_L, 'ON', 'low_stuck_on');
      case 'MidLevel':
        return sw('the mid level switch', MID_SWITCH_L, 'OFF', 'mid_stuck_off');
      case 'HighLevel':
        return sw('the high level switch', HIGH_SWITCH_L, 'OFF', 'high_stuck_off');
      case 'AgitatorOn': {
        const speed = `the agitator runs at ${(s.agitator * 100).toFixed(0)} % of full speed`;
        const dead = faults.has('agitator_dead') ? ' (its motor does not start: fault agitator_dead)' : '';
        return `the speed monitor is ON from 90 % of full speed; ${speed}${dead}, so it is ${s.agitator >= 0.9 ? 'ON' : 'OFF'}`;
      }
      case 'Level':
        return `the transmitter gives the level in whole litres; ${level}`;
      case 'Temperature': {
        const shown = `${s.shownTemp.toFixed(1)} °C (${Math.round(s.shownTemp * 10)})`;
        return faults.has('temp_frozen')
          ? `the transmitter is frozen (fault temp_frozen): it keeps showing ${shown} whatever the batch; the batch is ${s.temp.toFixed(1)} °C`
          : `the transmitter gives the batch's temperature in tenths of a degree; the batch is ${shown}`;
      }
    }
    return undefined;
  },

  quantity(s: MixerState, name: string): number | boolean {
    switch (name) {
      case 'temperature':
        return s.temp;
      case 'element':
        return s.element;
      case 'level':
        return s.level;
      case 'ratio':
        return s.level > 0 ? ratioOf(s) : s.lastRatio;
      case 'held':
        return s.heldMs / 1000;
      case 'max_temp':
        return s.maxTemp;
      case 'valve_a':
        return s.valveA * 100;
      case 'valve_b':
        return s.valveB * 100;
      case 'outlet':
        return s.outlet * 100;
      case 'agitator':
        return s.agitator * 100;
      case 'heating':
        return s.heating;
      case 'overflowing':
        return s.overflowing;
      case 'batches':
        return s.batches;
      case 'spoiled':
        return s.spoiled;
      case 'overflows':
        return s.overflows;
      case 'scorches':
        return s.scorches;
      case 'dry_heats':
        return s.dryHeats;
      case 'heels':
        return s.heels;
      case 'burnt_out':
        return s.burntOut;
    }
    throw new Error(`mixer has no quantity "${name}"`);
  },
};
