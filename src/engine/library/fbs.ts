// Standard function blocks (IEC 61131-3 tables 43-46) as small classes whose public fields are the
// IEC pins, so compiled networks can write `t.IN = x; t.PT = 5000; t.execute(now); y = t.Q;`
// without allocating. Each `execute` follows the ST body of MATIEC's library (lib/timer.txt,
// counter.txt, edge_detection.txt, bistable.txt), which transcribes the standard; the only
// profile-dependent part is the counters' counting limit (see profiles.ts). SEMA and the
// additional blocks (INTEGRAL, DERIVATIVE, PID, RAMP, HYSTERESIS) are in controlFbs.ts.
import { COUNTER_TYPES, type CounterType } from '../../model/blocks';
import type { Profile } from '../../model/project';
import { defaultValue } from '../values/types';
import { DERIVATIVE, HYSTERESIS, INTEGRAL, PID, RAMP, SEMA } from './controlFbs';
import { RTC } from './rtc';
import { StandardFb, type FbInstance, type FbState } from './fbBase';
import { counterLimits, type CounterLimits } from './profiles';

export type { FbInstance, FbState } from './fbBase';

/** STATE values of the timers' state machine in MATIEC's timer.txt. */
const RESET = 0;
const COUNTING = 1;
const SET = 2;

abstract class Timer extends StandardFb {
  IN = false;
  PT = 0;
  Q = false;
  ET = 0;
  STATE = RESET;
  PREV_IN = false;
  START_TIME = 0;

  reset(): void {
    this.IN = false;
    this.PT = 0;
    this.Q = false;
    this.ET = 0;
    this.STATE = RESET;
    this.PREV_IN = false;
    this.START_TIME = 0;
  }

  /** START_TIME is a time on the PLC clock: saved relative to `timeBase`. */
  override saveState(timeBase: number): FbState {
    return { ...super.saveState(timeBase), START_TIME: this.START_TIME - timeBase };
  }

  override loadState(state: FbState, timeBase: number): void {
    super.loadState(state, timeBase);
    if (typeof state.START_TIME === 'number') this.START_TIME = state.START_TIME + timeBase;
  }
}

/** On-delay: Q goes ON once IN has been ON for PT (seen at a scan start); ET stops at PT. */
export class TON extends Timer {
  readonly fbType = 'TON';
  execute(now: number): void {
    if (this.STATE === RESET && !this.PREV_IN && this.IN) {
      // Rising edge: start timing. ET is not updated in this scan (it is still 0).
      this.STATE = COUNTING;
      this.Q = false;
      this.START_TIME = now;
    } else if (!this.IN) {
      this.ET = 0;
      this.Q = false;
      this.STATE = RESET;
    } else if (this.STATE === COUNTING) {
      if (this.START_TIME + this.PT <= now) {
        this.STATE = SET;
        this.Q = true;
        this.ET = this.PT;
      } else this.ET = now - this.START_TIME;
    }
    this.PREV_IN = this.IN;
  }
}

/** Off-delay: Q follows IN ON and stays ON for PT after IN goes OFF; ET holds PT until IN comes back. */
export class TOF extends Timer {
  readonly fbType = 'TOF';
  execute(now: number): void {
    if (this.STATE === RESET && this.PREV_IN && !this.IN) {
      this.STATE = COUNTING;
      this.START_TIME = now;
    } else if (this.IN) {
      this.ET = 0;
      this.STATE = RESET;
    } else if (this.STATE === COUNTING) {
      if (this.START_TIME + this.PT <= now) {
        this.STATE = SET;
        this.ET = this.PT;
      } else this.ET = now - this.START_TIME;
    }
    this.Q = this.IN || this.STATE === COUNTING;
    this.PREV_IN = this.IN;
  }
}

/** Pulse: a rising edge of IN gives Q ON for PT; edges during the pulse are ignored (not retriggerable). */
export class TP extends Timer {
  readonly fbType = 'TP';
  execute(now: number): void {
    if (this.STATE === RESET && !this.PREV_IN && this.IN) {
      this.STATE = COUNTING;
      this.Q = true;
      this.START_TIME = now;
    } else if (this.STATE === COUNTING) {
      if (this.START_TIME + this.PT <= now) {
        this.STATE = SET;
        this.Q = false;
        this.ET = this.PT;
      } else this.ET = now - this.START_TIME;
    }
    // ET stays at PT after the pulse while IN is still ON, and resets once IN is OFF.
    if (this.STATE === SET && !this.IN) {
      this.ET = 0;
      this.STATE = RESET;
    }
    this.PREV_IN = this.IN;
  }
}

/** CV + 1 or CV - 1 in CV's representation (bigint for LINT/ULINT); the limits keep it in range. */
const step = (v: number | bigint, by: 1 | -1): number | bigint =>
  typeof v === 'bigint' ? v + BigInt(by) : v + by;

/** The counters' common part: PV/CV of type `cvType` (INT for CTU/CTD/CTUD, DINT for CTU_DINT ...). */
abstract class Counter extends StandardFb {
  PV: number | bigint;
  CV: number | bigint;
  constructor(
    readonly fbType: string,
    protected readonly limits: CounterLimits,
    protected readonly cvType: CounterType,
  ) {
    super();
    this.PV = this.CV = this.zero();
  }
  protected zero(): number | bigint {
    return defaultValue(this.cvType) as number | bigint;
  }
}

/**
 * Up counter. CU counts on its rising edge (an internal R_TRIG, as MATIEC's CU_T). MATIEC's
 * CTU_DINT, CTU_LINT, CTU_UDINT and CTU_ULINT (lib/counter.txt) have the same body with PV and CV
 * of that type.
 */
export class CTU extends Counter {
  CU = false;
  R = false;
  Q = false;
  /** Edge memory of CU (MATIEC: CU_T.M). */
  CU_M = false;
  constructor(limits: CounterLimits, type: CounterType = 'INT') {
    super(type === 'INT' ? 'CTU' : `CTU_${type}`, limits, type);
  }
  execute(_nowMs: number): void {
    const edge = this.CU && !this.CU_M;
    this.CU_M = this.CU;
    if (this.R) this.CV = this.zero();
    else if (edge && this.CV < this.limits.upTo(this.PV)) this.CV = step(this.CV, 1);
    this.Q = this.CV >= this.PV;
  }
  reset(): void {
    this.CU = this.R = this.Q = this.CU_M = false;
    this.PV = this.CV = this.zero();
  }
}

/** Down counter. CD counts on its rising edge; LD loads PV. Typed CTD_DINT ... CTD_ULINT as CTU. */
export class CTD extends Counter {
  CD = false;
  LD = false;
  Q = false;
  /** Edge memory of CD (MATIEC: CD_T.M). */
  CD_M = false;
  constructor(limits: CounterLimits, type: CounterType = 'INT') {
    super(type === 'INT' ? 'CTD' : `CTD_${type}`, limits, type);
  }
  execute(_nowMs: number): void {
    const edge = this.CD && !this.CD_M;
    this.CD_M = this.CD;
    if (this.LD) this.CV = this.PV;
    else if (edge && this.CV > this.limits.downTo) this.CV = step(this.CV, -1);
    this.Q = this.CV <= 0;
  }
  reset(): void {
    this.CD = this.LD = this.Q = this.CD_M = false;
    this.PV = this.CV = this.zero();
  }
}

/** Up-down counter: R wins over LD; edges of CU and CD in the same scan cancel out. Typed as CTU. */
export class CTUD extends Counter {
  CU = false;
  CD = false;
  R = false;
  LD = false;
  QU = false;
  QD = false;
  CU_M = false;
  CD_M = false;
  constructor(limits: CounterLimits, type: CounterType = 'INT') {
    super(type === 'INT' ? 'CTUD' : `CTUD_${type}`, limits, type);
  }
  execute(_nowMs: number): void {
    const down = this.CD && !this.CD_M;
    this.CD_M = this.CD;
    const up = this.CU && !this.CU_M;
    this.CU_M = this.CU;
    if (this.R) this.CV = this.zero();
    else if (this.LD) this.CV = this.PV;
    else if (!(up && down)) {
      if (up && this.CV < this.limits.upTo(this.PV)) this.CV = step(this.CV, 1);
      else if (down && this.CV > this.limits.downTo) this.CV = step(this.CV, -1);
    }
    this.QU = this.CV >= this.PV;
    this.QD = this.CV <= 0;
  }
  reset(): void {
    this.CU = this.CD = this.R = this.LD = this.QU = this.QD = this.CU_M = this.CD_M = false;
    this.PV = this.CV = this.zero();
  }
}

/** Rising edge: Q := CLK AND NOT M; M := CLK. M starts FALSE, so CLK ON at the first call gives a pulse. */
export class R_TRIG extends StandardFb {
  readonly fbType = 'R_TRIG';
  CLK = false;
  Q = false;
  M = false;
  execute(_nowMs: number): void {
    this.Q = this.CLK && !this.M;
    this.M = this.CLK;
  }
  reset(): void {
    this.CLK = this.Q = this.M = false;
  }
}

/** Falling edge: Q := NOT CLK AND NOT M; M := NOT CLK. M starts FALSE, so CLK OFF at the first call gives a pulse. */
export class F_TRIG extends StandardFb {
  readonly fbType = 'F_TRIG';
  CLK = false;
  Q = false;
  M = false;
  execute(_nowMs: number): void {
    this.Q = !this.CLK && !this.M;
    this.M = !this.CLK;
  }
  reset(): void {
    this.CLK = this.Q = this.M = false;
  }
}

/** Set-dominant bistable: Q1 := S1 OR (NOT R AND Q1). */
export class SR extends StandardFb {
  readonly fbType = 'SR';
  S1 = false;
  R = false;
  Q1 = false;
  execute(_nowMs: number): void {
    this.Q1 = this.S1 || (!this.R && this.Q1);
  }
  reset(): void {
    this.S1 = this.R = this.Q1 = false;
  }
}

/** Reset-dominant bistable: Q1 := NOT R1 AND (S OR Q1). */
export class RS extends StandardFb {
  readonly fbType = 'RS';
  S = false;
  R1 = false;
  Q1 = false;
  execute(_nowMs: number): void {
    this.Q1 = !this.R1 && (this.S || this.Q1);
  }
  reset(): void {
    this.S = this.R1 = this.Q1 = false;
  }
}

/** A fresh instance of a standard FB (name case-insensitive), or undefined for an unknown type. */
export function createFb(type: string, profile: Profile): FbInstance | undefined {
  const upper = type.toUpperCase();
  const typed = /^(CTU|CTD|CTUD)_(\w+)$/.exec(upper);
  if (typed) {
    const t = COUNTER_TYPES.find((c) => c !== 'INT' && c === typed[2]);
    if (!t) return undefined;
    const limits = counterLimits(profile, t);
    return typed[1] === 'CTU'
      ? new CTU(limits, t)
      : typed[1] === 'CTD'
        ? new CTD(limits, t)
        : new CTUD(limits, t);
  }
  switch (upper) {
    case 'TON':
      return new TON();
    case 'TOF':
      return new TOF();
    case 'TP':
      return new TP();
    case 'CTU':
      return new CTU(counterLimits(profile));
    case 'CTD':
      return new CTD(counterLimits(profile));
    case 'CTUD':
      return new CTUD(counterLimits(profile));
    case 'R_TRIG':
      return new R_TRIG();
    case 'F_TRIG':
      return new F_TRIG();
    case 'SR':
      return new SR();
    case 'RS':
      return new RS();
    case 'SEMA':
      return new SEMA();
    case 'INTEGRAL':
      return new INTEGRAL(profile);
    case 'DERIVATIVE':
      return new DERIVATIVE(profile);
    case 'PID':
      return new PID(profile);
    case 'RAMP':
      return new RAMP(profile);
    case 'HYSTERESIS':
      return new HYSTERESIS();
    case 'RTC':
      return new RTC();
    default:
      return undefined;
  }
}
