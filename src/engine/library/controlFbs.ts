// SEMA (OpenPLC Editor's Standard_Function_Blocks.xml) and the blocks of its
// Additional_Function_Blocks.xml: INTEGRAL, DERIVATIVE, PID, RAMP, HYSTERESIS (the standard's
// annex F examples, MATIEC's AnnexF/*_st.txt). Each `execute` is the block's ST body, statement
// by statement, with REAL arithmetic as MATIEC's C does it: every operation on floats, rounded to
// 32 bits (`f` below). TIME_TO_REAL(CYCLE) in the bodies is the profile's conversion: seconds in
// `openplc` (MATIEC: T#100ms -> 0.1), milliseconds in `iec` (profiles.ts, time-conversion-unit),
// so INTEGRAL, DERIVATIVE and PID's TR and TD count in that unit. CYCLE is an input: the blocks
// assume they are called once per CYCLE and do not read the clock.
// RTC (DATE_AND_TIME pins) is in rtc.ts.
import type { Profile } from '../../model/project';
import { StandardFb, type FbState } from './fbBase';
import { timeConversionUnitMs } from './profiles';

const f = Math.fround;

/** TIME_TO_REAL as the profile converts: a REAL number of seconds (openplc) or milliseconds (iec). */
const timeToReal = (profile: Profile): ((ms: number) => number) => {
  const unit = timeConversionUnitMs(profile);
  return (ms) => f(ms / unit);
};

/** Semaphore: Q_INTERNAL := CLAIM OR (Q_INTERNAL AND NOT RELEASE); BUSY := Q_INTERNAL. */
export class SEMA extends StandardFb {
  readonly fbType = 'SEMA';
  CLAIM = false;
  RELEASE = false;
  BUSY = false;
  Q_INTERNAL = false;
  execute(_nowMs: number): void {
    this.Q_INTERNAL = this.CLAIM || (this.Q_INTERNAL && !this.RELEASE);
    this.BUSY = this.Q_INTERNAL;
  }
  reset(): void {
    this.CLAIM = this.RELEASE = this.BUSY = this.Q_INTERNAL = false;
  }
}

/**
 * Q := NOT R1;
 * IF R1 THEN XOUT := X0; ELSIF RUN THEN XOUT := XOUT + XIN * TIME_TO_REAL(CYCLE); END_IF;
 */
export class INTEGRAL extends StandardFb {
  readonly fbType = 'INTEGRAL';
  RUN = false;
  R1 = false;
  XIN = 0;
  X0 = 0;
  CYCLE = 0;
  Q = false;
  XOUT = 0;
  private readonly toReal: (ms: number) => number;
  constructor(profile: Profile) {
    super();
    this.toReal = timeToReal(profile);
  }
  execute(_nowMs: number): void {
    this.Q = !this.R1;
    if (this.R1) this.XOUT = this.X0;
    else if (this.RUN) this.XOUT = f(this.XOUT + f(this.XIN * this.toReal(this.CYCLE)));
  }
  reset(): void {
    this.RUN = this.R1 = this.Q = false;
    this.XIN = this.X0 = this.CYCLE = this.XOUT = 0;
  }
}

/**
 * IF RUN THEN
 *   XOUT := (3.0 * (XIN - X3) + X1 - X2) / (10.0 * TIME_TO_REAL(CYCLE));
 *   X3 := X2; X2 := X1; X1 := XIN;
 * ELSE XOUT := 0.0; X1 := XIN; X2 := XIN; X3 := XIN; END_IF;
 * CYCLE = T#0s gives a division by zero: +-Inf or NaN, as C's float division.
 */
export class DERIVATIVE extends StandardFb {
  readonly fbType = 'DERIVATIVE';
  RUN = false;
  XIN = 0;
  CYCLE = 0;
  XOUT = 0;
  X1 = 0;
  X2 = 0;
  X3 = 0;
  private readonly toReal: (ms: number) => number;
  constructor(profile: Profile) {
    super();
    this.toReal = timeToReal(profile);
  }
  execute(_nowMs: number): void {
    if (this.RUN) {
      const num = f(f(f(3 * f(this.XIN - this.X3)) + this.X1) - this.X2);
      this.XOUT = f(num / f(10 * this.toReal(this.CYCLE)));
      this.X3 = this.X2;
      this.X2 = this.X1;
      this.X1 = this.XIN;
    } else {
      this.XOUT = 0;
      this.X1 = this.X2 = this.X3 = this.XIN;
    }
  }
  reset(): void {
    this.RUN = false;
    this.XIN = this.CYCLE = this.XOUT = this.X1 = this.X2 = this.X3 = 0;
  }
}

/**
 * ERROR := PV - SP;
 * ITERM(RUN := AUTO, R1 := NOT AUTO, XIN := ERROR, X0 := TR * (X0 - ERROR), CYCLE := CYCLE);
 * DTERM(RUN := AUTO, XIN := ERROR, CYCLE := CYCLE);
 * XOUT := KP * (ERROR + ITERM.XOUT/TR + DTERM.XOUT*TD);
 * With AUTO OFF the integrator is reset to TR * (X0 - ERROR), so XOUT = KP * X0 (bumpless transfer).
 */
export class PID extends StandardFb {
  readonly fbType = 'PID';
  AUTO = false;
  PV = 0;
  SP = 0;
  X0 = 0;
  KP = 0;
  TR = 0;
  TD = 0;
  CYCLE = 0;
  XOUT = 0;
  ERROR = 0;
  private readonly iterm: INTEGRAL;
  private readonly dterm: DERIVATIVE;
  constructor(profile: Profile) {
    super();
    this.iterm = new INTEGRAL(profile);
    this.dterm = new DERIVATIVE(profile);
  }
  execute(nowMs: number): void {
    this.ERROR = f(this.PV - this.SP);
    const i = this.iterm;
    i.RUN = this.AUTO;
    i.R1 = !this.AUTO;
    i.XIN = this.ERROR;
    i.X0 = f(this.TR * f(this.X0 - this.ERROR));
    i.CYCLE = this.CYCLE;
    i.execute(nowMs);
    const d = this.dterm;
    d.RUN = this.AUTO;
    d.XIN = this.ERROR;
    d.CYCLE = this.CYCLE;
    d.execute(nowMs);
    this.XOUT = f(this.KP * f(f(this.ERROR + f(i.XOUT / this.TR)) + f(d.XOUT * this.TD)));
  }
  reset(): void {
    this.AUTO = false;
    this.PV = this.SP = this.X0 = this.KP = this.TR = this.TD = this.CYCLE = this.XOUT = this.ERROR = 0;
    this.iterm.reset();
    this.dterm.reset();
  }
  /** The inner ITERM and DTERM instances' fields as `ITERM.XOUT`, `DTERM.X1`, ... */
  override saveState(timeBase: number): FbState {
    const out: Record<string, number | boolean> = { ...super.saveState(timeBase) };
    for (const [prefix, fb] of this.inner()) for (const [k, v] of Object.entries(fb.saveState(timeBase))) out[`${prefix}.${k}`] = v;
    return out;
  }
  override loadState(state: FbState, timeBase: number): void {
    super.loadState(state, timeBase);
    for (const [prefix, fb] of this.inner()) {
      const mine: Record<string, number | boolean> = {};
      for (const [k, v] of Object.entries(state)) if (k.startsWith(`${prefix}.`)) mine[k.slice(prefix.length + 1)] = v;
      fb.loadState(mine, timeBase);
    }
  }
  private inner(): [string, StandardFb][] {
    return [
      ['ITERM', this.iterm],
      ['DTERM', this.dterm],
    ];
  }
}

/**
 * BUSY := RUN;
 * IF RUN THEN
 *   IF T >= TR THEN BUSY := 0; XOUT := X1;
 *   ELSE XOUT := XI + (X1-XI) * TIME_TO_REAL(T) / TIME_TO_REAL(TR); T := T + CYCLE; END_IF;
 * ELSE XOUT := X0; XI := X0; T := T#0s; END_IF;
 */
export class RAMP extends StandardFb {
  readonly fbType = 'RAMP';
  RUN = false;
  X0 = 0;
  X1 = 0;
  TR = 0;
  CYCLE = 0;
  BUSY = false;
  XOUT = 0;
  /** Value of X0 when RUN came on (the ramp's start). */
  XI = 0;
  /** Elapsed time of the ramp (a duration, not a clock time). */
  T = 0;
  private readonly toReal: (ms: number) => number;
  constructor(profile: Profile) {
    super();
    this.toReal = timeToReal(profile);
  }
  execute(_nowMs: number): void {
    this.BUSY = this.RUN;
    if (this.RUN) {
      if (this.T >= this.TR) {
        this.BUSY = false;
        this.XOUT = this.X1;
      } else {
        this.XOUT = f(this.XI + f(f(f(this.X1 - this.XI) * this.toReal(this.T)) / this.toReal(this.TR)));
        this.T += this.CYCLE;
      }
    } else {
      this.XOUT = this.X0;
      this.XI = this.X0;
      this.T = 0;
    }
  }
  reset(): void {
    this.RUN = this.BUSY = false;
    this.X0 = this.X1 = this.TR = this.CYCLE = this.XOUT = this.XI = this.T = 0;
  }
}

/**
 * IF Q THEN IF XIN1 < (XIN2 - EPS) THEN Q := 0; END_IF;
 * ELSIF XIN1 > (XIN2 + EPS) THEN Q := 1; END_IF;
 */
export class HYSTERESIS extends StandardFb {
  readonly fbType = 'HYSTERESIS';
  XIN1 = 0;
  XIN2 = 0;
  EPS = 0;
  Q = false;
  execute(_nowMs: number): void {
    if (this.Q) {
      if (this.XIN1 < f(this.XIN2 - this.EPS)) this.Q = false;
    } else if (this.XIN1 > f(this.XIN2 + this.EPS)) this.Q = true;
  }
  reset(): void {
    this.XIN1 = this.XIN2 = this.EPS = 0;
    this.Q = false;
  }
}
